#!/usr/bin/env bash
# The closed-loop part of `make demo`: walks the polynomial and the optimal five-link gait under
# computed torque, the boundary-layer law and Mu's integral sliding mode, sweeps where walking
# stops (20 steps per point, pushes by 0.25 N s, model errors by 2.5 %) and maps push against
# mass error, walks Mu's uncertainty cases, and charts the ground models' speed against accuracy,
# into results/. Sweeps and maps resume: delete a stability or map folder to recompute it.
# Usage: scripts/closed_loop_demo.sh BUILD_DIR   (run from the repository root)
set -euo pipefail
build=${1:-build}
bin="$build/apps/gaitopt"
# The walks and sweeps use the strict rule: a centre of pressure beyond the 5 cm heel or the toe
# is a foot rotation and ends the walk (--cop-limit fail), so no walk counts that leans on a
# saturated ankle. (With the export's rates the derivatives of its angles, the optimum walks
# 20 steps at nominal under the default rule too; before, the quintic between its 1 kHz samples
# overshot at the RK4 mid-stages and the saturated ankle let it slide.)
rules=(--cop-limit fail)

echo "== gaitopt simulate: 20 steps of each five-link gait on rigid ground (Poincare map)"
for gait in poly opt opt_robust; do
  for controller in computed_torque sliding_mode mu_sliding_mode; do
    "$bin" simulate --reference "results/${gait}_mu2004" --controller "$controller" --steps 20 \
      "${rules[@]}" --rate 50 --out "results/walk_${gait}_mu2004_${controller}" --quiet
  done
done
for controller in computed_torque sliding_mode mu_sliding_mode; do
  "$bin" simulate --reference results/poly_zmp_mu2004 --controller "$controller" --steps 20 \
    "${rules[@]}" --rate 50 --out "results/walk_poly_zmp_mu2004_${controller}" --quiet
done
# The README's front-page animation is this walk's walk.gif: a re-walk clears the folder.
"$bin" report results/walk_opt_mu2004_computed_torque
echo "== gaitopt simulate: the optimal gait on the impedance and LCP grounds"
for ground in impedance lcp; do
  "$bin" simulate --reference results/opt_mu2004 --ground "$ground" --steps 20 "${rules[@]}" \
    --rate 50 --out "results/walk_opt_mu2004_${ground}" --quiet
done

for ground in impedance lcp; do
  for controller in computed_torque mu_sliding_mode; do
    "$bin" simulate --reference results/opt_robust_mu2004 --ground "$ground" --controller \
      "$controller" --steps 20 "${rules[@]}" --rate 50 --quiet \
      --out "results/walk_opt_robust_mu2004_${ground}_${controller}"
  done
done

echo "== RABBIT under HZD: Kelly's optimum, 20 steps, restricted Poincare map"
bash scripts/hzd_rabbit.sh "$build"

echo "== the same walk on four grounds: how smooth the contact forces are (results/ground_forces/)"
forces_work=$(mktemp -d)
for ground in rigid impedance pad lcp; do
  "$bin" simulate --reference results/poly_zmp_mu2004 --ground "$ground" --steps 5 \
    --cop-limit saturate --out "$forces_work/$ground" --no-plots --quiet
done
/usr/bin/python3 plots/ground_forces_chart.py results/ground_forces \
  "$forces_work"/{rigid,impedance,pad,lcp}
rm -rf "$forces_work"

echo "== Poincare multipliers of the walks on the unit circle (results/poincare_multipliers.png)"
walks=(results/walk_{poly,opt,opt_robust}_mu2004_{computed_torque,sliding_mode,mu_sliding_mode}
  results/walk_opt_mu2004_{impedance,lcp})
[[ -f results/walk_rabbit_hzd/summary.json ]] && walks+=(results/walk_rabbit_hzd)
/usr/bin/python3 plots/multipliers_plot.py results/poincare_multipliers.png "${walks[@]}"

echo "== gaitopt stability: where walking stops (20 steps per point)"
sweeps=(--sweep push=-3:3:25 --sweep mass_error=-0.2:0.2:17 --sweep length_error=-0.05:0.05:5
  --sweep friction=0.1:0.6:11 --sweep gain_scale=0.2:3:15)
for gait in poly opt opt_robust; do
  for controller in computed_torque sliding_mode mu_sliding_mode; do
    "$bin" stability --reference "results/${gait}_mu2004" --controller "$controller" --steps 20 \
      "${rules[@]}" "${sweeps[@]}" --quiet --out "results/stability_${gait}_mu2004_${controller}"
  done
done
for controller in computed_torque mu_sliding_mode; do
  "$bin" stability --reference results/poly_zmp_mu2004 --controller "$controller" --steps 20 \
    "${rules[@]}" "${sweeps[@]}" --quiet --out "results/stability_poly_zmp_mu2004_${controller}"
done
"$bin" stability --reference results/opt_mu2004 --ground impedance --steps 20 "${rules[@]}" --quiet \
  --sweep stiffness=1e4:1e9:11 --sweep push=-3:12:16 --out results/stability_opt_mu2004_impedance

# The gait designed to be walked under the other CoP rule: the controller clips the ankle torque
# where the centre of pressure reaches the heel or the toe (--cop-limit saturate), as a
# controller that knows its foot does, instead of counting that as a foot rotation.
"$bin" stability --reference results/opt_robust_mu2004 --controller mu_sliding_mode --steps 20 \
  --cop-limit saturate --quiet --sweep push=-6:6:49 --sweep mass_error=-0.4:0.4:33 \
  --sweep length_error=-0.1:0.1:9 --out results/stability_opt_robust_mu2004_mu_sliding_mode_saturate
# And under the strict rule at a softer bandwidth: what stiff tracking costs in pushes, and what
# soft tracking costs in model errors.
"$bin" stability --reference results/opt_robust_mu2004 --controller mu_sliding_mode --steps 20 \
  --gain-scale 0.3 "${rules[@]}" --quiet --sweep push=-4:4:33 --sweep mass_error=-0.3:0.3:25 \
  --sweep length_error=-0.1:0.1:9 --out results/stability_opt_robust_mu2004_mu_sliding_mode_gain0.3

echo "== gaitopt stability --map: push x mass error, 25 x 17 walks of 20 steps (results/map_*)"
map=(--map "push=-3:3:25,mass_error=-0.2:0.2:17" --steps 20 "${rules[@]}" --quiet)
"$bin" stability --reference results/opt_mu2004 --controller computed_torque "${map[@]}" \
  --out results/map_opt_mu2004_computed_torque
# The gait designed to be walked (configs/ocp/mu2004_walk_robust.yaml) under Mu's sliding mode.
"$bin" stability --reference results/opt_robust_mu2004 --controller mu_sliding_mode "${map[@]}" \
  --out results/map_opt_robust_mu2004_mu_sliding_mode
# Ten times finer around the nominal point, where the coarse map finds the optimum's one walk.
"$bin" stability --reference results/opt_mu2004 --controller computed_torque --steps 20 \
  "${rules[@]}" --quiet --map "push=-0.5:0.5:21,mass_error=-0.025:0.025:21" \
  --out results/map_fine_opt_mu2004_computed_torque
# The polynomial gait's ZMP leaves the shipped 5 cm heel: mapped on the long-heel test robot.
"$bin" stability --robot tests/apps/mu2004_five_link_long_heel.yaml --reference results/poly_mu2004 \
  --controller mu_sliding_mode "${map[@]}" --out results/map_poly_mu2004_mu_sliding_mode

# RABBIT under HZD (its 1 kHz gait is made by scripts/hzd_rabbit.sh): the same map, and a wide
# one by 1 N s and 10 % to find where it stops.
if [[ -f results/opt_rabbit/trajectory.csv ]]; then
  "$bin" stability --reference results/opt_rabbit --controller hzd "${map[@]}" \
    --out results/map_rabbit_hzd
  "$bin" stability --reference results/opt_rabbit --controller hzd --steps 20 --quiet \
    --map "push=-12:12:25,mass_error=-0.5:1:16" --out results/map_wide_rabbit_hzd
fi

echo "== Mu's uncertainty cases 1-3 on the controller's model (results/mu_cases/walks_by_plant.md)"
bash scripts/studies.sh "$build" "$build/studies" mu_cases
cp "$build/studies/mu_cases/walks.csv" "$build/studies/mu_cases/walks_by_plant.md" results/mu_cases/

echo "== ground models: speed against accuracy (bench/ground_bench, 3 repetitions)"
if [[ -x "$build/bench/ground_bench" ]]; then
  "$build/bench/ground_bench" 3 >results/ground_bench.csv
  /usr/bin/python3 plots/ground_chart.py results/ground_bench.csv >results/ground_bench.md
else
  echo "  skipped: $build/bench/ground_bench not built (GAITOPT_BUILD_BENCH=OFF)" >&2
fi
