#!/usr/bin/env bash
# The gait designed with model variants (configs/ocp/mu2004_walk_ensemble.yaml) beside the
# default optimum (configs/ocp/mu2004_walk.yaml), walked on plants that are not their model
# (scripts/walk_table.sh): on the rigid ground at plant masses 0.8 to 1.2 and on the LCP ground at
# 0.9, 1.0 and 1.1, a CoP beyond the model's foot a fall; in DART (a build with -DGAITOPT_DART=ON)
# at 0.9 to 1.1, where the feet are bodies that tip by DART's own contact physics, the controller
# clips its ankle torque to the foot (COP_LIMIT=saturate). Then the ensemble solved at 24 to
# 36 SSP segments and its 8 DSP ones (its continuation, from the polynomial gait), with cost,
# iterations, time and posture per mesh. Writes OUT/{rigid,lcp,dart}_walks.{csv,md},
# OUT/meshes.{csv,md} and the shipped mesh's (30 + 8) OUT/summary.json.
# Usage: scripts/ensemble_walks.sh BUILD_DIR OUT_DIR   (from the repository root)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh" "$@"  # build, out, bin, work
gaits=(mu2004_walk mu2004_walk_ensemble)
bash scripts/walk_table.sh "$build" "$out" rigid_walks rigid "-0.2 -0.1 -0.05 0 0.05 0.1 0.2" \
  "${gaits[@]}"
bash scripts/walk_table.sh "$build" "$out" lcp_walks lcp "-0.1 0 0.1" "${gaits[@]}"
COP_LIMIT=saturate bash scripts/walk_table.sh "$build" "$out" dart_walks dart \
  "-0.1 -0.05 0 0.05 0.1" "${gaits[@]}"
for ssp in 24 27 30 33 36; do
  "$bin" optimize --config configs/ocp/mu2004_walk_ensemble.yaml \
    --out "$work/mesh_$ssp" --no-plots --quiet --set "phases[0].segments=$ssp" >/dev/null || true
done
/usr/bin/python3 - "$work" "$out" <<'PY'
import json, os, sys
work, out = sys.argv[1:]
rows = ["ssp_segments,dsp_segments,status,iterations,cost,wall_time_s,max_torso_lean_deg,"
        "max_stance_knee_flexion_deg,max_swing_knee_flexion_deg"]
table = ["| SSP + DSP segments | status | iterations | cost | time [s] | torso lean, stance knee, "
         "swing knee [deg] |", "|---|---|---|---|---|---|"]
for ssp in (24, 27, 30, 33, 36):
    folder = os.path.join(work, f"mesh_{ssp}")
    if not os.path.isdir(folder):
        folder += ".failed"
    s = json.load(open(os.path.join(folder, "summary.json")))
    p = s["posture_deg"]
    angles = [p["max_torso_lean"], p["max_stance_knee_flexion"], p["max_swing_knee_flexion"]]
    dsp = s["mesh_history"][-1]["segments"][1]
    rows.append(f"{ssp},{dsp},{s['status']},{s['iterations']},{s['cost']:.6g},"
                f"{s['wall_time_s']:.3g}," + ",".join(f"{a:.3g}" for a in angles))
    table.append(f"| {ssp} + {dsp} | {s['status']} | {s['iterations']} | {s['cost']:.2f} | "
                 f"{s['wall_time_s']:.1f} | " + ", ".join(f"{a:.1f}" for a in angles) + " |")
open(os.path.join(out, "meshes.csv"), "w").write("\n".join(rows) + "\n")
open(os.path.join(out, "meshes.md"), "w").write("\n".join(table) + "\n")
# The shipped mesh's optimum in full, for the README's table.
open(os.path.join(out, "summary.json"), "w").write(
    open(os.path.join(work, "mesh_30", "summary.json")).read())
print("\n".join(table))
PY
