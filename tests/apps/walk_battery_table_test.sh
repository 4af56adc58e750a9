#!/usr/bin/env bash
# plots/walk_battery_table.py on a made-up `gaitopt study` folder: a gait that walks the rigid
# ground at 0.9-1.1 with a gap at 1.2, two of four pushes, one length and DART at two masses, and
# a gait without a strike whose solve failed; the intervals and the lists in the table and CSV;
# a study with an axis, its rows named by the axis's labels; columns only for the controllers the
# walks hold; and "error: <file>: ..." for a solve table without the trailing impulse's ratio.
# Needs Debian's python3-numpy (plot_io); skips (ctest: skipped) without it.
# Usage: walk_battery_table_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import numpy" 2>/dev/null || skip "no numpy"
table="$ROOT/plots/walk_battery_table.py"
out="$TMP/study"
mkdir -p "$out"
cat >"$out/solves.csv" <<'CSV'
gait,status,converged,iterations,cost,strike_normal_velocity_m_s,impulse_trailing_cone_ratio
strike,Solve_Succeeded,1,185,250,0.3,0.55
no_strike,Maximum_Iterations_Exceeded,0,400,132,-1e-9,
CSV
{
  echo "gait,walk,controller,plant_option,plant,steps,steps_requested,failure"
  for m in -0.2:0 -0.1:20 0:20 0.1:20 0.2:3; do
    echo "strike,rigid,computed_torque,mass-error,${m%%:*},${m##*:},20,"
  done
  for p in -2:20 -1:4 1:20 2:0; do echo "strike,rigid_push,computed_torque,push,${p%%:*},${p##*:},20,"; done
  for l in -0.05:20 0.05:1; do
    echo "strike,rigid_length,computed_torque,length-error,${l%%:*},${l##*:},20,"
  done
  for m in -0.1:0 0:20 0.1:20; do echo "strike,dart,computed_torque,mass-error,${m%%:*},${m##*:},20,"; done
  echo "strike,rigid,mu_sliding_mode,mass-error,0,2,20,"
} >"$out/walks.csv"

"$PY" "$table" "$out" >"$TMP/printed" || fail "exit $? on a good study"
for f in summary.csv summary.md; do
  grep -qx "$out/$f" "$TMP/printed" || fail "$f not printed"
done
has_text "$out/summary.md" \
  "| strike | 250.0 | 0.300 | 0.550 | 0.9-1.1 | -0.05 | -2 1 | — | — | 1 1.1 | falls at ×1 |" "strike row"
has_text "$out/summary.md" "| no_strike | 132.0, not converged | — | — | — | — |" \
  "failed solve row"
has_text "$out/summary.csv" "strike,1,250,0.3,0.55,0.9-1.1,-0.05,-2 1,—,—,1 1.1,falls at ×1," \
  "strike csv row"

# A study with an axis: one gait, a row per value of the axis, named by its label.
axis="$TMP/axis"
mkdir -p "$axis"
cat >"$axis/solves.csv" <<'CSV'
gait,penalty,status,converged,iterations,cost,strike_normal_velocity_m_s,impulse_trailing_cone_ratio
ens,ensemble,Solve_Succeeded,1,200,256,0.8,0.45
ens,V10,Solve_Succeeded,1,86,206,0.7,0.5
CSV
{
  echo "gait,penalty,walk,controller,plant_option,plant,steps,steps_requested,failure"
  for m in -0.1 0 0.1; do echo "ens,ensemble,rigid,computed_torque,mass-error,$m,20,20,"; done
  for m in -0.1:1 0:20 0.1:20; do echo "ens,V10,rigid,computed_torque,mass-error,${m%%:*},${m##*:},20,"; done
} >"$axis/walks.csv"
"$PY" "$table" "$axis" >/dev/null || fail "exit $? on a study with an axis"
has_text "$axis/summary.md" "| ensemble | 256.0 | 0.800 | 0.450 | 0.9-1.1 |" "axis row ensemble"
has_text "$axis/summary.md" "| V10 | 206.0 | 0.700 | 0.500 | 1-1.1 |" "axis row V10"

# The columns are those of the controllers the walks hold, in CONTROLLERS's order.
grep -q "plan DSP" "$out/summary.md" && fail "a plan-DSP column without its walks"
plan="$TMP/plan"
mkdir -p "$plan"
cp "$out/solves.csv" "$plan/"
{
  echo "gait,walk,controller,plant_option,plant,steps,steps_requested,failure"
  echo "strike,rigid_cases,mu_sliding_mode_plan_dsp,uncertainty-case,2,20,20,"
  echo "strike,rigid,computed_torque,mass-error,0,20,20,"
} >"$plan/walks.csv"
"$PY" "$table" "$plan" >/dev/null || fail "exit $? on a study with a plan-DSP controller"
has_text "$plan/summary.md" "| CT: dart | Mu plan DSP: rigid mass |" "plan-DSP header after CT's"
has_text "$plan/summary.md" "| 1 only | — | — | — | — | — | — | — | — | 2 | — | — |" \
  "plan-DSP row, no rigid-mass walks"
grep -q "Mu: rigid mass" "$plan/summary.md" && fail "Mu's column without its walks"
has_text "$plan/summary.csv" "Mu_plan_DSP_cases" "csv column named without spaces"

sed -i 's/,impulse_trailing_cone_ratio$//' "$out/solves.csv"
"$PY" "$table" "$out" >/dev/null 2>"$TMP/err" && fail "a solve table without the ratio passed"
grep -q "^error: $out/solves.csv: .*impulse_trailing_cone_ratio" "$TMP/err" ||
  fail "stderr: $(cat "$TMP/err")"
echo "walk battery table: intervals, walked lists, failed solve, axis rows, controller columns and a missing column named"
