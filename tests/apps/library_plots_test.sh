#!/usr/bin/env bash
# Checks of plots/library_plots.py on small made-up library folders: the picture for a
# 3 x 2 x 1 grid with a failed point (two panels), for a 2 x 1 x 3 grid (CoT vs slope), for an
# empty index, and "error: <file>: ..." with exit code 2 for a missing folder, a missing or
# malformed index.json and a point off the grid.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: library_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
SCRIPT="$ROOT/plots/library_plots.py"
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"

plot() {
  "$PY" "$SCRIPT" "$@" >"$TMP/out" 2>"$TMP/err"
  RC=$?
}

# expect_error NAME DIR PATTERN: exit 2 and one stderr line "error: ..." matching PATTERN.
expect_error() {
  plot "$2"
  [[ $RC -eq 2 ]] || fail "$1: exit $RC, expected 2 (stderr: $(cat "$TMP/err"))"
  [[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "$1: expected one stderr line: $(cat "$TMP/err")"
  grep -Eq "^error: $3" "$TMP/err" || fail "$1: stderr '$(cat "$TMP/err")' !~ '$3'"
  [[ ! -e "$2/library.png" ]] || fail "$1: library.png written"
}

# make_index DIR SPEEDS STEPS SLOPES [FAILED...]: index.json of a grid whose every point is
# finished, CoT made up, the points named in FAILED (grid indices) failed. Values as index.csv
# keeps them (12 digits), the axes exact.
make_index() {
  "$PY" - "$@" <<'PY'
import itertools, json, os, sys
out, speeds, steps, slopes = sys.argv[1], *(json.loads(a) for a in sys.argv[2:5])
failed = {int(a) for a in sys.argv[5:]}
os.makedirs(out, exist_ok=True)
points = []
for k, (v, L, s) in enumerate(itertools.product(speeds, steps, slopes)):
    ok = k not in failed
    points.append({"point": f"v{v:.3f}_L{L:.3f}_s{s:+.3f}", "speed": float(f"{v:.12g}"),
                   "step_length": L, "slope": s, "status": "Solve_Succeeded" if ok else
                   "Maximum_Iterations_Exceeded", "converged": ok,
                   "cost": 10 * v if ok else None,
                   "cost_of_transport": 0.1 + (v - 0.5) ** 2 + L / 10 + s if ok else None,
                   "poly_cost_of_transport": 0.3 + v / 5 + s, "iterations": 12,
                   "solve_time_s": 0.5, "start": "polynomial", "message": "" if ok else "max"})
json.dump({"axes": {"speed": speeds, "step_length": steps, "slope": slopes},
           "points_total": len(points), "points_solved": len(points) - len(failed),
           "points_failed": len(failed), "points": points,
           "last_run": {"points": len(points), "failed": len(failed), "workers": 2,
                        "wall_time_s": 3.0, "points_per_second": len(points) / 3.0}},
          open(f"{out}/index.json", "w"), indent=1)
PY
}

# Edits index.json in place with a Python snippet working on the object `d`.
edit() {
  "$PY" - "$1/index.json" "$2" <<'PY'
import json, sys
path, code = sys.argv[1], sys.argv[2]
d = json.load(open(path))
exec(code)
json.dump(d, open(path, "w"))
PY
}

# (a) 3 speeds x 2 step lengths, point 3 failed: CoT lines and the heat map.
make_index "$TMP/a" "[0.4, 0.6, 0.7]" "[0.3, 0.4]" "[0.0]" 3
plot "$TMP/a"
[[ $RC -eq 0 ]] || fail "(a) exited $RC: $(cat "$TMP/err")"
[[ "$(cat "$TMP/out")" == "$TMP/a/library.png" && -s "$TMP/a/library.png" ]] ||
  fail "(a) output: $(cat "$TMP/out")"
[[ ! -s "$TMP/err" ]] || fail "(a) stderr: $(cat "$TMP/err")"
# Two panels side by side: 2 x 6.4 in at 110 dpi.
"$PY" - "$TMP/a/library.png" <<'PY' || fail "(a) picture size"
import sys
import matplotlib.image as im
h, w = im.imread(sys.argv[1]).shape[:2]
assert (w, h) == (1408, 528), (w, h)
PY

# (a') panel (a) names what the optimum minimised (the first converged point's summary.json),
# so that a torque-squared optimum costing more transport than the polynomial gait reads right;
# "optimal" when no point kept its folder.
mkdir -p "$TMP/a/points/v0.400_L0.300_s+0.000"
echo '{"cost_type": "torque_squared"}' >"$TMP/a/points/v0.400_L0.300_s+0.000/summary.json"
(cd "$ROOT/plots" && "$PY" - "$TMP/a" "$TMP/b_absent" <<'PY') || fail "(a') optimum named"
import sys
import library_plots
d, axes, points = library_plots.read_index(sys.argv[1])
assert library_plots.optimum_name(sys.argv[1], points) == "∫Στ² optimum"
assert library_plots.optimum_name(sys.argv[2], points) == "optimal"
PY

# (b) 2 speeds x 1 step x 3 slopes, one failed: CoT vs speed and vs slope (no heat map).
make_index "$TMP/b" "[0.5, 0.7]" "[0.35]" "[-0.05, 0.0, 0.05]" 4
plot "$TMP/b"
[[ $RC -eq 0 && -s "$TMP/b/library.png" ]] || fail "(b) exited $RC: $(cat "$TMP/err")"
"$PY" -c "import sys, matplotlib.image as im; assert im.imread(sys.argv[1]).shape[1] == 1408" \
  "$TMP/b/library.png" || fail "(b) expected two panels"

# (c) all three panels; a partial index (unfinished points) and a single speed also draw.
make_index "$TMP/c" "[0.4, 0.6]" "[0.3, 0.4]" "[-0.05, 0.05]" 0 7
edit "$TMP/c" "d['points'] = d['points'][:5]"
plot "$TMP/c"
[[ $RC -eq 0 && -s "$TMP/c/library.png" ]] || fail "(c) exited $RC: $(cat "$TMP/err")"
"$PY" -c "import sys, matplotlib.image as im; assert im.imread(sys.argv[1]).shape[1] == 2112" \
  "$TMP/c/library.png" || fail "(c) expected three panels"
make_index "$TMP/c1" "[0.6]" "[0.3]" "[0.0]"
edit "$TMP/c1" "d['points'] = []"
plot "$TMP/c1"
[[ $RC -eq 0 && -s "$TMP/c1/library.png" ]] || fail "(c) empty index exited $RC: $(cat "$TMP/err")"

# (c') a config key as a fourth axis: two points of one speed that differ only in it are two
# points (not one given twice), and the CoT-vs-key panel makes two panels.
make_index "$TMP/k" "[0.5, 0.7]" "[0.35]" "[0.0]"
edit "$TMP/k" "
d['axes']['constraints.friction_margin'] = [0.1, 0.3]
d['points'] = [dict(p, config_values=[m], point=p['point'] + f'_m{m}',
                    cost_of_transport=p['cost_of_transport'] + m)
               for p in d['points'] for m in (0.1, 0.3)]"
plot "$TMP/k"
[[ $RC -eq 0 && -s "$TMP/k/library.png" ]] || fail "(c') exited $RC: $(cat "$TMP/err")"
"$PY" -c "import sys, matplotlib.image as im; assert im.imread(sys.argv[1]).shape[1] == 1408" \
  "$TMP/k/library.png" || fail "(c') expected two panels"
rm "$TMP/k/library.png"
edit "$TMP/k" "d['points'][0]['config_values'] = []"
expect_error "(c') no config value" "$TMP/k" "$TMP/k/index.json: key 'points\[0\].config_values': expected 1 numbers"

# (d) bad input.
expect_error "(d) no folder" "$TMP/nothing" "$TMP/nothing: not a folder"
mkdir -p "$TMP/d0"
expect_error "(d) no index" "$TMP/d0" "$TMP/d0/index.json: cannot read"
printf '{"axes": ' >"$TMP/d0/index.json"
expect_error "(d) torn JSON" "$TMP/d0" "$TMP/d0/index.json: not valid JSON"
printf '[1, 2]' >"$TMP/d0/index.json"
expect_error "(d) not an object" "$TMP/d0" "$TMP/d0/index.json: expected a JSON object"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "del d['axes']['slope']"
expect_error "(d) no slope axis" "$TMP/d" "$TMP/d/index.json: missing key 'axes.slope'"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "d['axes']['speed'] = [0.6, 0.4]"
expect_error "(d) unsorted axis" "$TMP/d" "$TMP/d/index.json: key 'axes.speed': expected increasing"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "d['points'][2]['speed'] = 0.5"
expect_error "(d) off the grid" "$TMP/d" "$TMP/d/index.json: key 'points\[2\].speed': 0.5 is not on the grid"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "d['points'][1]['cost_of_transport'] = 'low'"
expect_error "(d) CoT text" "$TMP/d" "$TMP/d/index.json: key 'points\[1\].cost_of_transport': expected a number or null"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "d['points'][0]['converged'] = 1"
expect_error "(d) converged" "$TMP/d" "$TMP/d/index.json: key 'points\[0\].converged': expected true or false"
make_index "$TMP/d" "[0.4, 0.6]" "[0.3, 0.4]" "[0.0]"
edit "$TMP/d" "d['points'].append(dict(d['points'][0]))"
expect_error "(d) twice" "$TMP/d" "$TMP/d/index.json: key 'points\[4\]': point v0.400_L0.300_s\+0.000 given twice"
# Usage text and exit 2 without a folder argument.
"$PY" "$SCRIPT" >/dev/null 2>"$TMP/err"
[[ $? -eq 2 ]] && grep -q "Usage: library_plots.py LIBRARY_DIR" "$TMP/err" || fail "(d) usage"

echo "library_plots_test: all checks passed"
