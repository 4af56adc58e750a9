#!/usr/bin/env bash
# Whether the library's optima walk where they were designed: every point of
# configs/library/mu2004_speed_step.yaml solved and exported at 250 Hz (the library's default
# rate) and at 1 kHz, each walked 20 steps under computed torque on the rigid ground at the
# nominal plant (`gaitopt simulate`, its default rules), and the 250 Hz exports also on plants
# 1 % lighter and heavier (--mass-error). Writes OUT/walks.csv (a row per walk: steps walked,
# the failure) and OUT/summary.md (per export and plant: walked, fell, where). About a minute on
# 2 cores.
# Usage: scripts/library_walks.sh BUILD_DIR OUT_DIR   (run from the repository root)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh"
echo "rate_hz,mass_error,point,steps,failure" >"$out/walks.csv"
for rate in 250 1000; do
  "$bin" library --config configs/library/mu2004_speed_step.yaml --rate "$rate" --quiet \
    --out "$work/library_$rate" >/dev/null
  for point in "$work/library_$rate"/points/*/; do
    name=$(basename "$point")
    [[ $name == *.failed ]] && continue
    errors=(0)
    [[ $rate == 250 ]] && errors=(0 -0.01 0.01)
    for error in "${errors[@]}"; do
      "$bin" simulate --reference "$point" --steps 20 --mass-error "$error" --no-plots \
        --no-poincare --quiet --out "$work/walk" >/dev/null
      /usr/bin/python3 - "$work/walk/summary.json" "$rate" "$error" "$name" \
        >>"$out/walks.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(",".join(sys.argv[2:]) + f",{s['steps_completed']}," + s["failure"].replace(",", ";"))
PY
    done
  done
done
/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "walks.csv"))))
lines = ["| export | plant mass error | points | walked 20 steps | fell | where they fell |",
         "|---|---:|---:|---:|---:|---|"]
for case in dict.fromkeys((r["rate_hz"], r["mass_error"]) for r in rows):
    at = [r for r in rows if (r["rate_hz"], r["mass_error"]) == case]
    fell = [r for r in at if int(r["steps"]) < 20]
    where = ("every point" if len(fell) == len(at) else
             "; ".join(f"{r['point'].split('_s')[0]}: {r['failure'].split(' (')[0]}" for r in fell))
    lines.append(f"| {case[0]} Hz | {float(case[1]):+g} | {len(at)} | {len(at) - len(fell)} | "
                 f"{len(fell)} | {where} |")
open(os.path.join(sys.argv[1], "summary.md"), "w").write("\n".join(lines) + "\n")
PY
cat "$out/summary.md"
