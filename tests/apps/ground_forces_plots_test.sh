#!/usr/bin/env bash
# plots/ground_forces_chart.py on two made-up walks: a smooth force and one that chatters
# with a spike; the table's figures (peak force, peak force rate, reversals per second) against
# hand counts, the picture, and "error: <file>: ..." with exit code 1 for a walk without its log.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: ground_forces_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"
chart="$ROOT/plots/ground_forces_chart.py"
# walk NAME KIND: 1 s at 1 kHz; B carries 300 N, E from 0.5 s on: smooth (a ramp to 100 N over
# 100 ms) or chattering (a 500 N spike, then 100 N +- 20 N alternating every sample for 10 ms).
walk() {
  mkdir -p "$TMP/$1"
  printf '{"ground_file": "configs/grounds/%s.yaml", "robot": "five"}\n' "$1" >"$TMP/$1/summary.json"
  "$PY" - "$TMP/$1/walk.csv" "$2" <<'PY'
import sys
path, kind = sys.argv[1:]
with open(path, "w") as f:
    f.write("t,step,fb_y,fe_y\n")
    for k in range(1001):
        t = k / 1000
        fe = 0.0
        if kind == "smooth" and t >= 0.5:
            fe = min(100.0, 1000.0 * (t - 0.5))
        if kind == "chatter" and t >= 0.5:
            fe = 500.0 if k == 500 else (100.0 + (20.0 if k % 2 else -20.0) if k <= 510 else 100.0)
        f.write(f"{t:.3f},1,300,{fe}\n")
PY
}
walk smooth smooth
walk chatter chatter
"$PY" "$chart" "$TMP/out" "$TMP/smooth" "$TMP/chatter" >"$TMP/printed" 2>"$TMP/err" ||
  fail "exit $? on good walks: $(cat "$TMP/err")"
grep -qx "$TMP/out/ground_forces.png" "$TMP/printed" || fail "png not printed: $(cat "$TMP/printed")"
"$PY" - "$TMP/out/ground_forces.md" <<'PY' || fail "table: $(cat "$TMP/out/ground_forces.md")"
import sys
rows = {r.split("|")[1].strip(): [c.strip() for c in r.split("|")[2:5]]
        for r in open(sys.argv[1]).read().splitlines()[2:]}
# Smooth: 300 N peak (B), 1 kN/s ramp, no reversals of at least 3 N.
assert rows["smooth"] == ["300", "1.0", "0.0"], rows["smooth"]
# Chatter: 500 N spike (0 -> 500 N in 1 ms: 500 kN/s); the increments +500, -380, -40, then
# +40 and -40 alternating to 80 N at 10 ms and +20 back to 100 N change sign 10 times in 1 s.
assert rows["chatter"][0] == "500" and rows["chatter"][1] == "500.0", rows["chatter"]
assert rows["chatter"][2] == "10.0", rows["chatter"]
PY
rm "$TMP/chatter/walk.csv"
"$PY" "$chart" "$TMP/out2" "$TMP/smooth" "$TMP/chatter" >/dev/null 2>"$TMP/err"
[[ $? -eq 1 ]] && grep -q "^error: $TMP/chatter/walk.csv: cannot read" "$TMP/err" ||
  fail "missing walk log: $(cat "$TMP/err")"
# The first touchdown's window: E loaded at the walk's start (both feet down) is not a
# touchdown; the window starts at E's rise after a sample without load and follows the same
# foot as B after the step change renames the tips.
PYTHONPATH="$ROOT/plots" "$PY" - <<'PY' || fail "touchdown window"
import numpy as np
import ground_forces_chart as chart
t = np.arange(0, 1.0, 0.001)
step = np.where(t < 0.55, 1, 2)
e = np.where(t < 0.003, 200.0, 0.0) + np.where((t >= 0.5) & (t < 0.55), 60.0, 0.0)
b = np.where(t < 0.55, 300.0, 0.0) + np.where(t >= 0.55, 250.0, 0.0)
ms, force = chart.touchdown_window(t, step, b, e)
assert abs(ms[np.argmax(force > 1.0)]) < 1e-9, ms[np.argmax(force > 1.0)]  # touchdown at 0.5 s
assert ms[0] < -39 and ms[-1] > 79, (ms[0], ms[-1])
assert np.all(force[(ms > 0) & (ms < 49)] == 60.0) and np.all(force[ms > 51] == 250.0)
# A rigid ground: E never carries load, the step change is the touchdown.
ms, force = chart.touchdown_window(t, step, b, np.zeros_like(t))
assert abs(ms[np.argmax(force > 1.0)]) < 1e-9 and force[-1] == 250.0
PY
echo "ground_forces_plots_test: all checks passed"
