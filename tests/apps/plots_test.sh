#!/usr/bin/env bash
# Checks of plots/walk_plots.py, stability_plots.py and gait_plots.py on small made-up
# result folders: the pictures they print, and "error: <file>: ..." with exit code 1 for broken
# inputs. Also checks that gait_plots.py, compare_gaits.py (exit 65, EX_DATAERR) and impact_map.py
# report broken inputs through plot_io the same way.
# Needs Debian's python3-matplotlib; skips (ctest: skipped) without it.
# Usage: plots_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
PLOTS="$ROOT/plots"
"$PY" -c "import matplotlib, numpy" 2>/dev/null || skip "no matplotlib/numpy"

# Runs a plotting script on a folder, keeping stdout, stderr and the exit code.
plot() {
  "$PY" "$PLOTS/$1" "$2" >"$TMP/out" 2>"$TMP/err"
  RC=$?
}

# expect_error NAME SCRIPT DIR PATTERN: exit 1 and one stderr line "error: ..." matching PATTERN.
expect_error() {
  plot "$2" "$3"
  [[ $RC -eq 1 ]] || fail "$1: exit $RC, expected 1 (stderr: $(cat "$TMP/err"))"
  [[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "$1: expected one stderr line: $(cat "$TMP/err")"
  grep -Eq "^error: $4" "$TMP/err" || fail "$1: stderr '$(cat "$TMP/err")' !~ '$4'"
}

# Made-up walk folder: N-link robot (5: stance shank, stance thigh, torso, swing thigh, swing
# shank; torso at the hip), STEPS steps of 0.7 s (0.6 s SSP then DSP), standing still in place
# but stepping forward; FELL=1 ends in the SSP of the last step.
make_walk() {
  "$PY" - "$1" "${2:-2}" "${3:-0}" <<'PY'
import csv, json, math, os, sys
out, steps, fell = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "1"
os.makedirs(out, exist_ok=True)
n, L, lengths, cont = 5, 0.35, [0.332, 0.302, 0.486, 0.302, 0.332], [1, 1, 0, 1, 1]
def pose(s):  # s in [0, 1] through the step
    a = 0.5 * (s - 0.5)
    return [a - 0.05, a + 0.05, 0.1, math.pi - a + 0.05, math.pi - a - 0.05]
def ends(th, x0):
    p, out_ = [x0, 0.0], []
    for i in range(n):
        q = [p[0] + lengths[i] * math.sin(th[i]), p[1] + lengths[i] * math.cos(th[i])]
        out_.append((p, q))
        if cont[i]:
            p = q
    return out_
walk, stick, rows = [], [], []
for k in range(steps):
    last = fell and k == steps - 1
    for j in range(71 if not last else 40):
        tl = j / 100
        t = 0.7 * k + tl
        ref = pose(min(tl / 0.7, 1))
        err = [0.02 * math.exp(-3 * t) * math.sin(i + 9 * t) + (tl ** 2 if last else 0)
               for i in range(n)]
        th = [r + e for r, e in zip(ref, err)]
        seg = ends(th, k * L)
        hip = seg[1][1]
        dsp = tl > 0.6
        row = [t, k + 1, "DSP" if dsp else "SSP", k * L, 0.0] + th + ref
        row += [10 * e for e in err] + [0.0] * n
        row += [-20 + 40 * tl, 250.0, 15.0 if dsp else 0.0, 120.0 if dsp else 0.0] + hip
        walk.append(row)
        if j % 5 == 0:
            stick += [[t, k + 1, i + 1, *p, *q] for i, (p, q) in enumerate(seg)]
    rows.append([k + 1, 0 if last else 1, "" if last else "double", 0.6, 0.1, L, 0.02,
                 "fell: hip below 0.4 m, at t = 1.8 s" if last else ""])
def write(name, header, data):
    with open(f"{out}/{name}", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(header)
        w.writerows(data)
write("walk.csv", ["t", "step", "phase", "stance_x", "stance_y"]
      + [f"theta{i}" for i in range(1, n + 1)] + [f"theta_ref{i}" for i in range(1, n + 1)]
      + [f"tau{j}" for j in range(n)] + [f"tau_ref{j}" for j in range(n)]
      + ["fb_x", "fb_y", "fe_x", "fe_y", "hip_x", "hip_y"], walk)
write("stick.csv", ["t", "step", "link", "x0", "y0", "x1", "y1"], stick)
write("steps.csv", ["step", "ok", "impact", "ssp_duration", "dsp_duration", "advance",
                    "max_tracking_error", "failure"], rows)
json.dump({"robot": "five_link", "reference": "ref", "controller": "computed_torque",
           "ground": "rigid", "steps_requested": steps, "friction": 0.6,
           "steps_completed": steps - fell, "fell": fell, "failure": rows[-1][-1],
           "max_tracking_error": 0.3 if fell else 0.02,
           "poincare_max_multiplier": None if fell else 0.5,
           "poincare_multipliers": None if fell else [[0.5, 0], [0.1, 0.2], [0.1, -0.2]],
           **({"poincare_failure": "no periodic orbit found"} if fell else {})},
          open(f"{out}/summary.json", "w"))
PY
}

# Made-up stability folder: sweeps of friction (with multipliers) and push (none computed).
make_stability() {
  mkdir -p "$1"
  cat >"$1/sweep_friction.csv" <<'CSV'
value,steps_completed,steps_requested,fell,failure,max_tracking_error,max_multiplier,mean_advance,wall_time_s
0.2,3,10,1,"slip at step 4, |f_t|/f_n > mu",0.5,,0.3,0.2
0.4,10,10,0,,0.03,0.62,0.35,0.4
0.6,10,10,0,,0.02,0.55,0.35,0.4
CSV
  cat >"$1/sweep_push.csv" <<'CSV'
value,steps_completed,steps_requested,fell,failure,max_tracking_error,max_multiplier,mean_advance,wall_time_s
-10,0,10,1,fell,0.9,,,0.1
0,10,10,0,,0.02,,0.35,0.4
10,10,10,0,,0.05,,0.35,0.4
CSV
  cat >"$1/summary.json" <<'JSON'
{"robot": "five_link", "controller": "computed_torque", "sweeps": {
  "friction": {"unit": "", "values": 3, "walks_from": 0.4, "walks_to": 0.6, "nominal": 0.6},
  "push": {"unit": "N s", "values": 3, "walks_from": 0, "walks_to": 10, "nominal": 0}}}
JSON
}

# Edits a file in place with a Python snippet working on `text`.
edit() {
  "$PY" - "$1" "$2" <<'PY'
import sys
path, code = sys.argv[1], sys.argv[2]
text = open(path).read()
exec(code)
open(path, "w").write(text)
PY
}

fresh() {  # fresh KIND NAME: a new copy of a good folder of that kind in $TMP/NAME
  rm -rf "${TMP:?}/$2"
  cp -r "$TMP/good_$1" "$TMP/$2"
}

# (a) a 2-step walk: six pictures, one printed line each, nothing on stderr.
make_walk "$TMP/walk" 2 0
plot walk_plots.py "$TMP/walk"
[[ $RC -eq 0 ]] || fail "(a) walk_plots.py exited $RC: $(cat "$TMP/err")"
for name in walk_stick tracking torques forces walk_overview poincare; do
  grep -qx "$TMP/walk/$name.png" "$TMP/out" || fail "(a) $name.png not printed"
  [[ -s "$TMP/walk/$name.png" ]] || fail "(a) $name.png not written"
done
[[ $(wc -l <"$TMP/out") -eq 6 ]] || fail "(a) expected 6 lines: $(cat "$TMP/out")"
[[ ! -s "$TMP/err" ]] || fail "(a) stderr: $(cat "$TMP/err")"

# A picture's temporary file left by a run killed while it drew is removed by the next write of
# that picture, and one of a running process is not.
mkdir -p "$TMP/leftovers"
(cd "$PLOTS" && "$PY" - "$TMP/leftovers" <<'PY') || fail "leftover temporary pictures"
import os, sys
import plot_style
folder = sys.argv[1]
dead = os.path.join(folder, "x.png.tmp-4194305-abc.png")  # above Linux's largest pid
alive = os.path.join(folder, f"x.png.tmp-{os.getppid()}-def.png")
for f in (dead, alive):
    open(f, "w").close()
with plot_style.replacing(os.path.join(folder, "x.png")) as tmp:
    open(tmp, "w").write("picture")
assert not os.path.exists(dead) and os.path.exists(alive), os.listdir(folder)
assert open(os.path.join(folder, "x.png")).read() == "picture"
PY

# (a') the stick diagram stands each step's stance tip on the foot of the walk's summary.
cp -r "$TMP/walk" "$TMP/footed_walk"
(cd "$PLOTS" && "$PY" - "$TMP/footed_walk" <<'PY') || fail "(a') feet of the stick diagram"
import json, sys
import plot_style
import walk_plots
path = sys.argv[1] + "/summary.json"
s = json.load(open(path))
s["foot"] = {"heel": 0.05, "toe": 0.15}
json.dump(s, open(path, "w"))
w = walk_plots.Walk(sys.argv[1])
assert w.foot == (0.05, 0.15), w.foot
fig, ax = plot_style.pyplot().subplots()
walk_plots.draw_walk_stick(ax, w, colorbar=False)
feet = [line.get_xdata() for line in ax.lines if line.get_linewidth() == 2.5 and
        len(line.get_xdata()) == 2]
starts = sorted(set(w.col["step"]))
assert len(feet) == len(starts), (len(feet), starts)
assert all(abs((x[1] - x[0]) - 0.2) < 1e-12 for x in feet), feet
PY

# (a'') the time panels' legends sit below the axes (loc="best" sat on the curves) and at most
# MAX_STEP_LABELS step starts are labelled, above the axes.
(cd "$PLOTS" && "$PY" - "$TMP/walk" <<'PY') || fail "(a'') legends below, few step labels"
import sys
import plot_style
import walk_plots
w = walk_plots.Walk(sys.argv[1])
for draw in (walk_plots.draw_tracking, walk_plots.draw_all_torques,
             walk_plots.draw_normal_forces, walk_plots.draw_friction):
    fig, ax = plot_style.pyplot().subplots()
    draw(ax, w)
    fig.canvas.draw()
    box = ax.get_legend().get_window_extent().transformed(ax.transAxes.inverted())
    assert box.y1 < 0, (draw.__name__, box)
    if draw is walk_plots.draw_tracking:
        labels = [t for t in ax.texts if t.get_text().startswith("step ")]
        assert labels and all(t.xy[1] == 1 for t in labels), [t.xy for t in labels]
starts = [(k, 0.1 * k) for k in range(2, 22)]
picked = walk_plots.labelled_steps(starts)
assert len(picked) <= walk_plots.MAX_STEP_LABELS and picked[0] == (2, 0.2), picked
PY

# (b) a walk that fell: no Poincare multipliers, so five pictures and a note on stderr.
make_walk "$TMP/fell" 3 1
plot walk_plots.py "$TMP/fell"
[[ $RC -eq 0 ]] || fail "(b) walk_plots.py exited $RC: $(cat "$TMP/err")"
[[ $(wc -l <"$TMP/out") -eq 5 ]] || fail "(b) expected 5 lines: $(cat "$TMP/out")"
grep -q "poincare.png skipped: no periodic orbit found" "$TMP/err" ||
  fail "(b) no skip note: $(cat "$TMP/err")"
[[ ! -e "$TMP/fell/poincare.png" ]] || fail "(b) poincare.png written"

# (b') a walk without the map (--no-poincare): no multipliers and no failure, so no note.
"$PY" - "$TMP/fell/summary.json" "$TMP/unasked/summary.json" <<'PY'
import json, os, shutil, sys
shutil.copytree(os.path.dirname(sys.argv[1]), os.path.dirname(sys.argv[2]))
s = json.load(open(sys.argv[2]))
s.pop("poincare_failure")
json.dump(s, open(sys.argv[2], "w"))
PY
rm -f "$TMP/unasked/"*.png
plot walk_plots.py "$TMP/unasked"
[[ $RC -eq 0 ]] && ! grep -q "poincare.png skipped" "$TMP/err" || fail "(b') $RC $(cat "$TMP/err")"

# (c) stability sweeps: one picture.
make_stability "$TMP/stab"
plot stability_plots.py "$TMP/stab"
[[ $RC -eq 0 ]] || fail "(c) stability_plots.py exited $RC: $(cat "$TMP/err")"
[[ "$(cat "$TMP/out")" == "$TMP/stab/stability.png" && -s "$TMP/stab/stability.png" ]] ||
  fail "(c) output: $(cat "$TMP/out")"

# (c2) the words and axes of a sweep: a geometric sweep (0.1, 0.3, 0.9) on a log axis, a linear
# one not; no walking interval around the nominal value reads "falls at the nominal ..." when
# other values walked and "falls at every tested value" when none did; the title names the gait.
cp -r "$TMP/stab" "$TMP/stab2"
edit "$TMP/stab2/sweep_friction.csv" "text = text.replace('\n0.2,', '\n0.1,').replace('\n0.4,', '\n0.3,').replace('\n0.6,', '\n0.9,')"
edit "$TMP/stab2/summary.json" "import json; d = json.loads(text); d['reference'] = 'results/gait_x'; d['sweeps']['push'].update(walks_from=None, walks_to=None); d['sweeps']['friction'].update(walks_from=None, walks_to=None, nominal=0.1); text = json.dumps(d)"
edit "$TMP/stab2/sweep_push.csv" "text = text.replace('0,10,10,0,,', '0,2,10,1,fell,')"
(cd "$PLOTS" && "$PY" - "$TMP/stab2" <<'PY') || fail "(c2) sweep words and axes"
import sys
import numpy as np
import stability_plots as sp
s, (friction, push) = sp.read_sweeps(sys.argv[1])
assert friction.log_spaced() and not push.log_spaced()
assert friction.interval_text() == "falls at the nominal 0.1; walks at 2 of 3 values (0.3 .. 0.9)", friction.interval_text()
assert push.interval_text() == "falls at every tested value (3 values)", push.interval_text()
# A sweep that walks again past the values it fell at says so (its title said "walks only at
# the nominal value 0" over green walks at +0.8 .. +1).
friction.walks, friction.nominal = (0.3, 0.3), 0.3
friction.walked = np.array([True, True, True])
assert friction.interval_text() == "walks only at the nominal value 0.3; beyond the falls it walks at 2 more (0.1 .. 0.9)", friction.interval_text()
assert sp.headline(s).startswith("Stability sweeps: gait gait_x, computed_torque controller"), sp.headline(s)
# Two sweeps of one gait at other gains or another CoP rule do not share a title.
s2 = dict(s, gain_scale=0.3, contact_rules={"cop_limit": "fail"})
assert "computed_torque controller at 0.3 x its gains, CoP limit: fail" in sp.headline(s2), sp.headline(s2)
assert " x its gains" not in sp.headline(dict(s, gain_scale=1.0)), sp.headline(s)
# summary.json's `geometric` decides the axis, also where the nominal inserted breaks the ratio
# (a pad's 3e5 in stiffness=1e5:1e7:3, drawn linear by the ratio test).
friction.value = np.array([1e5, 3e5, 1e6, 1e7])
assert not friction.log_spaced()  # no `geometric`: by the ratio
friction.geometric = True
assert friction.log_spaced()
friction.geometric, friction.value = False, np.array([0.1, 0.3, 0.9])
assert not friction.log_spaced()
PY
plot stability_plots.py "$TMP/stab2"
[[ $RC -eq 0 ]] || fail "(c2) stability_plots.py exited $RC: $(cat "$TMP/err")"
# (c2'') a model error is a fraction, drawn and worded in percent as the maps give it: the same
# sweep read as mass_error (its values 0.1, 0.3, 0.9).
cp -r "$TMP/stab2" "$TMP/stab3"
mv "$TMP/stab3/sweep_friction.csv" "$TMP/stab3/sweep_mass_error.csv"
edit "$TMP/stab3/summary.json" "import json; d = json.loads(text); d['sweeps']['mass_error'] = d['sweeps'].pop('friction'); text = json.dumps(d)"
(cd "$PLOTS" && "$PY" - "$TMP/stab3" <<'PY') || fail "(c2'') a model error's sweep in percent"
import sys
import stability_plots as sp
s, sweeps = sp.read_sweeps(sys.argv[1])
mass = next(sw for sw in sweeps if sw.name == "mass_error")
push = next(sw for sw in sweeps if sw.name == "push")
assert mass.label() == "mass error [%]" and push.label() == "push [N s]", (mass.label(), push.label())
assert mass.interval_text() == "falls at the nominal 10 %; walks at 2 of 3 values (30 .. 90 %)", mass.interval_text()
fig = sp.stability_figure(s, [mass])
assert fig.axes[0].xaxis.get_major_formatter()(0.05, 0) == "5"
assert fig.axes[0].get_xlabel().startswith("mass error [%]"), fig.axes[0].get_xlabel()
PY
# (c2') a long headline over one sweep is wrapped inside the figure (it ran off both sides),
# above the panel's title; every word is kept.
(cd "$PLOTS" && "$PY" - "$TMP/stab2" <<'PY') || fail "(c2') the title of one sweep"
import sys
import stability_plots as sp
s, (friction, push) = sp.read_sweeps(sys.argv[1])
s = dict(s, controller="mu_sliding_mode", contact_rules={"cop_limit": "saturate"},
         robot="mu2004_five_link", ground="rigid", steps_requested=20,
         reference="results/a_gait_with_a_long_name")
fig = sp.stability_figure(s, [push])
fig.canvas.draw()
renderer = fig.canvas.get_renderer()
title = fig._suptitle.get_window_extent(renderer)
assert 0 <= title.x0 and title.x1 <= fig.bbox.width and title.y1 <= fig.bbox.height, title
assert title.y0 > fig.axes[0].title.get_window_extent(renderer).y1, "the title overlaps the panel"
assert fig._suptitle.get_text().split() == sp.headline(s).split(), fig._suptitle.get_text()
PY

# (c3) a 2-D map alone: map_<a>_<b>.png and no stability.png; the failure cause drops the step;
# a grid of another size than summary.json's is refused.
mkdir -p "$TMP/map"
cat >"$TMP/map/summary.json" <<'JSON'
{"controller": "computed_torque", "steps_requested": 10, "maps": {"push_friction": {
 "a": {"name": "push", "unit": "N s", "values": 2, "nominal": 0},
 "b": {"name": "friction", "unit": "", "values": 3, "nominal": 0.6},
 "largest_rectangle_around_nominal": {"a_from": 0, "a_to": 0, "b_from": 0.4, "b_to": 0.6,
                                      "points": 2}}}}
JSON
cat >"$TMP/map/map_push_friction.csv" <<'CSV'
push,friction,steps_completed,steps_requested,fell,failure,max_tracking_error,max_multiplier,mean_advance,wall_time_s
0,0.2,3,10,1,"step 4: slip: the tip slid 1 cm",0.01,,0.35,0.1
0,0.4,10,10,0,,0.01,,0.35,0.1
0,0.6,10,10,0,,0.01,,0.35,0.1
1,0.2,2,10,1,"step 3: foot rotation: the CoP left [-heel, toe]",0.01,,0.35,0.1
1,0.4,2,10,1,"step 3: foot rotation: the CoP left [-heel, toe]",0.01,,0.35,0.1
1,0.6,10,10,0,,0.01,,0.35,0.1
CSV
plot stability_plots.py "$TMP/map"
[[ $RC -eq 0 ]] || fail "(c3) stability_plots.py exited $RC: $(cat "$TMP/err")"
[[ "$(cat "$TMP/out")" == "$TMP/map/map_push_friction.png" && -s "$TMP/map/map_push_friction.png" &&
  ! -e "$TMP/map/stability.png" ]] || fail "(c3) output: $(cat "$TMP/out")"
(cd "$PLOTS" && "$PY" - "$TMP/map" <<'PY') || fail "(c3) map grid"
import sys, json
import map_plots as mp
s = json.load(open(sys.argv[1] + "/summary.json"))
m = mp.Map(sys.argv[1], "push_friction", s["maps"]["push_friction"])
assert m.steps.tolist() == [[3, 10, 10], [2, 2, 10]], m.steps
assert m.outcome.tolist() == [["slip", mp.WALKED, mp.WALKED],
                              ["foot rotation", "foot rotation", mp.WALKED]], m.outcome
PY
# (c3') an *_error sweep without a unit is a fraction, labelled and ticked in percent; the
# colour bar of steps has whole-step ticks.
(cd "$PLOTS" && "$PY" - "$TMP/map" <<'PY') || fail "(c3') percent axis, whole steps"
import sys, json
import map_plots as mp
s = json.load(open(sys.argv[1] + "/summary.json"))
m = mp.Map(sys.argv[1], "push_friction", s["maps"]["push_friction"])
mass = {"name": "mass_error", "unit": ""}
assert mp.is_fraction(mass) and m.label(mass) == "mass error [%]"
assert not mp.is_fraction(m.b) and m.label(m.a) == "push [N s]"
fig = mp.map_figure(m, "t")
ax = fig.axes[0]
mp.percent_ticks(ax.xaxis)
assert ax.xaxis.get_major_formatter()(0.05, 0) == "5"
bar = fig.axes[-1]  # the colour bar
ticks = [t for t in bar.get_yticks() if 0 <= t <= m.requested]
assert all(float(t).is_integer() for t in ticks), ticks
PY
# (c3'') an uneven axis is drawn as walked: cell edges midway between the values (the nominal 0
# inserted into push=-6:-5:2 made rows -6, -5, 0, drawn evenly over -7.5 .. 1.5), a geometric
# axis (stiffness) on a log scale, also in a summary written before `geometric`; ticks at the
# values; the walking rectangle framed on its cells' edges.
mkdir -p "$TMP/umap"
cat >"$TMP/umap/summary.json" <<'JSON'
{"controller": "computed_torque", "steps_requested": 10, "maps": {"push_stiffness": {
 "a": {"name": "push", "unit": "N s", "values": 3, "nominal": 0, "geometric": false},
 "b": {"name": "stiffness", "unit": "N/m^n", "values": 3, "nominal": 1e7, "geometric": true},
 "largest_rectangle_around_nominal": {"a_from": -5, "a_to": 0, "b_from": 1e6, "b_to": 1e7,
                                      "points": 4}}}}
JSON
"$PY" - "$TMP/umap/map_push_stiffness.csv" <<'PY'
import sys
rows = ["push,stiffness,steps_completed,steps_requested,fell,failure,max_tracking_error,"
        "max_multiplier,mean_advance,wall_time_s"]
for a in (-6, -5, 0):
    for b in (1e5, 1e6, 1e7):
        walks = a > -6 and b > 1e5
        rows.append(f"{a},{b:g},{10 if walks else 2},10,{0 if walks else 1},"
                    f"{'' if walks else 'step 3: slip'},0.01,,0.35,0.1")
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
plot stability_plots.py "$TMP/umap"
[[ $RC -eq 0 && -s "$TMP/umap/map_push_stiffness.png" ]] || fail "(c3'') exited $RC: $(cat "$TMP/err")"
(cd "$PLOTS" && "$PY" - "$TMP/umap" <<'PY') || fail "(c3'') uneven axes"
import sys, json
import numpy as np
import map_plots as mp
s = json.load(open(sys.argv[1] + "/summary.json"))
for old in (False, True):  # with `geometric`, and as written before it
    entry = json.loads(json.dumps(s["maps"]["push_stiffness"]))
    if old:
        for axis in ("a", "b"):
            del entry[axis]["geometric"]
    m = mp.Map(sys.argv[1], "push_stiffness", entry)
    assert np.allclose(m.a_edges, [-6.5, -5.5, -2.5, 2.5]), m.a_edges
    assert np.allclose(np.log10(m.b_edges), [4.5, 5.5, 6.5, 7.5]), m.b_edges
    fig = mp.map_figure(m, "t")
    for ax in fig.axes[:2]:
        assert ax.get_xscale() == "log" and ax.get_yscale() == "linear"
        xy = ax.collections[0].get_coordinates()  # the cells' corners, [a edge][b edge]
        assert np.allclose(xy[:, 0, 1], m.a_edges) and np.allclose(xy[0, :, 0], m.b_edges), xy
        assert list(ax.get_yticks()) == [-6, -5, 0], ax.get_yticks()
        assert np.allclose(ax.get_xticks(), [1e5, 1e6, 1e7]), ax.get_xticks()
    frame = [p for p in fig.axes[0].patches if p.get_label().startswith("walking rectangle")][0]
    assert np.allclose([frame.get_x(), frame.get_y()], [10 ** 5.5, -5.5]), frame
    assert np.isclose(frame.get_x() + frame.get_width(), 10 ** 7.5), frame
    assert np.isclose(frame.get_y() + frame.get_height(), 2.5), frame
PY
edit "$TMP/map/summary.json" "text = text.replace('\"values\": 3', '\"values\": 4')"
expect_error "(c3) grid size" stability_plots.py "$TMP/map" "$TMP/map/map_push_friction.csv: a 2 x 3 grid, summary.json says 2 x 4"

# (d) broken walk folders.
make_walk "$TMP/good_walk" 2 0
W="$TMP/w"
for f in walk.csv steps.csv stick.csv summary.json; do
  fresh walk w; rm "$W/$f"
  expect_error "(d) no $f" walk_plots.py "$W" "$W/$f: cannot read"
done
for col in hip_y theta_ref3 tau_ref4 fe_x phase stance_x; do
  fresh walk w
  edit "$W/walk.csv" "h, rest = text.split('\n', 1); text = h.replace('$col', 'x_$col', 1) + '\n' + rest"
  expect_error "(d) no walk.csv $col" walk_plots.py "$W" "$W/walk.csv: missing column '$col'"
done
fresh walk w; edit "$W/steps.csv" "text = text.replace(',impact,', ',kind,', 1)"
expect_error "(d) no steps.csv impact" walk_plots.py "$W" "$W/steps.csv: missing column 'impact'"
fresh walk w; edit "$W/stick.csv" "text = text.replace(',link,', ',body,', 1)"
expect_error "(d) no stick.csv link" walk_plots.py "$W" "$W/stick.csv: missing column 'link'"
for key in robot reference controller ground steps_requested steps_completed fell failure \
    max_tracking_error poincare_max_multiplier poincare_multipliers; do
  fresh walk w
  edit "$W/summary.json" "import json; d = json.loads(text); del d['$key']; text = json.dumps(d)"
  expect_error "(d) no key $key" walk_plots.py "$W" "$W/summary.json: missing key '$key'"
done
fresh walk w; edit "$W/walk.csv" "lines = text.split('\n'); lines[3] = lines[3].replace('SSP', 'XSP'); text = '\n'.join(lines)"
expect_error "(d) bad phase" walk_plots.py "$W" "$W/walk.csv: column 'phase': unknown value 'XSP'"
fresh walk w; edit "$W/walk.csv" "lines = text.split('\n'); f = lines[5].split(','); f[7] = 'abc'; lines[5] = ','.join(f); text = '\n'.join(lines)"
expect_error "(d) bad number" walk_plots.py "$W" "$W/walk.csv:6: column 'theta3': expected a finite number, found 'abc'"
fresh walk w; edit "$W/steps.csv" "text = text.replace(',double,', ',triple,', 1)"
expect_error "(d) bad impact" walk_plots.py "$W" "$W/steps.csv: column 'impact': unknown value 'triple'"
fresh walk w; edit "$W/summary.json" "import json; d = json.loads(text); d['fell'] = 'no'; text = json.dumps(d)"
expect_error "(d) fell not bool" walk_plots.py "$W" "$W/summary.json: key 'fell': expected true or false"
fresh walk w; edit "$W/summary.json" "import json; d = json.loads(text); d['poincare_multipliers'] = [1, 2]; text = json.dumps(d)"
expect_error "(d) bad multipliers" walk_plots.py "$W" "$W/summary.json: key 'poincare_multipliers'"
fresh walk w; edit "$W/summary.json" "text = text[:-3]"
expect_error "(d) bad JSON" walk_plots.py "$W" "$W/summary.json: not valid JSON"

# (e) broken stability folders.
make_stability "$TMP/good_stab"
S="$TMP/s"
fresh stab s; rm "$S/summary.json"
expect_error "(e) no summary" stability_plots.py "$S" "$S/summary.json: cannot read"
fresh stab s; rm "$S/sweep_push.csv"
expect_error "(e) no sweep file" stability_plots.py "$S" "$S/sweep_push.csv: cannot read"
fresh stab s; edit "$S/summary.json" "text = text.replace('\"sweeps\"', '\"sweep\"')"
expect_error "(e) no sweeps" stability_plots.py "$S" "$S/summary.json: missing key 'sweeps'"
for key in unit values walks_from walks_to nominal; do
  fresh stab s
  edit "$S/summary.json" "import json; d = json.loads(text); del d['sweeps']['push']['$key']; text = json.dumps(d)"
  expect_error "(e) no $key" stability_plots.py "$S" "$S/summary.json: missing key 'sweeps.push.$key'"
done
for col in value steps_completed steps_requested fell failure max_tracking_error max_multiplier \
    mean_advance wall_time_s; do
  fresh stab s
  edit "$S/sweep_friction.csv" "h, rest = text.split('\n', 1); text = h.replace('$col', 'x_$col', 1) + '\n' + rest"
  expect_error "(e) no $col" stability_plots.py "$S" "$S/sweep_friction.csv: missing column '$col'"
done
fresh stab s; edit "$S/summary.json" "text = text.replace('\"values\": 3', '\"values\": 4', 1)"
expect_error "(e) row count" stability_plots.py "$S" "$S/sweep_friction.csv: 3 rows, summary.json says 4 values"
fresh stab s; edit "$S/sweep_push.csv" "text = text.replace('-10,0,10,1', '-10,0,10,maybe')"
expect_error "(e) bad fell" stability_plots.py "$S" "$S/sweep_push.csv: column 'fell': unknown value 'maybe'"

# (f) gait_plots.py and impact_map.py through plot_io: missing files and a missing column.
mkdir -p "$TMP/empty"
expect_error "(f) gait no trajectory" gait_plots.py "$TMP/empty" "$TMP/empty/trajectory.csv: cannot read the trajectory"
expect_error "(f) no impact map" impact_map.py "$TMP/empty" "$TMP/empty/impact_map.csv: cannot read the map"
printf 'mu_SL,type\n0.2,single\n' >"$TMP/empty/impact_map.csv"
expect_error "(f) impact map column" impact_map.py "$TMP/empty" "$TMP/empty/impact_map.csv: missing column 'knee_bias_deg'"
# Usage text and exit 1 without a folder argument.
for script in gait_plots.py impact_map.py walk_plots.py stability_plots.py hzd_plots.py; do
  "$PY" "$PLOTS/$script" >/dev/null 2>"$TMP/err"
  [[ $? -eq 1 ]] && grep -q "^Usage: $script RESULT_DIR" "$TMP/err" || fail "(f) $script usage"
done

# (g) hzd_plots.py: the made-up walk with an "hzd" block draws hzd.png; without the block, or
# with a non-numeric multiplier, "error: <summary>: ..." naming the key.
make_walk "$TMP/hzd" 2 0
"$PY" - "$TMP/hzd/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["hzd"] = {"phase_weights": [0.5, 0.5, 0, 0, 0], "phase_plus": -0.3, "phase_minus": 0.35,
            "restricted_multiplier": 0.55, "v_zero_minus": -330.0,
            "zeta_minus_fixed_point": 733.3}
json.dump(d, open(sys.argv[1], "w"))
PY
plot hzd_plots.py "$TMP/hzd"
[[ $RC -eq 0 ]] || fail "(g) hzd_plots.py exited $RC: $(cat "$TMP/err")"
grep -qx "$TMP/hzd/hzd.png" "$TMP/out" && [[ -s "$TMP/hzd/hzd.png" ]] || fail "(g) hzd.png"
"$PY" -c "import json,sys; d=json.load(open(sys.argv[1])); d['hzd']['restricted_multiplier']='x'; \
json.dump(d, open(sys.argv[1], 'w'))" "$TMP/hzd/summary.json"
expect_error "(g) bad multiplier" hzd_plots.py "$TMP/hzd" \
  "$TMP/hzd/summary.json: key 'hzd.restricted_multiplier': expected a number"
expect_error "(g) no hzd block" hzd_plots.py "$TMP/walk" "$TMP/walk/summary.json: missing key 'hzd'"

# (h) gait_plots.py on a made-up gait folder (five links, 0.6 s SSP then 0.1 s DSP, ZMP 0.15 m
# behind the heel at t = 0): every picture, the stick diagram thinned to 12 SSP + 4 DSP frames,
# the ZMP margin drawn equal to the summary's; the foot from summary.json or, without the key,
# no foot (point tips, a note on stderr). Then the one trajectory reader (plot_io) rejects a
# torn row and a missing torque column, the same in gait_plots.py and compare_gaits.py.
make_gait() {
  "$PY" - "$@" <<'PY'
import csv, json, math, os, sys
out = sys.argv[1]; foot = sys.argv[2] if len(sys.argv) > 2 else "summary"
os.makedirs(out, exist_ok=True)
n, L, T, Ts = 5, 0.35, 0.7, 0.6
lengths, cont = [0.332, 0.302, 0.486, 0.302, 0.332], [1, 1, 0, 1, 1]
def pose(s):
    a = 0.5 * (s - 0.5)
    lift = 0.25 * math.sin(math.pi * min(s / (Ts / T), 1))
    return [a - 0.05, a + 0.05, 0.1, math.pi - a + 0.05 - lift, math.pi - a - 0.05 + lift]
def tips(th):
    p = [0.0, 0.0]
    for i in range(n):
        q = [p[0] + lengths[i] * math.sin(th[i]), p[1] + lengths[i] * math.cos(th[i])]
        if cont[i]: p = q
    return p, q
rows = []
for k in range(71):
    t = k / 100; s = t / T; dsp = t > Ts + 1e-9
    th = pose(s); dth = [0.0] * n; ddth = [0.0] * n
    hip, sw = tips(th)
    hipp = [lengths[0]*math.sin(th[0])+lengths[1]*math.sin(th[1]), lengths[0]*math.cos(th[0])+lengths[1]*math.cos(th[1])]
    tau = [20 * math.sin(2 * math.pi * s + j) for j in range(n)]
    fb = [10.0, 150.0 if dsp else 290.0]; fe = [-5.0, 140.0] if dsp else [0.0, 0.0]
    zmp = (0.3 * s - 0.2) if not dsp else 0.18
    q = th[:]; dq = [0.0]*n
    rows.append([t, "DSP" if dsp else "SSP"] + th + dth + ddth + q + dq + tau + fb + fe
                + [zmp, hipp[0], hipp[1], sw[0], sw[1], hipp[0], hipp[1] + 0.1])
with open(f"{out}/trajectory.csv", "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["t", "phase"] + [f"theta{i}" for i in range(1, 6)] + [f"dtheta{i}" for i in range(1, 6)]
               + [f"ddtheta{i}" for i in range(1, 6)] + [f"q{j}" for j in range(5)] + [f"dq{j}" for j in range(5)]
               + [f"tau{j}" for j in range(5)] + ["fb_x", "fb_y", "fe_x", "fe_y", "zmp_x", "hip_x", "hip_y",
               "swing_x", "swing_y", "com_x", "com_y"])
    w.writerows(rows)
names = ["stance_shank", "stance_thigh", "torso", "swing_thigh", "swing_shank"]
s = {"robot": "made_up", "status": "designed", "step_length": L, "duration": T, "speed": L / T, "friction": 0.6,
     "min_normal_force": 140.0, "max_friction_ratio": 0.05, "min_zmp_margin": -0.15,
     "energy_J": 30.0, "cost_of_transport": 0.3, "torque_squared": 100.0,
     "links": [{"name": a, "length": l, "continues": bool(c)} for a, l, c in zip(names, lengths, cont)],
     "joints": [{"name": j} for j in ["stance_ankle", "stance_knee", "stance_hip", "swing_hip", "swing_knee"]]}
if foot == "summary":
    s["foot"] = {"heel": 0.05, "toe": 0.15}
elif foot == "point":
    s["foot"] = {"heel": 0.0, "toe": 0.0}
elif foot == "robot_file":  # a folder written before summaries named the foot
    s["robot"] = "mu2004_five_link"
json.dump(s, open(f"{out}/summary.json", "w"))
PY
}
make_gait "$TMP/gait"
plot gait_plots.py "$TMP/gait"
[[ $RC -eq 0 ]] || fail "(h) gait_plots.py exited $RC: $(cat "$TMP/err")"
for name in joint_angles paths dsp_zmp forces torques zmp stick overview; do
  grep -qx "$TMP/gait/$name.png" "$TMP/out" && [[ -s "$TMP/gait/$name.png" ]] ||
    fail "(h) $name.png"
done
[[ $(wc -l <"$TMP/out") -eq 8 && ! -s "$TMP/err" ]] || fail "(h) output: $(cat "$TMP/out" "$TMP/err")"
(cd "$PLOTS" && "$PY" - "$TMP/gait" <<'PY') || fail "(h) frames or ZMP margin"
import sys
import gait_plots
g = gait_plots.Gait(sys.argv[1])
frames = gait_plots.stick_frames(g)
assert (len(frames) - sum(g.dsp[frames]), sum(g.dsp[frames])) == (12, 4), frames
assert g.foot == (0.05, 0.15) and g.foot_source == "summary.json", (g.foot, g.foot_source)
assert abs(g.zmp_margin().min() - g.s["min_zmp_margin"]) < 1e-9, g.zmp_margin().min()
PY
# (h') the overview's panels: no stray "(a)" in a title; the swing hip's torque dashed beside
# the stance hip's (they coincide through much of a step); the stick legend lists DSP only for
# a gait with one; the ZMP note in the half away from its point.
(cd "$PLOTS" && "$PY" - "$TMP/gait" <<'PY') || fail "(h') overview panels"
import sys
import numpy as np
import gait_plots
import plot_style
g = gait_plots.Gait(sys.argv[1])
plt = plot_style.pyplot()
fig, ax = plt.subplots()
gait_plots.draw_positions(ax, g)
assert ax.get_title() == "Horizontal positions over two steps", ax.get_title()
names = ["stance ankle", "stance knee", "stance hip", "swing hip", "swing knee"]
assert [gait_plots.torque_style(names, j) for j in range(5)] == ["-", "-", "-", "--", "-"]
assert gait_plots.torque_style(["stance ankle", "swing hip"], 1) == "-"
def stick_labels(g):
    fig, ax = plt.subplots()
    gait_plots.draw_stick(ax, g)
    return ax.get_legend_handles_labels()[1]
assert "DSP" in stick_labels(g)
g.dsp = np.zeros_like(g.dsp)
assert "DSP" not in stick_labels(g)
fig, ax = plt.subplots()
ax.set_xlim(0, 0.7)
assert gait_plots.note_place(ax, 0.01) == (0.97, "right")
assert gait_plots.note_place(ax, 0.6) == (0.03, "left")
PY
# (h) a gait folder on the fixed-rate grid: the touchdown's two rows and the end row come from
# summary.json (phase_switches, step_end) and plot_io puts them back in time order, replacing
# the grid rows at 0.6 s and 0.7 s (docs/design.md#the-export-contract, gaits/trajectory/switch_states.hpp).
make_gait "$TMP/grid"
(cd "$PLOTS" && "$PY" - "$TMP/grid" <<'PY') || fail "(h) switch rows from summary.json"
import csv, json, sys
import plot_io
d = sys.argv[1]
with open(f"{d}/trajectory.csv") as f:
    header, *rows = list(csv.reader(f))
row = lambda r: {h: (v if h == "phase" else float(v)) for h, v in zip(header, r)}
at = {round(float(r[0]), 9): r for r in rows}
before, end = row(at[0.6]), row(at[0.7])
before["tau0"] = 123.0  # a marker: the summary's row, not the CSV's
after = dict(before, phase="DSP", tau0=-123.0)
at[0.6] = [str(after[h]) for h in header]  # the grid's sample at the switch: post-impact
with open(f"{d}/trajectory.csv", "w") as f:
    csv.writer(f, lineterminator="\n").writerows([header] + [at[t] for t in sorted(at)])
s = json.load(open(f"{d}/summary.json"))
s["phase_switches"] = [{"t": 0.6, "from": "SSP", "to": "DSP", "before": before, "after": after}]
s["step_end"] = end
s["sample_rate_hz"] = 100.0  # the grid's rate, which the export writes beside its switch rows
json.dump(s, open(f"{d}/summary.json", "w"))
g = plot_io.read_trajectory(f"{d}/trajectory.csv")
assert len(g.t) == 72, len(g.t)  # 71 grid rows, less 0.6 and 0.7, plus before, after, end
assert list(g.phase[59:63]) == ["SSP", "SSP", "DSP", "DSP"], g.phase[59:63]
assert g.t[60] == g.t[61] == 0.6 and g.t_touchdown == 0.6 and g.t[-1] == 0.7, g.t[58:63]
assert g.col["tau0"][60] == 123.0 and g.col["tau0"][61] == -123.0, g.col["tau0"][59:63]
s["step_end"] = {"t": 0.7}
json.dump(s, open(f"{d}/summary.json", "w"))
try:
    plot_io.read_trajectory(f"{d}/trajectory.csv")
    raise SystemExit("a step_end without its columns was accepted")
except plot_io.InputError as e:
    assert "key 'step_end.phase'" in str(e) or "key 'step_end.theta1'" in str(e), e
PY
make_gait "$TMP/pointfoot" none
plot gait_plots.py "$TMP/pointfoot"
[[ $RC -eq 0 ]] && grep -q "ZMP drawn against point tips" "$TMP/err" || fail "(h) no foot: $(cat "$TMP/err")"
# A summary that says point feet: no note. One without the key: the foot of the shipped robot
# file of that name (configs/robots/, beside plots/ in a checkout and in an installation).
make_gait "$TMP/pointfeet" point
plot gait_plots.py "$TMP/pointfeet"
[[ $RC -eq 0 && ! -s "$TMP/err" ]] || fail "(h) point feet: $(cat "$TMP/err")"
make_gait "$TMP/robotfile" robot_file
(cd "$PLOTS" && "$PY" - "$TMP/robotfile" <<'PY') || fail "(h) foot from the robot file"
import sys
import gait_plots
g = gait_plots.Gait(sys.argv[1])
assert g.foot == (0.05, 0.15) and g.foot_source == "configs/robots/mu2004_five_link.yaml", (
    g.foot, g.foot_source)
PY
G="$TMP/torn"
make_gait "$G"
edit "$G/trajectory.csv" "lines = text.split('\n'); lines[4] = lines[4].rsplit(',', 1)[0]; text = '\n'.join(lines)"
expect_error "(h) torn row" gait_plots.py "$G" "$G/trajectory.csv:5: 42 fields, the header has 43"
"$PY" "$PLOTS/compare_gaits.py" "$TMP/gait" "$G" "$TMP/cmp" >/dev/null 2>"$TMP/err"
[[ $? -eq 65 ]] && grep -qx "error: $G/trajectory.csv:5: 42 fields, the header has 43" "$TMP/err" ||
  fail "(h) compare_gaits.py torn row: $(cat "$TMP/err")"
make_gait "$G"
edit "$G/trajectory.csv" "h, rest = text.split('\n', 1); text = h.replace('tau2', 'x_tau2', 1) + '\n' + rest"
expect_error "(h) no tau2" gait_plots.py "$G" "$G/trajectory.csv: missing column 'tau2'"
make_gait "$G"
edit "$G/trajectory.csv" "lines = text.split('\n'); lines[6] = '0.001' + lines[6][lines[6].index(','):]; text = '\n'.join(lines)"
expect_error "(h) time backwards" gait_plots.py "$G" "$G/trajectory.csv:7: column 't': time goes backwards"
make_gait "$G"
edit "$G/trajectory.csv" "lines = text.split('\n'); lines[3] = lines[3].replace('SSP', 'DSP'); text = '\n'.join(lines)"
expect_error "(h) DSP before SSP" gait_plots.py "$G" "$G/trajectory.csv: column 'phase': expected SSP rows followed by DSP rows"

# (j) ground_chart.py: a failed walk with a path value is drawn at its own wall time (no note);
# one without an end time is named in the note of the timing panel; the table is printed.
mkdir -p "$TMP/ground"
cat >"$TMP/ground/bench.csv" <<'CSV'
ground,variant,time_step,steps,failure,hip_deviation_m,timing_s,wall_s
rigid,RK4,0.01,10,,1e-06,1e-04,0.006
rigid,RK4,0.005,10,,5e-07,1e-05,0.011
soft,floor,0.001,0,"step 1: diverged: too long",1e-04,nan,0.002
soft,floor,0.0005,10,,1e-03,2e-01,0.2
CSV
"$PY" "$PLOTS/ground_chart.py" "$TMP/ground/bench.csv" >"$TMP/out" 2>"$TMP/err" &&
  [[ -s "$TMP/ground/ground_speed_accuracy.png" ]] && grep -q "^| soft | floor | 0.001 | 0 |" "$TMP/out" ||
  fail "(j) ground_chart.py: $(cat "$TMP/err")"
(cd "$PLOTS" && "$PY" - "$TMP/ground/bench.csv" <<'PY') || fail "(j) failed walk placement"
import sys
import ground_chart as gc
import plot_io
rows = plot_io.read_csv(sys.argv[1], "ground bench", gc.NAMES, strings=gc.STRINGS, finite=False)
fig, (a, b) = gc.plt.subplots(1, 2)
assert gc.draw(a, rows, "hip_deviation_m", "path: y") == []
notes = gc.draw(b, rows, "timing_s", "timing: y")
assert notes == ["soft (floor), h = 0.001 s failed: step 1: diverged: no timing value to draw"], notes
xs = [x for line in a.lines for x in line.get_xdata() if line.get_marker() == "X"]
assert 0.002 in xs, xs
# The failure marker is in the legend of a panel that draws one only; notes one line each.
assert "walk failed (at its wall time)" in a.get_legend_handles_labels()[1]
assert "walk failed (at its wall time)" not in b.get_legend_handles_labels()[1]
assert gc.legend_entries((a, b))[1].count("walk failed (at its wall time)") == 1
lines = gc.note_lines(["a note", "x " * 100, "a note"])
assert lines[0] == "a note" and len(lines) == 3 and all(len(l) <= gc.NOTE_WIDTH for l in lines), lines
PY

# (k) walk_gif.py: each physical leg keeps its colour across the touchdown (the link numbers
# run from the new stance tip), and the x range holds the toe ahead of the leading tip.
(cd "$PLOTS" && "$PY" - <<'PY') || fail "(k) walk.gif colours and x range"
import walk_gif
one, two = walk_gif.link_colours(5, 1), walk_gif.link_colours(5, 2)
assert two == one[::-1] and two[2] == one[2] and walk_gif.link_colours(5, 3) == one
lo, hi = walk_gif.x_limits(0.0, 2.0, (0.05, 0.15))
assert hi >= 2.0 + 0.15 + 0.05 - 1e-12 and lo <= -0.1, (lo, hi)
assert walk_gif.x_limits(0.0, 2.0, None) == (-0.1, 2.1)
PY

# (i) multipliers_plot.py: the walks with multipliers on the unit circle, a walk that fell named
# as having none; a malformed multiplier list is an error naming the file and key.
plot_multipliers() {
  "$PY" "$PLOTS/multipliers_plot.py" "$@" >"$TMP/out" 2>"$TMP/err"
  RC=$?
}
plot_multipliers "$TMP/mult.png" "$TMP/walk" "$TMP/fell"
[[ $RC -eq 0 && -s "$TMP/mult.png" ]] && grep -qx "$TMP/mult.png" "$TMP/out" ||
  fail "(i) multipliers_plot.py exited $RC: $(cat "$TMP/err")"
(cd "$PLOTS" && "$PY" - "$TMP/walk" "$TMP/fell" <<'PY') || fail "(i) walks read"
import sys
import multipliers_plot as mp
(label, z, _), (_, none, outcome) = mp.read_walk(sys.argv[1]), mp.read_walk(sys.argv[2])
assert label == "ref, computed_torque, rigid ground" and len(z) == 3 and abs(abs(z).max() - 0.5) < 1e-12
assert none is None and outcome.startswith("fell: fell: hip below"), outcome
PY
# (i') magnitudes at or below FLOOR are an arrow at the floor with their own legend entry, shown
# only when used; the legend under the axes.
(cd "$PLOTS" && "$PY" - <<'PY') || fail "(i') multipliers at the floor"
import numpy as np
import multipliers_plot as mp
import plot_style
m, below = mp.split_at_floor(np.array([0.5, 1e-13, 0, 1e-6j]))
assert list(m) == [0.5, 1e-6] and below == 2, (m, below)
fig, (a, b) = plot_style.pyplot().subplots(1, 2)
mp.draw_magnitudes(a, [("x", np.array([0.5, 0.0]), "C0", "o")])
mp.draw_magnitudes(b, [("y", np.array([0.5, 1e-3]), "C0", "o")])
floor_label = f"|λ| ≤ {mp.FLOOR:g} (drawn at {mp.FLOOR:g})"
assert floor_label in a.get_legend_handles_labels()[1]
assert floor_label not in b.get_legend_handles_labels()[1]
arrows = [l for l in a.lines if l.get_marker() == mp.BELOW_FLOOR and len(l.get_ydata())]
assert len(arrows) == 1 and list(arrows[0].get_ydata()) == [mp.FLOOR]
fig.canvas.draw()
box = a.get_legend().get_window_extent().transformed(a.transAxes.inverted())
assert box.y1 < 0, box
PY
cp -r "$TMP/walk" "$TMP/badmult"
edit "$TMP/badmult/summary.json" "import json; d = json.loads(text); d['poincare_multipliers'] = [[1]]; text = json.dumps(d)"
plot_multipliers "$TMP/m2.png" "$TMP/badmult"
[[ $RC -eq 1 ]] && grep -q "^error: $TMP/badmult/summary.json: key 'poincare_multipliers'" "$TMP/err" ||
  fail "(i) bad multipliers: $RC $(cat "$TMP/err")"

echo "plots_test: all checks passed"
