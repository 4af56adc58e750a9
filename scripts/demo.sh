#!/usr/bin/env bash
# The main job of `make demo`: runs gaitopt into results/ and says where everything is.
# The quick part (a minute: the robots, the polynomial and the optimal five-link gait, one
# closed-loop walk, their report pages) always runs; --full (`make demo-full`) adds the RABBIT
# and cost-of-transport solves, the comparisons, every walk and stability sweep, and the gait
# libraries (tens of minutes).
# Usage: scripts/demo.sh BUILD_DIR [--full]
set -euo pipefail
build=${1:-build}
full=${2:-}
[[ -z "$full" || "$full" == --full ]] || { echo "usage: $0 BUILD_DIR [--full]" >&2; exit 2; }
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"  # relative paths in every output (summary.json echoes the config path)
bin="$build/apps/gaitopt"
[[ -x "$bin" ]] || { echo "demo: $bin not built (run make build)" >&2; exit 1; }
out="results/inspect"
mkdir -p "$out"

echo "== gaitopt inspect: every shipped robot at its standing posture"
for robot in configs/robots/*.yaml; do
  name=$(basename "$robot" .yaml)
  "$bin" inspect --robot "$robot" >"$out/$name.json.tmp" && mv "$out/$name.json.tmp" "$out/$name.json"
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); \
print(f\"  {d['robot']:<18} {d['n_links']} links  mass {d['total_mass']:.2f} kg  \
CoM height {d['com']['position'][1]:.3f} m\")" "$out/$name.json"
done

echo "== Mu (2004) Table 4.1 posture: dynamics and the angle-convention picture"
"$bin" inspect --robot "configs/robots/mu2004_five_link.yaml" \
  --state "configs/states/mu2004_table41.json" >"$out/mu2004_table41.json"
if /usr/bin/python3 -c "import matplotlib" 2>/dev/null; then
  /usr/bin/python3 "plots/convention.py" "$out/mu2004_table41.json" "results/convention.png"
  echo "  picture: results/convention.png"
else
  echo "  warning: python3-matplotlib missing, no picture drawn (scripts/install-deps.sh installs it)" >&2
fi
echo "== gaitopt poly: Mu (2004) ch. 3 polynomial gait of the five-link robot"
"$bin" poly --robot "configs/robots/mu2004_five_link.yaml" \
  --gait "configs/gaits/mu2004.yaml" --out "results/poly_mu2004"
echo "== gaitopt poly: the same gait with its hip searched for the shipped foot"
"$bin" poly --robot "configs/robots/mu2004_five_link.yaml" \
  --gait "configs/gaits/mu2004_zmp.yaml" --out "results/poly_zmp_mu2004"

echo "== gaitopt optimize: the default five-link problem from the polynomial gait"
"$bin" optimize --config configs/ocp/mu2004_walk.yaml --out results/opt_mu2004 --quiet
echo "== gaitopt simulate: 20 steps of the optimal gait under computed torque"
# --cop-limit fail: a CoP beyond the 5 cm heel is a foot rotation, the strict rule of the
# curated walks (scripts/closed_loop_demo.sh).
"$bin" simulate --reference results/opt_mu2004 --controller computed_torque --steps 20 --rate 50 \
  --cop-limit fail \
  --out results/walk_opt_mu2004_computed_torque --quiet

echo "== gaitopt report: one page per result (animated robot, summary, charts)"
for dir in results/poly_mu2004 results/opt_mu2004 results/walk_opt_mu2004_computed_torque; do
  "$bin" report "$dir"
done

if [[ "$full" == --full ]]; then
  echo "== gaitopt optimize: the RABBIT benchmark of Kelly (2017)"
  "$bin" optimize --config configs/ocp/rabbit_kelly2017.yaml --out results/opt_rabbit --quiet

  echo "== gaitopt optimize: the default problem again, exported at 200 Hz (a sample to commit)"
  "$bin" optimize --config configs/ocp/mu2004_walk.yaml --rate 200 --no-plots --quiet \
    --out results/sample_opt_mu2004_200hz
  echo "== gaitopt optimize: the passive compass gait (no torque: a check of the transcription)"
  "$bin" optimize --config configs/ocp/compass_gait_passive.yaml --out results/opt_compass_passive \
    --quiet

  echo "== gaitopt optimize: the default problem designed to be walked (strike, margins)"
  "$bin" optimize --config configs/ocp/mu2004_walk_robust.yaml --out results/opt_robust_mu2004 \
    --quiet
  echo "== gaitopt optimize: least cost of transport, free single/double support split"
  "$bin" optimize --config configs/ocp/mu2004_walk_cot.yaml --out results/opt_cot_mu2004 --quiet

  echo "== polynomial (A: Mu's hip plan, B: searched for the foot) versus torque-squared optimal (C)"
  /usr/bin/python3 plots/compare_gaits.py results/poly_mu2004 results/poly_zmp_mu2004 \
    results/opt_mu2004 \
    results/poly_vs_opt_mu2004.md
  echo "== polynomial (A) versus least-cost-of-transport (B) gait of the five-link robot"
  /usr/bin/python3 plots/compare_gaits.py results/poly_mu2004 results/opt_cot_mu2004 \
    results/poly_vs_cot_mu2004.md

  echo "== gaitopt compare: both polynomial gaits versus the optimal gait, table and overlaid plots"
  "$bin" compare results/poly_mu2004 results/poly_zmp_mu2004 results/opt_mu2004 \
    --out results/compare_poly_opt_mu2004

  echo "== gaitopt impact-map: single or double impact over Mu's ch. 5 grid (Fig. 5.3)"
  "$bin" impact-map --robot configs/robots/mu2004_five_link.yaml --out results/impact_map_mu2004 \
    --quiet

  bash scripts/closed_loop_demo.sh "$build"

  # Gait libraries resume: points already in results/library_*/index.csv are not solved again.
  echo "== gaitopt library: 5 speeds x 5 step lengths of the default problem"
  "$bin" library --config configs/library/mu2004_speed_step.yaml --out results/library_mu2004 --quiet
  echo "== gaitopt library: least cost of transport from 0.4 to 1.4 m/s (the speed sweep)"
  "$bin" library --config configs/library/mu2004_cot_speed.yaml \
    --out results/library_cot_speed_mu2004 --quiet
  echo "== gaitopt library: slopes from -0.1 to 0.1 rad x 3 speeds"
  "$bin" library --config configs/library/mu2004_slope.yaml --out results/library_slope_mu2004 --quiet
  echo "== gaitopt library: the ensemble problem (designed to be walked), 5 speeds x 3 step lengths"
  "$bin" library --config configs/library/mu2004_ensemble_speed_step.yaml \
    --out results/library_ensemble_mu2004 --quiet
  echo "== gaitopt report: the pages of the libraries, walks and sweeps"
  for dir in results/library_*/ results/walk_*/ results/stability_*/; do
    "$bin" report "${dir%/}" --no-gif
  done
fi

echo
echo "Report page: $root/results/walk_opt_mu2004_computed_torque/report.html (open it in a browser)"
echo "Results are in $root/results/:"
echo "  inspect/*.json          robot models and dynamics at a posture"
echo "  convention.png          angle convention"
echo "  poly_mu2004/            polynomial gait: trajectory.csv (1 kHz), summary.json, *.png"
echo "  opt_mu2004/, opt_rabbit/, opt_cot_mu2004/  optimal gaits, same files"
echo "  poly_vs_opt_mu2004.md, poly_vs_cot_mu2004.md  the comparison tables above"
echo "  library_*/              gait libraries: index.csv, index.json, library.png, points/"
echo "  compare_poly_opt_mu2004/  comparison.md and overlaid angles, torques, forces, ZMP"
echo "  impact_map_mu2004/      impact type over step length x approach angle (Mu Fig. 5.3)"
echo "  walk_*/                 closed-loop walks: summary.json, steps.csv, walk_overview.png"
echo "  poincare_multipliers.png  the walks' Poincare multipliers on the unit circle"
echo "  stability_*/            sweeps: sweep_*.csv, summary.json, stability.png"
echo "  ground_bench.md, ground_speed_accuracy.png  speed against accuracy of the grounds"
echo "  */report.html           one self-contained page per result; walk_*/walk.gif"
[[ "$full" == --full ]] || echo "(make demo-full adds RABBIT, the comparisons, every walk and sweep, the libraries)"
