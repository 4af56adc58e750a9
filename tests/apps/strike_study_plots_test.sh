#!/usr/bin/env bash
# plots/strike_study_chart.py on a made-up `gaitopt study` folder: a lands-at-rest variant swept by
# one controller (walks 0 .. 0.5 N s, fails at nominal under mass error, the failure from
# summary.json's nominal_failure), a strike variant whose solve failed; the table's rows, the CSV's failures and
# the picture, and "error: <file>: ..." for a broken summary.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: strike_study_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/plots/strike_study_chart.py"
work="$TMP/work"
rest=mu2004_walk_friction_margin=0.15_zmp_margin=0.06_strike_velocity=0
swept="$work/stability/$rest/0_computed_torque"
mkdir -p "$work/runs/$rest" "$swept"
# The study's solves.csv (configs/studies/strike_study.yaml's axes), the failed strike variant
# listed first to check the rows come out sorted by strike, then margins.
printf '%s\n' "gait,friction_margin,zmp_margin,strike_velocity,status,cost,folder" \
  "mu2004_walk,0.3,0,0.1,Maximum_Iterations_Exceeded,900,failed_strike" \
  "mu2004_walk,0.15,0.06,0,Solve_Succeeded,133.14,$rest" >"$work/solves.csv"
cat >"$work/runs/$rest/summary.json" <<'JSON'
{"status": "Solve_Succeeded", "cost": 133.14, "min_zmp_margin": 0.06, "max_friction_ratio": 0.45}
JSON
cat >"$swept/summary.json" <<'JSON'
{"sweeps": {
  "push": {"walks_from": 0.0, "walks_to": 0.5,
           "fails_below": {"value": -0.25, "failure": "step 2: foot rotation"},
           "fails_above": {"value": 0.75, "failure": "step 3: foot rotation"}},
  "mass_error": {"nominal": 0.0, "walks_from": null, "walks_to": null,
                 "nominal_failure": "step 1: foot rotation"}}}
JSON

"$PY" "$chart" "$work" "$TMP/out" >"$TMP/printed" || fail "exit $? on a good study"
for ext in csv md png; do
  grep -qx "$TMP/out/strike_study.$ext" "$TMP/printed" || fail "strike_study.$ext not printed"
  [[ -s $TMP/out/strike_study.$ext ]] || fail "strike_study.$ext empty"
done
grep -qF "| 0 | 0.15 | 0.06 | 133.14 | 0 .. 0.5 | fails |" "$TMP/out/strike_study.md" ||
  fail "rest variant row: $(cat "$TMP/out/strike_study.md")"
[[ $(sed -n 3p "$TMP/out/strike_study.md") == "| 0 |"* ]] || fail "rows not sorted by strike"
printf '%s\n' "gait,zmp_margin,strike_velocity,folder" "mu2004_walk,0,0,x" >"$TMP/no_axis.csv"
mkdir -p "$TMP/no_axis" && mv "$TMP/no_axis.csv" "$TMP/no_axis/solves.csv"
"$PY" "$chart" "$TMP/no_axis" "$TMP/out2" >/dev/null 2>"$TMP/err" && fail "a study without margins passed"
grep -q "friction_margin" "$TMP/err" || fail "missing column not named: $(cat "$TMP/err")"
grep -qF "| 0.1 | 0.3 | 0 | solve failed |" "$TMP/out/strike_study.md" ||
  fail "failed solve row: $(cat "$TMP/out/strike_study.md")"
grep -qF "0.75: step 3: foot rotation" "$TMP/out/strike_study.csv" || fail "failure not in csv"
grep -qF "at nominal: step 1: foot rotation" "$TMP/out/strike_study.csv" ||
  fail "nominal failure not in csv: $(cat "$TMP/out/strike_study.csv")"

# A variant falling at nominal under every controller is drawn in the "falls at ×1" column left
# of 0 (not at 0, a gait walking the nominal plant only); --redraw reads the CSV back alike.
(cd "$ROOT/plots" && "$PY" - "$TMP/out/strike_study.csv" <<'PY') || fail "falls column"
import sys
import strike_study_chart as chart
rows = chart.read_table(sys.argv[1])
rest = [r for r in rows if r["variant"] == "v0_f0.15_z0.06"]
assert chart.widest(rest, "push") == 0.5 and chart.widest(rest, "mass") is None, rest
assert chart.falls_x([0.5, None]) < 0 and chart.falls_x([None]) < 0
assert chart.widest([{"controller": "c", "mass_from": 0.0, "mass_to": 0.0}], "mass") == 0.0
PY
"$PY" "$chart" --redraw "$TMP/out" >"$TMP/printed" && grep -qx "$TMP/out/strike_study.png" "$TMP/printed" ||
  fail "--redraw: $(cat "$TMP/printed")"

echo '{"cost": "high", "min_zmp_margin": 0.06, "max_friction_ratio": null}' \
  >"$work/runs/$rest/summary.json"
"$PY" "$chart" "$work" "$TMP/out" >/dev/null 2>"$TMP/err" && fail "a broken summary passed"
grep -qF "error: $work/runs/$rest/summary.json: key 'cost': expected a number" "$TMP/err" ||
  fail "stderr: $(cat "$TMP/err")"
echo "strike study chart: table, picture and a broken summary named"
