#!/usr/bin/env bash
# Whether a library's optima walk where they were designed and off it: every point of LIBRARY
# solved and exported at each rate the walks name, each export walked 20 steps under computed
# torque on the rigid ground (`gaitopt simulate`, its default rules) on the plants the walks
# name (--mass-error, --length-error). Writes OUT/walks.csv (a row per walk: steps walked, the
# failure), OUT/summary.csv (per export and plant: points, walked, fell) and OUT/summary.md (the
# same, and where they fell).
# Without LIBRARY and WALKS: configs/library/mu2004_speed_step.yaml (the torque-squared optima),
# exported at 250 Hz (the library's default rate) and walked on the nominal plant and on plants
# 1 % lighter and heavier, and exported at 1 kHz and walked on the nominal plant: about a minute
# on 2 cores.
# Usage: scripts/library_walks.sh BUILD_DIR OUT_DIR [LIBRARY WALK...]   (from the repository root)
#   WALK: RATE/MASS_ERROR/LENGTH_ERROR, e.g. 250/-0.2/0 (a plant 20 % lighter, 250 Hz export)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh"
library=${3:-configs/library/mu2004_speed_step.yaml}
walks=("${@:4}")
[[ ${#walks[@]} -gt 0 ]] || walks=(250/0/0 250/-0.01/0 250/0.01/0 1000/0/0)
for walk in "${walks[@]}"; do
  [[ $walk =~ ^[0-9]+/-?[0-9.]+/-?[0-9.]+$ ]] || { echo "error: walk '$walk' is not RATE/MASS/LENGTH" >&2; exit 2; }
done
echo "rate_hz,mass_error,length_error,point,steps,failure" >"$out/walks.csv"
for walk in "${walks[@]}"; do
  IFS=/ read -r rate mass length <<<"$walk"
  lib="$work/library_$rate"
  [[ -d $lib ]] || "$bin" library --config "$library" --rate "$rate" --quiet --out "$lib" >/dev/null
  for point in "$lib"/points/*/; do
    name=$(basename "$point")
    [[ $name == *.failed ]] && continue
    "$bin" simulate --reference "$point" --steps 20 --mass-error "$mass" --length-error "$length" \
      --no-plots --no-poincare --quiet --out "$work/walk" >/dev/null
    /usr/bin/python3 - "$work/walk/summary.json" "$rate" "$mass" "$length" "$name" \
      >>"$out/walks.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(",".join(sys.argv[2:]) + f",{s['steps_completed']}," + s["failure"].replace(",", ";"))
PY
  done
done
/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "walks.csv"))))
lines = ["| export | plant mass error | plant length error | points | walked 20 steps | fell | where they fell |",
         "|---|---:|---:|---:|---:|---:|---|"]
key = lambda r: (r["rate_hz"], r["mass_error"], r["length_error"])
table = csv.writer(open(os.path.join(sys.argv[1], "summary.csv"), "w", newline=""))
table.writerow(["rate_hz", "mass_error", "length_error", "points", "walked", "fell"])
for case in dict.fromkeys(key(r) for r in rows):
    at = [r for r in rows if key(r) == case]
    fell = [r for r in at if int(r["steps"]) < 20]
    where = ("every point" if len(fell) == len(at) else
             "; ".join(f"{r['point'].split('_s')[0]}: {r['failure'].split(' (')[0]}" for r in fell))
    table.writerow([*case, len(at), len(at) - len(fell), len(fell)])
    lines.append(f"| {case[0]} Hz | {float(case[1]):+g} | {float(case[2]):+g} | {len(at)} | "
                 f"{len(at) - len(fell)} | {len(fell)} | {where} |")
open(os.path.join(sys.argv[1], "summary.md"), "w").write("\n".join(lines) + "\n")
PY
cat "$out/summary.md"
