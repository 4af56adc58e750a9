#!/usr/bin/env bash
# scripts/plots/ensemble_front_chart.py on a made-up front: the default optimum (cost 100), a
# width that walks the rigid ground at 0.9-1.1 with a gap at 1.2 and falls at nominal on the LCP
# ground, and a width whose solve failed; the intervals in the table and CSV, the cost ratios,
# the picture, and "error: <file>: ..." for a table without the default optimum.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: ensemble_front_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/scripts/plots/ensemble_front_chart.py"
out="$TMP/front"
mkdir -p "$out"
cat >"$out/solves.csv" <<'CSV'
width_percent,status,converged,iterations,cost,wall_time_s,max_torso_lean,max_stance_knee_flexion,max_swing_knee_flexion
default,Solve_Succeeded,1,15,100,0.1,8,30,90
10,Solve_Succeeded,1,185,250,20,12,44,56
20,Maximum_Iterations_Exceeded,0,400,900,60,,,
CSV
{
  echo "width_percent,ground,controller,plant_mass,steps,max_tracking_error_rad,max_slip_m,failure"
  for m in 0.8:0 0.9:20 1:20 1.1:20 1.2:3; do
    echo "10,rigid,computed_torque,${m%%:*},${m##*:},0.01,0,"
  done
  for m in 0.9:20 1:1 1.1:20; do echo "10,lcp,computed_torque,${m%%:*},${m##*:},0.01,0,"; done
} >"$out/walks.csv"

"$PY" "$chart" "$out" >"$TMP/printed" || fail "exit $? on a good front"
for f in front.csv front.md front.png; do
  grep -qx "$out/$f" "$TMP/printed" || fail "$f not printed"
  [[ -s $out/$f ]] || fail "$f empty"
done
grep -qF "| 10 | 250.0 (2.50) | 12.0, 44.0, 56.0 | 0.9-1.1 | falls at ×1 | falls at ×1 |" \
  "$out/front.md" || fail "width 10 row: $(cat "$out/front.md")"
grep -qF "| 20 | 900.0 (9.00), not converged | —, —, — |" "$out/front.md" ||
  fail "failed solve row: $(cat "$out/front.md")"
grep -q "^10,1,250,2.5,12,44,56,0.9-1.1,,," "$out/front.csv" ||
  fail "width 10 csv row: $(cat "$out/front.csv")"

sed -i '/^default,/d' "$out/solves.csv"
"$PY" "$chart" "$out" >/dev/null 2>"$TMP/err" && fail "a front without the default optimum passed"
grep -q "^error: $out/solves.csv: no row of the default optimum" "$TMP/err" ||
  fail "stderr: $(cat "$TMP/err")"
echo "ensemble front chart: intervals, ratios, picture and a missing default named"
