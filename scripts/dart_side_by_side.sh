#!/usr/bin/env bash
# What DART says beside the toolkit's own grounds: the polynomial gait (Mu ch. 3), the default
# optimum, the two gaits designed to be walked (margins: mu2004_walk_robust; model variants:
# mu2004_walk_ensemble) under computed torque, and RABBIT's optimum (Kelly 2017, point feet) under
# HZD, each walked 20 steps on the rigid ground, the LCP ground and in DART (a build with
# -DGAITOPT_DART=ON), then swept over pushes (-3..3 N s) and plant mass errors (-20..+20 %) on the
# rigid ground and in DART (`gaitopt stability`). On every plant the controller clips its ankle
# torque to the foot (--cop-limit saturate): in DART a foot tips by DART's own physics, and the
# same rule keeps the grounds comparable. Writes OUT/walks.{csv,md} (steps, tracking error, slip,
# least CoP margin, largest friction ratio |F_t|/F_n of a loaded tip, largest stance-foot tilt,
# failure), OUT/intervals.{csv,md} (the push and mass intervals walked), OUT/interval_ends.{csv,md}
# (the failure just outside each interval) and OUT/side_by_side.png
# (plots/dart_side_by_side_chart.py: the steps and both intervals per gait and ground).
# Usage: scripts/dart_side_by_side.sh BUILD_DIR OUT_DIR   (from the repository root; ~5 minutes)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh"
"$bin" poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$work/poly" --no-plots >/dev/null
for config in mu2004_walk mu2004_walk_robust mu2004_walk_ensemble rabbit_kelly2017; do
  "$bin" optimize --config "configs/ocp/$config.yaml" --out "$work/$config" --no-plots \
    --quiet >/dev/null
done
gaits=(poly mu2004_walk mu2004_walk_robust mu2004_walk_ensemble rabbit_kelly2017)
controller_of() { [[ $1 == rabbit_kelly2017 ]] && echo hzd || echo computed_torque; }

echo "gait,controller,ground,steps,max_tracking_error_rad,max_slip_m,min_cop_margin_m,max_friction_ratio,max_foot_tilt_rad,failure" \
  >"$out/walks.csv"
for gait in "${gaits[@]}"; do
  for ground in rigid lcp dart; do
    "$bin" simulate --reference "$work/$gait" --ground "$ground" \
      --controller "$(controller_of "$gait")" --cop-limit saturate --steps 20 \
      --out "$work/walk" --no-plots --no-poincare --quiet >/dev/null
    /usr/bin/python3 - "$work/walk/summary.json" "$gait" "$(controller_of "$gait")" "$ground" \
      >>"$out/walks.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
margin = s.get("min_cop_margin_m")
print(",".join(sys.argv[2:]) + f",{s['steps_completed']},{s['max_tracking_error']:.3g},"
      f"{s.get('max_slip_m') or 0:.3g},{'' if margin is None else f'{margin:.3g}'},"
      f"{s['max_friction_ratio']:.3g},{s['max_foot_tilt_rad']:.3g}," + s["failure"].replace(",", ";"))
PY
  done
done

echo "gait,controller,ground,push_from_Ns,push_to_Ns,mass_from,mass_to" >"$out/intervals.csv"
echo "gait,controller,ground,sweep,side,value,failure" >"$out/interval_ends.csv"
for gait in "${gaits[@]}"; do
  for ground in rigid dart; do
    "$bin" stability --reference "$work/$gait" --ground "$ground" \
      --controller "$(controller_of "$gait")" --cop-limit saturate --steps 20 \
      --sweep push=-3:3:13 --sweep mass_error=-0.2:0.2:9 --out "$work/stability_${gait}_$ground" \
      --no-plots --quiet >/dev/null
    /usr/bin/python3 - "$work/stability_${gait}_$ground/summary.json" "$out" "$gait" \
      "$(controller_of "$gait")" "$ground" <<'PY'
import json, os, sys
sweeps = json.load(open(sys.argv[1]))["sweeps"]
row = sys.argv[3:]
cells, ends = [], []
for name, offset in (("push", 0.0), ("mass_error", 1.0)):
    lo, hi = sweeps[name]["walks_from"], sweeps[name]["walks_to"]
    cells += ["", ""] if lo is None else [f"{lo + offset:g}", f"{hi + offset:g}"]
    for side in ("fails_below", "fails_above"):
        end = sweeps[name].get(side)
        if end:
            failure = end["failure"].replace(",", ";")
            ends.append(",".join(row + [name, side, f"{end['value'] + offset:g}", failure]))
with open(os.path.join(sys.argv[2], "intervals.csv"), "a") as f:
    f.write(",".join(row + cells) + "\n")
with open(os.path.join(sys.argv[2], "interval_ends.csv"), "a") as f:
    f.writelines(line + "\n" for line in ends)
PY
  done
done

/usr/bin/python3 - "$out" <<'PY'
import csv, math, os, sys
out = sys.argv[1]
walks = list(csv.DictReader(open(os.path.join(out, "walks.csv"))))
lines = ["| gait (controller) | rigid ground | LCP ground | DART |", "|---|---|---|---|"]
for gait in dict.fromkeys(r["gait"] for r in walks):
    rows = {r["ground"]: r for r in walks if r["gait"] == gait}
    def cell(r):
        text = f"{r['steps']} of 20, error {float(r['max_tracking_error_rad']):.2g} rad"
        if float(r["max_slip_m"]) > 0:
            text += f", slip {1000 * float(r['max_slip_m']):.2g} mm"
        text += f", friction {float(r['max_friction_ratio']):.2f}"
        if float(r["max_foot_tilt_rad"]) > 0:
            text += f", foot tilt {math.degrees(float(r['max_foot_tilt_rad'])):.2g} deg"
        return text + (f" ({r['failure']})" if int(r["steps"]) < 20 else "")
    lines.append(f"| `{gait}` ({rows['rigid']['controller']}) | "
                 + " | ".join(cell(rows[g]) for g in ("rigid", "lcp", "dart")) + " |")
open(os.path.join(out, "walks.md"), "w").write("\n".join(lines) + "\n")
intervals = list(csv.DictReader(open(os.path.join(out, "intervals.csv"))))
lines = ["| gait (controller) | push walked [N s], rigid | push, DART | plant mass walked, rigid "
         "| plant mass, DART |", "|---|---|---|---|---|"]
def span(r, a, b):
    if not r[a]:
        return "falls at nominal"
    return f"{r[a]} only" if r[a] == r[b] else f"{r[a]} to {r[b]}"
for gait in dict.fromkeys(r["gait"] for r in intervals):
    rows = {r["ground"]: r for r in intervals if r["gait"] == gait}
    lines.append(f"| `{gait}` ({rows['rigid']['controller']}) | "
                 + " | ".join(span(rows[g], f"{q}_from{u}", f"{q}_to{u}")
                              for q, u in (("push", "_Ns"), ("mass", "")) for g in ("rigid", "dart"))
                 + " |")
open(os.path.join(out, "intervals.md"), "w").write("\n".join(lines) + "\n")
ends = list(csv.DictReader(open(os.path.join(out, "interval_ends.csv"))))
lines = ["| gait | plant | sweep | first value that falls below / above the interval |",
         "|---|---|---|---|"]
for gait in dict.fromkeys(r["gait"] for r in ends):
    for ground in ("rigid", "dart"):
        for sweep, unit in (("push", " N s"), ("mass_error", "")):
            found = {r["side"]: r for r in ends
                     if (r["gait"], r["ground"], r["sweep"]) == (gait, ground, sweep)}
            text = " / ".join(f"{found[s]['value']}{unit}: {found[s]['failure']}"
                              for s in ("fails_below", "fails_above") if s in found)
            if text:
                name = "mass" if sweep == "mass_error" else sweep
                lines.append(f"| `{gait}` | {ground} | {name} | {text} |")
open(os.path.join(out, "interval_ends.md"), "w").write("\n".join(lines) + "\n")
print(open(os.path.join(out, "walks.md")).read() + "\n" + open(os.path.join(out, "intervals.md")).read())
PY
/usr/bin/python3 plots/dart_side_by_side_chart.py "$out"
