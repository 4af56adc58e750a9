#!/usr/bin/env bash
# Checks of plots/compare_gaits.py on two small made-up gait result folders (five links; A with
# DSP rows, B without): the markdown table (a known row, B/A left empty for a tiny A and for
# differing signs), the OUT.md mode, the OUT_DIR mode (the files it prints and writes), and
# "error: <file>: ..." with exit code 65 (EX_DATAERR) for a missing folder, file, column and key.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: compare_plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
SCRIPT="$ROOT/plots/compare_gaits.py"
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"

# Runs compare_gaits.py with the given arguments, keeping stdout, stderr and the exit code.
compare() {
  "$PY" "$SCRIPT" "$@" >"$TMP/out" 2>"$TMP/err"
  RC=$?
}

# expect_error NAME PATTERN ARGS...: exit 65 and one stderr line "error: ..." matching PATTERN.
expect_error() {
  local name=$1 pattern=$2
  shift 2
  compare "$@"
  [[ $RC -eq 65 ]] || fail "$name: exit $RC, expected 65 (stderr: $(cat "$TMP/err"))"
  [[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "$name: expected one stderr line: $(cat "$TMP/err")"
  grep -Eq "^error: $pattern" "$TMP/err" || fail "$name: stderr '$(cat "$TMP/err")' !~ '$pattern'"
}

# Made-up result folder: 5 links, ROWS samples 0.1 s apart, the last DSP_ROWS of them DSP.
# Values are smooth but made up (not a dynamically consistent gait).
make_gait() {
  "$PY" - "$@" <<'PY'
import csv, json, math, os, sys
out, rows, dsp_rows, energy, impact, margin = (sys.argv[1], int(sys.argv[2]), int(sys.argv[3]),
                                               float(sys.argv[4]), float(sys.argv[5]),
                                               float(sys.argv[6]))
os.makedirs(out)
n = 5
header = (["t", "phase"] + [f"{p}theta{i}" for p in ("", "d", "dd") for i in range(1, n + 1)]
          + [f"{p}q{j}" for p in ("", "d") for j in range(n)] + [f"tau{j}" for j in range(n)]
          + ["fb_x", "fb_y", "fe_x", "fe_y", "zmp_x", "hip_x", "hip_y", "swing_x", "swing_y",
             "com_x", "com_y"])
with open(f"{out}/trajectory.csv", "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(header)
    for k in range(rows):
        t = 0.1 * k
        dsp = k >= rows - dsp_rows
        th = [0.3 * t - 0.1, 0.2 * t - 0.3, 0.05, math.pi - 0.2 * t, math.pi + 0.1 * t]
        row = [round(t, 6), "DSP" if dsp else "SSP"] + th + [0.3, 0.2, 0.0, -0.2, 0.1]
        row += [0.0] * n + [0.0] * (2 * n) + [10 * math.sin(j + 3 * t) for j in range(n)]
        row += [5.0, 150.0 if dsp else 300.0, -4.0 if dsp else 0.0, 150.0 if dsp else 0.0,
                0.02 + 0.1 * t, 0.1 * t, 0.6, 0.35 if dsp else 0.5 * t - 0.2, 0.0, 0.1 * t, 0.5]
        w.writerow(row)
summary = {"robot": "made_up", "status": "designed", "step_length": 0.35,
           "duration": 0.1 * (rows - 1), "energy_J": energy, "cost_of_transport": 0.1,
           "impact_energy_loss_J": impact, "min_zmp_margin": margin, "friction": 0.6,
           "peak_torque": [10.0, 20.0, 0.0, 5.0, 8.0],
           "joints": [{"name": x} for x in ("stance_ankle", "stance_knee", "stance_hip",
                                             "swing_hip", "swing_knee")],
           "links": [{"name": x, "length": 0.3, "continues": x != "torso"}
                     for x in ("stance_shank", "stance_thigh", "torso", "swing_thigh",
                               "swing_shank")]}
with open(f"{out}/summary.json", "w") as f:
    json.dump(summary, f, indent=2)
PY
  [[ $? -eq 0 ]] || fail "could not make the made-up folder $1"
}

A="$TMP/gait_a"
B="$TMP/gait_b"
make_gait "$A" 8 2 10.0 -4e-16 -0.1  # with DSP rows
make_gait "$B" 7 0 25.0 -5e-15 0.05  # without DSP rows

# (a) Table only: a known row, B/A empty for a tiny A and for differing signs, a peak torque row
# with A = 0 empty too.
compare "$A" "$B"
[[ $RC -eq 0 && ! -s "$TMP/err" ]] || fail "(a) exit $RC: $(cat "$TMP/err")"
grep -qxF "| energy (absolute work) [J] | 10.00 | 25.00 | 2.50 |" "$TMP/out" ||
  fail "(a) energy row: $(cat "$TMP/out")"
grep -qxF "| impact energy loss [J] | -4e-16 | -5e-15 |  |" "$TMP/out" ||
  fail "(a) tiny A must leave B/A empty: $(grep impact "$TMP/out")"
grep -qxF "| min ZMP margin [m] | -0.1000 | 0.0500 |  |" "$TMP/out" ||
  fail "(a) differing signs must leave B/A empty: $(grep ZMP "$TMP/out")"
grep -qxF "| peak torque stance_hip [N m] | 0.0 | 0.0 |  |" "$TMP/out" ||
  fail "(a) zero A must leave B/A empty: $(grep stance_hip "$TMP/out")"
grep -qxF "| quantity | A: $A | B: $B | B/A |" "$TMP/out" || fail "(a) header: $(head -1 "$TMP/out")"
cp "$TMP/out" "$TMP/table.md"

# (b) OUT.md: prints the same table and writes it there; no pictures.
compare "$A" "$B" "$TMP/cmp.md"
[[ $RC -eq 0 ]] || fail "(b) exit $RC: $(cat "$TMP/err")"
cmp -s "$TMP/out" "$TMP/table.md" || fail "(b) printed table differs from (a)"
cmp -s "$TMP/cmp.md" "$TMP/table.md" || fail "(b) written table differs from (a)"
[[ -z $(find "$TMP" -maxdepth 1 -name '*.png') ]] || fail "(b) pictures written in md mode"

# (c) OUT_DIR (new, no .md suffix): created; one printed line per file, each file written.
PICTURES="angles_overlay.png torques_overlay.png forces_overlay.png zmp_overlay.png comparison.png"
check_dir() {
  local dir=$1 name=$2 expected f
  expected=$(printf '%s\n' "$dir/comparison.md" $(for f in $PICTURES; do echo "$dir/$f"; done))
  [[ $RC -eq 0 ]] || fail "$name: exit $RC: $(cat "$TMP/err")"
  [[ "$(cat "$TMP/out")" == "$expected" ]] || fail "$name: printed '$(cat "$TMP/out")'"
  cmp -s "$dir/comparison.md" "$TMP/table.md" || fail "$name: comparison.md differs from (a)"
  for f in $PICTURES; do
    [[ $(head -c 8 "$dir/$f" | od -An -tx1 | tr -d ' \n') == 89504e470d0a1a0a ]] ||
      fail "$name: $f is not a PNG"
    [[ $(stat -c %s "$dir/$f") -gt 20000 ]] || fail "$name: $f suspiciously small"
  done
}
compare "$A" "$B" "$TMP/report"
check_dir "$TMP/report" "(c)"

# (d) An existing folder is OUT_DIR even with an .md name.
mkdir "$TMP/existing.md"
compare "$A" "$B" "$TMP/existing.md"
check_dir "$TMP/existing.md" "(d)"

# (e) Errors: message names the file and the problem; nothing is written.
expect_error "(e) missing folder" "$TMP/nope: no such folder$" "$TMP/nope" "$B"
cp -r "$B" "$TMP/no_traj" && rm "$TMP/no_traj/trajectory.csv"
expect_error "(e) missing file" "$TMP/no_traj/trajectory.csv: cannot read the trajectory" \
  "$A" "$TMP/no_traj" "$TMP/out_e1"
[[ ! -e "$TMP/out_e1" ]] || fail "(e) missing file: output folder created"
cp -r "$A" "$TMP/no_zmp"
"$PY" - "$TMP/no_zmp/trajectory.csv" <<'PY'
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
i = rows[0].index("zmp_x")
with open(sys.argv[1], "w", newline="") as f:
    csv.writer(f, lineterminator="\n").writerows([r[:i] + r[i + 1:] for r in rows])
PY
expect_error "(e) missing column" "$TMP/no_zmp/trajectory.csv: missing column 'zmp_x'$" \
  "$TMP/no_zmp" "$B" "$TMP/out_e2"
[[ ! -e "$TMP/out_e2" ]] || fail "(e) missing column: output folder created"
cp -r "$A" "$TMP/no_status"
"$PY" -c "import json, sys; p = sys.argv[1]; s = json.load(open(p)); del s['status']
json.dump(s, open(p, 'w'))" "$TMP/no_status/summary.json"
expect_error "(e) missing key" "$TMP/no_status/summary.json: missing key 'status'$" \
  "$A" "$TMP/no_status" "$TMP/out_e3.md"
[[ ! -e "$TMP/out_e3.md" ]] || fail "(e) missing key: table written"

# (f) Usage text and exit 1 with the wrong number of arguments.
compare "$A"
[[ $RC -eq 1 ]] && grep -q "^Usage: compare_gaits.py A_DIR B_DIR" "$TMP/err" || fail "(f) usage"

# (g) The ZMP panel shades the stance foot from heel to toe for each gait whose summary names a foot
# (A: 5 cm heel, 15 cm toe), and none for point tips (B names none, and no robot file is
# "made_up"); a malformed foot names its key.
cp -r "$A" "$TMP/footed"
"$PY" -c "import json, sys; p = sys.argv[1]; s = json.load(open(p))
s['foot'] = {'heel': 0.05, 'toe': 0.15}; json.dump(s, open(p, 'w'))" "$TMP/footed/summary.json"
(cd "$ROOT/plots" && "$PY" - "$TMP/footed" "$B" <<'PY') || fail "(g) foot band"
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import compare_gaits
a, b = compare_gaits.Gait(sys.argv[1], "A", "-"), compare_gaits.Gait(sys.argv[2], "B", "--")
assert a.foot == (0.05, 0.15) and b.foot is None, (a.foot, b.foot)
fig, ax = plt.subplots()
compare_gaits.draw_zmp(ax, [a, b])
feet = [p.get_xy()[:, 1] for p in ax.patches if p.get_gid() == "foot"]
assert len(feet) == 1 and (feet[0].min(), feet[0].max()) == (-0.05, 0.15), feet
# A's double support (B has none) from B's heel to E's toe, as zmp.png draws it: it stopped at
# the tips, 5 cm short behind and 15 cm ahead.
dsp = [c for c in ax.collections if c.get_gid() == "dsp_support"]
assert len(dsp) == 1, dsp
y = dsp[0].get_paths()[0].vertices[:, 1]
assert abs(y.min() + 0.05) < 1e-12 and abs(y.max() - (a.s["step_length"] + 0.15)) < 1e-12, (y.min(), y.max())
PY
"$PY" -c "import json, sys; p = sys.argv[1]; s = json.load(open(p))
s['foot'] = {'heel': 'long', 'toe': 0.15}; json.dump(s, open(p, 'w'))" "$TMP/footed/summary.json"
expect_error "(g) malformed foot" "$TMP/footed/summary.json: key 'foot.heel'" "$TMP/footed" "$B" \
  "$TMP/out_g"

# (g2) Link angles as overview.png draws them, each from its foot toward the hip: the swing
# thigh (theta4 = pi - 0.2 t) as -0.2 t and the swing shank (theta5 = pi + 0.1 t) as 0.1 t, not
# near 180 degrees; the stance links and the torso as they are.
(cd "$ROOT/plots" && "$PY" - "$A" <<'PY') || fail "(g2) angle convention"
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import compare_gaits
a = compare_gaits.Gait(sys.argv[1], "A", "-")
fig, ax = plt.subplots()
compare_gaits.draw_all_angles(ax, [a])
curves = [line.get_ydata() for line in ax.get_lines() if len(line.get_xdata()) == len(a.t)]
assert len(curves) == 5, len(curves)
expected = [0.3 * a.t - 0.1, 0.2 * a.t - 0.3, 0.05 + 0 * a.t, -0.2 * a.t, 0.1 * a.t]
for k, (y, e) in enumerate(zip(curves, expected)):
    assert np.allclose(y, np.degrees(e), atol=1e-9), (k, y[:3], np.degrees(e)[:3])
assert "foot toward hip" in ax.get_title(), ax.get_title()
PY

# (h) Gaits of other robots: peak torques matched by joint name (B's three joints against A's
# five, a dash where a gait has no such joint), the robots named; an unbounded friction ratio
# (summary.json's null: a tip pulls on the ground) is shown as inf, not its row dropped.
cp -r "$A" "$TMP/with_mu" && cp -r "$B" "$TMP/three"
"$PY" - "$TMP/with_mu/summary.json" "$TMP/three/summary.json" <<'PY'
import json, sys
a, b = (json.load(open(p)) for p in sys.argv[1:])
a["max_friction_ratio"] = 0.3
b.update(robot="three_joints", max_friction_ratio=None, peak_torque=[1.0, 2.0, 3.0],
         joints=[{"name": x} for x in ("stance_ankle", "stance_hip", "swing_hip")])
for p, s in zip(sys.argv[1:], (a, b)):
    json.dump(s, open(p, "w"))
PY
compare "$TMP/with_mu" "$TMP/three"
[[ $RC -eq 0 ]] || fail "(h) exit $RC: $(cat "$TMP/err")"
for line in "| robot | made_up | three_joints |  |" \
  "| max friction ratio abs(Fx)/Fy | 0.300 | inf |  |" \
  "| peak torque stance_knee [N m] | 20.0 | — |  |" \
  "| peak torque stance_hip [N m] | 0.0 | 2.0 |  |" \
  "| peak torque swing_hip [N m] | 5.0 | 3.0 | 0.60 |" \
  "| peak torque swing_knee [N m] | 8.0 | — |  |"; do
  grep -qxF "$line" "$TMP/out" || fail "(h) no row '$line' in: $(cat "$TMP/out")"
done

echo "compare_plots_test: all checks passed"
