#!/usr/bin/env bash
# Whether a library's gaits walk where they were designed and off it: every point of LIBRARY
# solved and exported at each rate the walks name, and, where a walk asks for them, the blends
# at the centres of the grid's cells (`gaitopt interpolate`, its speed and step length halfway
# between two solved values of each), each walked 20 steps (`gaitopt simulate`, its default
# rules) under the walk's law on the walk's ground and plant (--mass-error, --length-error).
# Writes OUT/walks.csv (a row per walk: steps walked, the failure), OUT/summary.csv (per walk:
# gaits, walked, fell) and OUT/summary.md (the same, and where they fell).
# Without LIBRARY and WALKs: configs/library/mu2004_speed_step.yaml (the torque-squared optima)
# under computed torque on the rigid ground, exported at 250 Hz (the library's default rate) and
# walked on the nominal plant and on plants 1 % lighter and heavier, and exported at 1 kHz and
# walked on the nominal plant: about a minute on 2 cores.
# Usage: scripts/library_walks.sh BUILD_DIR OUT_DIR [LIBRARY WALK...]   (from the repository root)
#   WALK: GAITS/RATE/MASS_ERROR/LENGTH_ERROR/LAW/GROUND, GAITS `points` or `cells` (the cell
#   centres), LAW a `gaitopt simulate --controller`, GROUND its --ground; e.g.
#   points/250/-0.2/0/computed_torque/dart (the solved points exported at 250 Hz, in DART on a
#   plant 20 % lighter)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh"
library=${3:-configs/library/mu2004_speed_step.yaml}
walks=("${@:4}")
[[ ${#walks[@]} -gt 0 ]] || walks=(points/250/0/0/computed_torque/rigid
  points/250/-0.01/0/computed_torque/rigid points/250/0.01/0/computed_torque/rigid
  points/1000/0/0/computed_torque/rigid)
for walk in "${walks[@]}"; do
  [[ $walk =~ ^(points|cells)/[0-9]+/-?[0-9.]+/-?[0-9.]+/[a-z_]+/[a-z_]+$ ]] ||
    { echo "error: walk '$walk' is not GAITS/RATE/MASS/LENGTH/LAW/GROUND" >&2; exit 2; }
done

# gaits GAITS RATE: the folders of the library's points, or of its blends at the cell centres,
# exported at RATE (each made once).
gaits() {
  local lib="$work/library_$2"
  [[ -d $lib ]] || "$bin" library --config "$library" --rate "$2" --quiet --out "$lib" >/dev/null
  if [[ $1 == points ]]; then
    find "$lib/points" -mindepth 1 -maxdepth 1 -type d ! -name '*.failed' | sort
    return
  fi
  /usr/bin/python3 - "$lib/library.json" <<'PY' | while read -r speed step; do
import json, sys
axes = json.load(open(sys.argv[1]))["axes"]
mid = lambda v: [(a + b) / 2 for a, b in zip(v, v[1:])] or v
for speed in mid(axes["speed"]):
    for step in mid(axes["step_length"]):
        print(f"{speed:g} {step:g}")
PY
    local blend="$work/cells_$2/v${speed}_L${step}"
    [[ -d $blend ]] || "$bin" interpolate --library "$lib" --speed "$speed" --step-length "$step" \
      --rate "$2" --no-plots --out "$blend" >/dev/null
    echo "$blend"
  done
}

echo "gaits,rate_hz,mass_error,length_error,law,ground,gait,steps,failure" >"$out/walks.csv"
for walk in "${walks[@]}"; do
  IFS=/ read -r which rate mass length law ground <<<"$walk"
  while read -r gait; do
    "$bin" simulate --reference "$gait" --controller "$law" --ground "$ground" --steps 20 \
      --mass-error "$mass" --length-error "$length" --no-plots --no-poincare --quiet \
      --out "$work/walk" >/dev/null
    /usr/bin/python3 - "$work/walk/summary.json" "$which" "$rate" "$mass" "$length" "$law" \
      "$ground" "$(basename "$gait")" >>"$out/walks.csv" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print(",".join(sys.argv[2:]) + f",{s['steps_completed']}," + s["failure"].replace(",", ";"))
PY
  done < <(gaits "$which" "$rate")
done
/usr/bin/python3 - "$out" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(os.path.join(sys.argv[1], "walks.csv"))))
lines = ["| gaits | export | plant mass error | plant length error | law | ground | walks | walked 20 steps | fell | where they fell |",
         "|---|---|---:|---:|---|---|---:|---:|---:|---|"]
fields = ("gaits", "rate_hz", "mass_error", "length_error", "law", "ground")
key = lambda r: tuple(r[f] for f in fields)
table = csv.writer(open(os.path.join(sys.argv[1], "summary.csv"), "w", newline=""))
table.writerow([*fields, "walks", "walked", "fell"])
for case in dict.fromkeys(key(r) for r in rows):
    at = [r for r in rows if key(r) == case]
    fell = [r for r in at if int(r["steps"]) < 20]
    where = ("every one" if len(fell) == len(at) else
             "; ".join(f"{r['gait'].split('_s')[0]}: {r['failure'].split(' (')[0]}" for r in fell))
    table.writerow([*case, len(at), len(at) - len(fell), len(fell)])
    gaits, rate, mass, length, law, ground = case
    lines.append(f"| {'solved points' if gaits == 'points' else 'cell centres (blends)'} | "
                 f"{rate} Hz | {float(mass):+g} | {float(length):+g} | `{law}` | {ground} | {len(at)} | "
                 f"{len(at) - len(fell)} | {len(fell)} | {where} |")
open(os.path.join(sys.argv[1], "summary.md"), "w").write("\n".join(lines) + "\n")
PY
cat "$out/summary.md"
