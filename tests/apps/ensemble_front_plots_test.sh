#!/usr/bin/env bash
# plots/ensemble_front_chart.py on a made-up `gaitopt study` folder and default optimum
# (cost 100): a
# width that walks the rigid ground at 0.9-1.1 with a gap at 1.2 and falls at nominal on the LCP
# ground, and a width whose solve failed; the intervals in the table and CSV, the cost ratios,
# the picture, and "error: <file>: ..." for a default optimum without a cost.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: ensemble_front_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/plots/ensemble_front_chart.py"
out="$TMP/front"
mkdir -p "$out" "$TMP/default"
echo '{"cost": 100}' >"$TMP/default/summary.json"
cat >"$out/solves.csv" <<'CSV'
gait,width_percent,status,converged,iterations,cost,wall_time_s,max_torso_lean_deg,max_stance_knee_flexion_deg,max_swing_knee_flexion_deg
mu2004_walk_ensemble,10,Solve_Succeeded,1,185,250,20,12,44,56
mu2004_walk_ensemble,20,Maximum_Iterations_Exceeded,0,400,900,60,,,
CSV
{
  echo "gait,width_percent,walk,controller,plant_option,plant,steps,steps_requested,failure"
  for m in -0.2:0 -0.1:20 0:20 0.1:20 0.2:3; do
    echo "mu2004_walk_ensemble,10,rigid,computed_torque,mass-error,${m%%:*},${m##*:},20,"
  done
  for m in -0.1:20 0:1 0.1:20; do
    echo "mu2004_walk_ensemble,10,lcp,computed_torque,mass-error,${m%%:*},${m##*:},20,"
  done
} >"$out/walks.csv"

"$PY" "$chart" "$out" "$TMP/default" >"$TMP/printed" || fail "exit $? on a good front"
for f in front.csv front.md front.png; do
  grep -qx "$out/$f" "$TMP/printed" || fail "$f not printed"
  [[ -s $out/$f ]] || fail "$f empty"
done
has_text "$out/front.md" "| 10 | 250.0 (2.50) | 12.0, 44.0, 56.0 | 0.9-1.1 | falls at ×1 | falls at ×1 |" \
  "width 10 row"
has_text "$out/front.md" "| 20 | 900.0 (9.00), not converged | —, —, — |" "failed solve row"
grep -q "^10,1,250,2.5,12,44,56,0.9-1.1,,," "$out/front.csv" ||
  fail "width 10 csv row: $(cat "$out/front.csv")"

# Where the chart puts a width: a gait that falls on the nominal plant apart from one that walks
# it only (an interval of width 0), a failed solve not at all; widths drawn at one place (cost
# ratios equal to 0.01) share one label.
(cd "$ROOT/plots" && "$PY" - <<'PY') || fail "front points or labels"
import ensemble_front_chart as chart
import plot_style
key = ("rigid", "computed_torque")
rows = [{"converged": True, "cost_ratio": 1.5, "width_percent": 5, key: (1.0, 1.0)},
        {"converged": True, "cost_ratio": 1.6, "width_percent": 10, key: None},
        {"converged": False, "cost_ratio": 9.0, "width_percent": 20, key: (0.9, 1.1)}]
points = chart.front_points(rows, *key)
assert chart.FALLS_AT < 0 and points == [(0.0, 1.5, 5), (chart.FALLS_AT, 1.6, 10)], points
fig, ax = plot_style.pyplot().subplots()
chart.label_points(ax, [(0.2, 1.690, 5), (0.2, 1.692, 10), (0.3, 1.7, 15), (0.2, 1.8, 20)])
assert sorted(t.get_text() for t in ax.texts) == ["W=15", "W=20", "W=5, 10"], ax.texts
# An interval reaching its sweep's end is cut off by it; each ground's range for the legend.
walks = {(10, "rigid", "computed_torque"): {0.8: 0, 0.9: 20, 1.0: 20, 1.1: 20, 1.2: 3},
         (10, "lcp", "computed_torque"): {0.9: 20, 1.0: 20, 1.1: 20}}
assert not chart.cut_by_sweep((0.9, 1.1), walks[(10, "rigid", "computed_torque")])
assert chart.cut_by_sweep((0.9, 1.1), walks[(10, "lcp", "computed_torque")])
assert not chart.cut_by_sweep(None, walks[(10, "lcp", "computed_torque")])
ranges = chart.sweep_ranges(walks)
assert ranges == {"rigid": (0.8, 1.2), "lcp": (0.9, 1.1)}, ranges
assert chart.ground_label("lcp", ranges) == "lcp (swept ×0.9–1.1)"
rows = [{"converged": True, "cost_ratio": 2.0, "width_percent": 10, ("lcp", "computed_torque"):
         (0.9, 1.1), ("lcp", "computed_torque", "cut"): True}]
assert [tuple(round(v, 9) for v in p) for p in chart.cut_points(rows, "lcp", "computed_torque")] \
    == [(0.2, 2.0)]
PY

echo '{"status": "Solve_Succeeded"}' >"$TMP/default/summary.json"
"$PY" "$chart" "$out" "$TMP/default" >/dev/null 2>"$TMP/err" && fail "a default without a cost passed"
grep -q "^error: $TMP/default/summary.json: .*cost" "$TMP/err" || fail "stderr: $(cat "$TMP/err")"
"$PY" "$chart" "$out" >/dev/null 2>&1 && fail "one argument passed"
echo "ensemble front chart: intervals, ratios, picture and a default without a cost named"
