#!/usr/bin/env bash
# Shipped optima walked 20 steps each under computed torque and Mu's sliding mode on one ground,
# on plants whose masses and inertias are (1 + e) times the model's for each e of MASS_ERRORS
# (--mass-error), with the strict CoP rule of the other closed-loop results (--cop-limit fail) or
# the rule COP_LIMIT names (saturate: the controller clips its ankle torque to the foot).
# Writes OUT/NAME.csv and OUT/NAME.md ("of 10" is the first ten steps of the same walk).
# Usage: [COP_LIMIT=fail|saturate] scripts/walk_table.sh BUILD_DIR OUT_DIR NAME GROUND
#          "MASS_ERRORS" CONFIG...   (from the repository root; CONFIG: configs/ocp/CONFIG.yaml)
set -euo pipefail
build=${1:?usage: $0 BUILD_DIR OUT_DIR NAME GROUND MASS_ERRORS CONFIG...}
out=${2:?}
name=${3:?}
ground=${4:?}
read -r -a masses <<<"${5:?}"
shift 5
gaits=("$@")
cop_limit=${COP_LIMIT:-fail}
bin="$build/apps/gaitopt"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
for gait in "${gaits[@]}"; do
  "$bin" optimize --config "configs/ocp/$gait.yaml" --out "$work/ref_$gait" --no-plots \
    --quiet >/dev/null
done
echo "gait,controller,cop_limit,plant_mass,steps,max_tracking_error_rad,max_slip_m,failure" \
  >"$out/$name.csv"
for gait in "${gaits[@]}"; do
  for controller in computed_torque mu_sliding_mode; do
    for mass in "${masses[@]}"; do
      "$bin" simulate --reference "$work/ref_$gait" --ground "$ground" --controller "$controller" \
        --mass-error="$mass" --cop-limit "$cop_limit" --steps 20 --out "$work/walk" --no-plots \
        --no-poincare --quiet >/dev/null
      /usr/bin/python3 scripts/walk_row.py "$work/walk/summary.json" "$gait" "$controller" \
        "$cop_limit" "$(awk "BEGIN { m = sprintf(\"%.2f\", 1 + $mass); sub(/0$/, \"\", m); print m }")" \
        >>"$out/$name.csv"
    done
  done
done
/usr/bin/python3 - "$out/$name.csv" >"$out/$name.md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
masses = list(dict.fromkeys(r["plant_mass"] for r in rows))
print("| gait | controller (CoP rule) | " + " | ".join(f"plant mass x{m}" for m in masses) + " |")
print("|---|---|" + "---|" * len(masses))
key = lambda r: (r["gait"], r["controller"], r["cop_limit"])
for k in dict.fromkeys(key(r) for r in rows):
    cells = []
    for r in (r for r in rows if key(r) == k):
        n = int(r["steps"])
        step, _, rest = r["failure"].partition(": ")
        why = "" if n == 20 else f" ({step}: {rest.split(':')[0]})"
        cells.append(f"{min(n, 10)} of 10, {n} of 20{why}")
    print(f"| `{k[0]}` | {k[1]} ({k[2]}) | " + " | ".join(cells) + " |")
PY
cat "$out/$name.md"
