#!/usr/bin/env bash
# plots/dart_side_by_side_chart.py on a made-up study: a gait that falls at nominal on
# every ground, one that walks the rigid ground at a single push and mass but falls in DART, and
# one that walks everywhere; the picture at plot_style's size, and "error: <file>: ..." for a
# missing walks.csv, a missing column and a steps cell that is not a number.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: dart_side_by_side_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy, PIL" 2>/dev/null || skip "no matplotlib/numpy/Pillow"
chart="$ROOT/plots/dart_side_by_side_chart.py"
out="$TMP/study"
mkdir -p "$out"
cat >"$out/walks.csv" <<'CSV'
gait,controller,ground,steps,max_tracking_error_rad,max_slip_m,min_cop_margin_m,max_friction_ratio,max_foot_tilt_rad,failure
poly,computed_torque,rigid,0,0.2,0.0001,-4,0.6,0,step 1: stance tip lifts off the ground
poly,computed_torque,lcp,0,1,0.0005,-0.9,0.6,0,step 1: stance tip lifts off the ground
poly,computed_torque,dart,0,0.02,0.01,-0.2,0.2,0.4,step 1: slip: a tip slid further than max_slip within the step
walk,computed_torque,rigid,20,0.003,0,0.05,0.4,0,
walk,computed_torque,lcp,20,0.02,0,-0.5,0.6,0,
walk,computed_torque,dart,3,0.1,0.009,-4,0.7,0.1,step 4: slip: a tip slid further than max_slip within the step
rabbit,hzd,rigid,20,3e-05,0,,0.4,0,
rabbit,hzd,lcp,20,0.02,0,,0.8,0,
rabbit,hzd,dart,20,0.02,0.002,,0.5,0,
CSV
cat >"$out/intervals.csv" <<'CSV'
gait,controller,ground,push_from_Ns,push_to_Ns,mass_from,mass_to
poly,computed_torque,rigid,,,,
poly,computed_torque,dart,,,,
walk,computed_torque,rigid,0,0,1,1
walk,computed_torque,dart,,,,
rabbit,hzd,rigid,-3,3,0.8,1.2
rabbit,hzd,dart,-2.5,1,0.9,1.15
CSV
png="$out/side_by_side.png"

"$PY" "$chart" "$out" >"$TMP/printed" || fail "exit $? on a good study"
[[ "$(cat "$TMP/printed")" == "$png" ]] || fail "printed: $(cat "$TMP/printed")"
[[ -s $png ]] || fail "side_by_side.png empty"
"$PY" - "$ROOT/plots" "$png" <<'PY' || fail "side_by_side.png size"
import sys
sys.path.insert(0, sys.argv[1])
from PIL import Image
import dart_side_by_side_chart as chart
import plot_style
want = tuple(int(inches * plot_style.DPI) for inches in chart.FIGSIZE)  # Agg truncates
with Image.open(sys.argv[2]) as im:
    assert im.format == "PNG" and im.size == want, (im.format, im.size, want)
PY

# expect_error FILE MESSAGE: the chart exits 1 with "error: FILE: MESSAGE" on stderr.
expect_error() {
  "$PY" "$chart" "$out" >/dev/null 2>"$TMP/err"
  local rc=$?
  [[ $rc -eq 1 ]] || fail "exit $rc, expected 1 for '$2'"
  grep -qF "error: $1: $2" "$TMP/err" || fail "stderr: $(cat "$TMP/err")"
}
cp "$out/walks.csv" "$TMP/walks.csv"
rm "$out/walks.csv"
expect_error "$out/walks.csv" "cannot read the walk table"
cut -d, -f1-3,5- "$TMP/walks.csv" >"$out/walks.csv"
expect_error "$out/walks.csv" "missing column 'steps'"
sed '7s/,3,/,three,/' "$TMP/walks.csv" >"$out/walks.csv"
expect_error "$out/walks.csv:7" "column 'steps': expected a finite number, found 'three'"
echo "dart side-by-side chart: picture at its size; a missing file, column and number named"
