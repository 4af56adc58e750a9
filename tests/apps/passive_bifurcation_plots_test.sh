#!/usr/bin/env bash
# plots/passive_bifurcation_chart.py on a made-up diagram: a period-1 branch whose
# multiplier crosses -1, a period-2 branch beyond it and a walk's steps; the picture, and
# "error: <file>: ..." with exit code 1 for a missing orbit file and a branch without a
# period-1 gait.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: passive_bifurcation_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/plots/passive_bifurcation_chart.py"
out="$TMP/diagram"
mkdir -p "$out"
{
  echo "period,slope,step,duration_s,interleg_angle_rad,max_multiplier,most_negative_multiplier"
  echo "1,0.010,0,3.89,0.42,0.58,-inf"
  echo "1,0.014,0,3.91,0.46,0.70,-0.70"
  echo "1,0.016,0,3.92,0.48,1.19,-1.19"
  echo "2,0.016,0,3.80,0.47,0.70,-inf"
  echo "2,0.016,1,4.00,0.49,0.70,-inf"
} >"$out/branch.csv"
{
  echo "slope,step,duration_s,interleg_angle_rad"
  for s in 200 201; do echo "0.014,$s,3.91,0.46"; done
  echo "0.016,200,3.80,0.47"
  echo "0.016,201,4.00,0.49"
} >"$out/orbit.csv"

"$PY" "$chart" "$out" >"$TMP/printed" 2>"$TMP/err" || fail "exit $? on a good diagram: $(cat "$TMP/err")"
grep -qx "$out/bifurcation.png" "$TMP/printed" || fail "path not printed: $(cat "$TMP/printed")"
"$PY" -c "import sys, matplotlib.image as im; assert im.imread(sys.argv[1]).shape[1] > 1200" \
  "$out/bifurcation.png" || fail "expected three panels side by side"

# The multiplier panel fits its data (a fixed -1.6 .. 1.2 cut the curves), infinities aside;
# at most five slope ticks (more ran together).
(cd "$ROOT/plots" && "$PY" - <<'PY') || fail "fitted limits, few ticks"
import numpy as np
import passive_bifurcation_chart as chart
import plot_style
lo, hi = chart.fitted_limits(np.array([-1.7, -0.7, -np.inf]), np.array([0.6, 1.7]), -1.0, 1.0)
assert lo < -1.7 and hi > 1.7 and np.isfinite(lo), (lo, hi)
fig, ax = plot_style.pyplot().subplots()
ax.plot([0.001, 0.0192], [0, 1])
chart.few_ticks(ax)
ticks = [t for t in ax.get_xticks() if 0.001 <= t <= 0.0192]
assert len(ticks) <= 6, ticks
PY
mv "$out/orbit.csv" "$TMP/orbit.csv"
"$PY" "$chart" "$out" >/dev/null 2>"$TMP/err"
[[ $? -eq 1 ]] && grep -q "^error: $out/orbit.csv: cannot read" "$TMP/err" ||
  fail "missing orbit: $(cat "$TMP/err")"
mv "$TMP/orbit.csv" "$out/orbit.csv"
sed -i '/^1,/d' "$out/branch.csv"
"$PY" "$chart" "$out" >/dev/null 2>"$TMP/err"
[[ $? -eq 1 ]] && grep -q "^error: $out/branch.csv: no period-1 gait" "$TMP/err" ||
  fail "no period-1 gait: $(cat "$TMP/err")"
echo "passive_bifurcation_plots_test: all checks passed"
