#!/usr/bin/env bash
# The cost-robustness front of the gait designed with model variants
# (configs/ocp/mu2004_walk_ensemble.yaml): the same problem with copies of the robot W % lighter
# and heavier for W = 0 (no copies: the strike and the margins alone), 5, 10, 15 and 20, each
# solved and walked 20 steps under computed torque and Mu's sliding mode on plants of other masses:
# the rigid ground and the LCP ground (a CoP beyond the foot is a fall) and DART (a build with
# -DGAITOPT_DART=ON; the controller clips its ankle torque to the foot). Writes OUT/solves.csv (the
# default optimum and each width: status, iterations, cost, time, posture), OUT/walks.csv (one row
# per walk), then OUT/front.csv, OUT/front.md (per width: cost, posture, the mass interval walked
# around the nominal per ground and controller) and OUT/front.png
# (scripts/plots/ensemble_front_chart.py OUT).
# Usage: scripts/ensemble_front.sh BUILD_DIR OUT_DIR   (from the repository root; about 8 minutes)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh" "$@"  # build, out, bin, work
# A copy of configs/ whose relative paths resolve (the solver is the shipped config's own).
bash scripts/solver_configs.sh "$work/configs" mumps
# One row of OUT/solves.csv from a gait folder's summary.json.
solve_row() {
  /usr/bin/python3 - "$1/summary.json" "$2" >>"$out/solves.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
p = s.get("posture_deg", {})
posture = [p.get(k) for k in ("max_torso_lean", "max_stance_knee_flexion", "max_swing_knee_flexion")]
print(f"{sys.argv[2]},{s['status']},{int(s['converged'])},{s['iterations']},{s['cost']:.6g},"
      f"{s['wall_time_s']:.3g}," + ",".join("" if v is None else f"{v:.3g}" for v in posture))
PY
}
echo "width_percent,status,converged,iterations,cost,wall_time_s,max_torso_lean,\
max_stance_knee_flexion,max_swing_knee_flexion" >"$out/solves.csv"
"$bin" optimize --config configs/ocp/mu2004_walk.yaml --out "$work/default" --no-plots --quiet \
  >/dev/null
solve_row "$work/default" default
declare -A masses=([rigid]="-0.2 -0.1 -0.05 0 0.05 0.1 0.2" [lcp]="-0.1 -0.05 0 0.05 0.1"
  [dart]="-0.1 -0.05 0 0.05 0.1")
echo "width_percent,ground,controller,plant_mass,steps,max_tracking_error_rad,max_slip_m,failure" \
  >"$out/walks.csv"
for width in 0 5 10 15 20; do
  config="$work/configs/ocp/front_$width.yaml"
  /usr/bin/python3 - configs/ocp/mu2004_walk_ensemble.yaml "$config" "$width" <<'PY'
import re, sys
source, target, width = sys.argv[1], sys.argv[2], int(sys.argv[3])
text = open(source).read()
if width == 0:  # the nominal robot alone: no copies, no law for them
    text = re.sub(r"^variant\w*:.*\n", "", text, flags=re.M)
else:
    lo, hi = 1 - width / 100, 1 + width / 100
    text = re.sub(r"^variants:.*$", f"variants: [{{mass_scale: {lo:g}}}, {{mass_scale: {hi:g}}}]",
                  text, flags=re.M)
open(target, "w").write(text)
PY
  gait="$work/gait_$width"
  echo "width $width %: solving" >&2
  "$bin" optimize --config "$config" --out "$gait" --no-plots --quiet >/dev/null 2>&1 || true
  [[ -d "$gait" ]] || { solve_row "$gait.failed" "$width"; continue; }
  solve_row "$gait" "$width"
  for ground in rigid lcp dart; do
    limit=fail
    [[ $ground == dart ]] && limit=saturate
    for controller in computed_torque mu_sliding_mode; do
      for mass in ${masses[$ground]}; do
        "$bin" simulate --reference "$gait" --ground "$ground" --controller "$controller" \
          --mass-error="$mass" --cop-limit "$limit" --steps 20 --out "$work/walk" --no-plots \
          --no-poincare --quiet >/dev/null
        /usr/bin/python3 scripts/walk_row.py "$work/walk/summary.json" "$width" "$ground" \
          "$controller" "$(/usr/bin/python3 -c "print(f'{1 + $mass:g}')")" >>"$out/walks.csv"
      done
    done
  done
done
/usr/bin/python3 scripts/plots/ensemble_front_chart.py "$out"
