#!/usr/bin/env bash
# scripts/plots/strike_study_chart.py on a made-up study folder: a lands-at-rest variant swept by
# one controller (walks 0 .. 0.5 N s, fails at nominal under mass error, the failure read from
# its sweep CSV), a strike variant whose solve failed; the table's rows, the CSV's failures and
# the picture, and "error: <file>: ..." for a broken summary.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: strike_study_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/scripts/plots/strike_study_chart.py"
work="$TMP/work"
mkdir -p "$work/v0_f0.15_z0.06" "$work/v0_f0.15_z0.06_computed_torque"
touch "$work/v0_f0.15_z0.06.yaml" "$work/v0.1_f0.3_z0.yaml" "$work/notes.yaml"
cat >"$work/v0_f0.15_z0.06/summary.json" <<'JSON'
{"status": "Solve_Succeeded", "cost": 133.14, "min_zmp_margin": 0.06, "max_friction_ratio": 0.45}
JSON
cat >"$work/v0_f0.15_z0.06_computed_torque/summary.json" <<'JSON'
{"sweeps": {
  "push": {"walks_from": 0.0, "walks_to": 0.5,
           "fails_below": {"value": -0.25, "failure": "step 2: foot rotation"},
           "fails_above": {"value": 0.75, "failure": "step 3: foot rotation"}},
  "mass_error": {"nominal": 0.0, "walks_from": null, "walks_to": null}}}
JSON
printf '%s\n' "value,steps_completed,failure" "-0.025,0,step 1: fall" "0,0,step 1: foot rotation" \
  >"$work/v0_f0.15_z0.06_computed_torque/sweep_mass_error.csv"

"$PY" "$chart" "$work" "$TMP/out" >"$TMP/printed" || fail "exit $? on a good study"
for ext in csv md png; do
  grep -qx "$TMP/out/strike_study.$ext" "$TMP/printed" || fail "strike_study.$ext not printed"
  [[ -s $TMP/out/strike_study.$ext ]] || fail "strike_study.$ext empty"
done
grep -qF "| 0 | 0.15 | 0.06 | 133.14 | 0 .. 0.5 | fails |" "$TMP/out/strike_study.md" ||
  fail "rest variant row: $(cat "$TMP/out/strike_study.md")"
grep -qF "| 0.1 | 0.3 | 0 | solve failed |" "$TMP/out/strike_study.md" ||
  fail "failed solve row: $(cat "$TMP/out/strike_study.md")"
grep -qF "0.75: step 3: foot rotation" "$TMP/out/strike_study.csv" || fail "failure not in csv"
grep -qF "at nominal: step 1: foot rotation" "$TMP/out/strike_study.csv" ||
  fail "nominal failure not in csv: $(cat "$TMP/out/strike_study.csv")"

echo '{"cost": "high", "min_zmp_margin": 0.06, "max_friction_ratio": null}' \
  >"$work/v0_f0.15_z0.06/summary.json"
"$PY" "$chart" "$work" "$TMP/out" >/dev/null 2>"$TMP/err" && fail "a broken summary passed"
grep -q "^error: $work/v0_f0.15_z0.06/summary.json: key 'cost': expected a number" "$TMP/err" ||
  fail "stderr: $(cat "$TMP/err")"
echo "strike study chart: table, picture and a broken summary named"
