#!/usr/bin/env bash
# End-to-end checks of `gaitopt report`: the page of a gait and of a walk (self-contained: no
# http(s) reference, every chart inlined), walk.gif, a non-result folder exits 2; the walk page
# in headless Chromium (report_browser_check.py: renders, no console error, the robot moves);
# user text that stays script data; a stability sweep whose reference is another robot's gait.
# Usage: report_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
# The polynomial gait walks a robot with a heel long enough for its ankle torque.
LONG_HEEL="$ROOT/tests/apps/mu2004_five_link_long_heel.yaml"
cd "$ROOT" || fail "no repo root $ROOT"

# (a) a gait folder: the page animates the step and inlines overview.png.
run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$TMP/poly"
[[ $RC -eq 0 ]] || fail "(a) poly exited $RC: $(cat "$TMP/err")"
run report "$TMP/poly"
[[ $RC -eq 0 ]] || fail "(a) report exited $RC: $(cat "$TMP/err")"
page="$TMP/poly/report.html"
[[ -s "$page" ]] || fail "(a) no report.html"
grep -qE '(src|href)="https?:' "$page" && fail "(a) the page loads something from the network"
"$PY" - "$page" "$TMP/poly" <<'PY' || fail "(a) page content"
import base64, json, pathlib, re, sys
page, folder = pathlib.Path(sys.argv[1]).read_text(), pathlib.Path(sys.argv[2])
data = json.loads(re.search(r"const DATA = (.*?);\n", page).group(1))
assert data["kind"] == "gait", data["kind"]
assert data["foot"] == [0.05, 0.15], data["foot"]  # configs/robots/mu2004_five_link.yaml's
f = data["frames"]
assert f["phase"][0] == "SSP" and f["phase"][-1] == "DSP", f["phase"][::10]
assert abs(f["t"][-1] - f["t"][0] - 0.7) < 1e-3, f["t"][-1]  # the gait's 0.6 s SSP + 0.1 s DSP
# Every frame's links form a chain from the stance tip at the origin (B), 5 links of Mu Table 2.1.
for links in f["links"]:
    assert len(links) == 5 and abs(links[0][0]) < 1e-4 and abs(links[0][1]) < 1e-4, links[0]
    assert abs(links[1][0] - links[0][2]) < 2e-4 and abs(links[1][1] - links[0][3]) < 2e-4
# Charts inlined byte for byte.
png = {c["name"]: c["src"] for c in data["charts"]}
want = base64.b64encode((folder / "overview.png").read_bytes()).decode()
assert png["overview.png"] == "data:image/png;base64," + want
PY

# (b) a walk folder: the page, walk.gif with one frame per stick.csv frame of the first steps.
run simulate --robot "$LONG_HEEL" --reference "$TMP/poly" --steps 3 --no-poincare --no-plots --out "$TMP/walk"
[[ $RC -eq 0 ]] || fail "(b) simulate exited $RC: $(cat "$TMP/err")"
run report "$TMP/walk"
[[ $RC -eq 0 ]] || fail "(b) report exited $RC: $(cat "$TMP/err")"
[[ -s "$TMP/walk/report.html" && -s "$TMP/walk/walk.gif" ]] || fail "(b) report.html or walk.gif"
"$PY" - "$TMP/walk" <<'PY' || fail "(b) walk.gif"
import sys
from PIL import Image
import numpy as np
rows = np.genfromtxt(sys.argv[1] + "/stick.csv", delimiter=",", names=True, dtype=None,
                     encoding="ascii")
frames = len(set(rows["t"]))  # every frame of the 3 steps (the GIF shows up to 6)
gif = Image.open(sys.argv[1] + "/walk.gif")
assert gif.n_frames >= frames - 1, (gif.n_frames, frames)
PY

# (b''') a stability folder of a map only (no sweep): its page, with the map's rows as a table.
run stability --robot "$LONG_HEEL" --reference "$TMP/poly" --steps 2 --no-plots --quiet \
  --map push=-1:1:2,mass_error=0:0.1:2 --out "$TMP/map"
[[ $RC -eq 0 ]] || fail "(b''') stability exited $RC: $(cat "$TMP/err")"
run report "$TMP/map" --robot "$LONG_HEEL"
[[ $RC -eq 0 ]] || fail "(b''') report of a map-only folder exited $RC: $(cat "$TMP/err")"
grep -q '"name":"map_push_mass_error.csv"' "$TMP/map/report.html" ||
  fail "(b''') the map's rows are not on the page"

# (b') the page of a walk whose robot file was given relative to the repository, made from
# another folder: its links are still named (the robot of the summary's name).
run simulate --robot tests/apps/mu2004_five_link_long_heel.yaml --reference "$TMP/poly" --steps 1 \
  --no-poincare --no-plots --out "$TMP/walk_rel"
[[ $RC -eq 0 ]] || fail "(b') simulate exited $RC: $(cat "$TMP/err")"
(cd "$TMP" && "$GAITOPT" report walk_rel --no-gif >/dev/null 2>"$TMP/err") ||
  fail "(b') report exited: $(cat "$TMP/err")"
"$PY" - "$TMP/walk_rel/report.html" <<'PY' || fail "(b') link names"
import json, re, sys
page = open(sys.argv[1]).read()
data = json.loads(re.search(r"const DATA = (.*?);\n", page).group(1))
names = ["stance_shank", "stance_thigh", "torso", "swing_thigh", "swing_shank"]
assert data["link_names"] == names, data["link_names"]
assert data["foot"] == [0.30, 0.15], data["foot"]  # the long heel walked, from the summary
PY

# (b'') walk.gif's feet: under the stance tip always, under the other tip when it is on the ground.
(cd "$ROOT/plots" && "$PY" - <<'PY') || fail "(b'') feet of walk.gif"
import numpy as np
import walk_gif
p0 = np.array([[0.0, 0.0], [0.1, 0.3]])
p1 = np.array([[0.1, 0.3], [0.35, 0.001]])
feet = walk_gif.feet_at(p0, p1, (0.05, 0.15))
assert np.allclose([x for xs, _ in feet for x in xs], [-0.05, 0.15, 0.30, 0.50]), feet
assert [ys for _, ys in feet] == [[0.0, 0.0], [0.001, 0.001]], feet
p1[-1, 1] = 0.05  # the swing tip 5 cm up: the stance foot alone
assert len(walk_gif.feet_at(p0, p1, (0.05, 0.15))) == 1
PY

# (c) not a result folder: exit 2 naming it; no page written.
mkdir -p "$TMP/empty"
run report "$TMP/empty"
[[ $RC -eq 2 ]] || fail "(c) exit $RC for a folder without results"
grep -q "$TMP/empty" "$TMP/err" || fail "(c) message does not name the folder: $(cat "$TMP/err")"
[[ -e "$TMP/empty/report.html" ]] && fail "(c) a page was written"
# and an --out that is a folder named like a page: bad input (exit 2), not an I/O failure (1)
mkdir -p "$TMP/page.html"
run report "$TMP/poly" --out "$TMP/page.html"
[[ $RC -eq 2 ]] && grep -qF "is a folder: expected a .html file" "$TMP/err" ||
  fail "(c) --out a folder: exit $RC: $(cat "$TMP/err")"

# (d) the walk page in a browser: renders, no console error, the robot walks between 0.1 and 0.5 s.
command -v chromium >/dev/null || fail "(d) chromium missing (scripts/install-deps.sh installs it)"
"$PY" "$(dirname "$0")/report_browser_check.py" "$TMP/walk/report.html" "$TMP" 0.1 0.5 ||
  fail "(d) browser check"

# (e) user text that would end the script or open the HTML parser's escaped states ("<!--",
# "<script") stays data: a folder and a robot (and a link) so named; the page still renders.
HOSTILE_DIR="$TMP/g<!--<script>&amp;"
HOSTILE_ROBOT='r<!--<script></script>&amp;'
cp -r "$TMP/poly" "$HOSTILE_DIR"
"$PY" - "$HOSTILE_DIR/summary.json" "$HOSTILE_ROBOT" "$TMP/hostile.yaml" <<'PY' || fail "(e) inputs"
import json, re, sys
summary_path, robot, robot_file = sys.argv[1:]
summary = json.load(open(summary_path))
summary["robot"] = robot
json.dump(summary, open(summary_path, "w"))
yaml = open("configs/robots/mu2004_five_link.yaml").read()
yaml = re.sub(r"(?m)^name: .*$", lambda _: f'name: "{robot}"', yaml)
open(robot_file, "w").write(yaml.replace("name: torso", 'name: "torso<!--<script>"'))
PY
run report --robot "$TMP/hostile.yaml" "$HOSTILE_DIR"
[[ $RC -eq 0 ]] || fail "(e) report exited $RC: $(cat "$TMP/err")"
"$PY" - "$HOSTILE_DIR" "$HOSTILE_ROBOT" "$(dirname "$0")" "$TMP" <<'PY' || fail "(e) script data"
import json, pathlib, re, sys
folder, robot = pathlib.Path(sys.argv[1]), sys.argv[2]
page = (folder / "report.html").read_text()
# The template's one script element, whole: the data opened and closed no other.
assert len(re.findall(r"<script", page, re.I)) == 1, "a <script tag came from the data"
assert len(re.findall(r"</script", page, re.I)) == 1, "a </script tag came from the data"
script = re.search(r"<script>(.*?)</script>", page, re.S).group(1)
literal = re.search(r"const DATA = (.*?);\n", script).group(1)
assert not re.search(r"[<>&]", literal), "raw <, > or & of the data in the script"
data = json.loads(literal)
assert data["title"] == folder.name, data["title"]
assert f"({robot})" in data["animation_note"], data["animation_note"]
assert "torso<!--<script>" in data["link_names"], data["link_names"]
# A browser shows the page (it would stay blank, titled "loading", in a double-escaped script).
sys.path.insert(0, sys.argv[3])
from report_browser_check import state_at
t, _ = state_at((folder / "report.html").resolve().as_uri() + "#t=0.1", pathlib.Path(sys.argv[4]))
assert abs(t - 0.1) < 1e-3, t
PY

# (a4) what the summary holds in objects is on the page, and a gait that breaks a check between
# the solver's points says so above the table (a copy of the gait with one breach written in).
cp -r "$TMP/poly" "$TMP/breach" && rm -f "$TMP/breach/report.html"
"$PY" - "$TMP/breach/summary.json" <<'PY' || fail "(a4) summary edit"
import json, sys
s = json.load(open(sys.argv[1]))
s["between_nodes"] = {"rate_hz": 1000.0, "max_friction_ratio": 1.6368, "breaches": [
    {"check": "max_friction_ratio", "value": 1.6368, "bound": 0.6,
     "meaning": "a tip force leaves the friction cone of the robot's mu: the tip slips"}]}
json.dump(s, open(sys.argv[1], "w"))
PY
run report "$TMP/breach" --no-gif
[[ $RC -eq 0 ]] || fail "(a4) report exited $RC: $(cat "$TMP/err")"
"$PY" - "$TMP/breach/report.html" "$(dirname "$0")" "$TMP" <<'PY' || fail "(a4) page"
import pathlib, re, sys
sys.path.insert(0, sys.argv[2])
from report_browser_check import chromium
dom = chromium(pathlib.Path(sys.argv[3]), "--dump-dom",
               pathlib.Path(sys.argv[1]).resolve().as_uri()).stdout
box = re.search(r'<div id="breaches"( hidden="")?>(.*?)</div>', dom, re.S)
assert box and not box.group(1), "the breach box is missing or hidden"
assert "breaks 1 check(s)" in box.group(2) and "the tip slips" in box.group(2), box.group(2)
for row in ("between_nodes", "max_torso_lean", "max_stance_knee_flexion"):
    assert re.search(rf'<td class="[^"]*"( colspan="2")?>{row}</td>', dom), f"no row {row}"
PY

# (f) a stability sweep whose reference folder now holds a gait of another robot (remade since):
# exit 2 naming both robots, as simulate refuses such a pair, rather than animate that robot.
mkdir -p "$TMP/sweep"
printf '{"robot": "rabbit", "reference": "%s", "sweeps": {}}\n' "$TMP/poly" \
  >"$TMP/sweep/summary.json"
run report "$TMP/sweep"
[[ $RC -eq 2 ]] || fail "(f) exit $RC for a sweep of another robot than its reference gait's"
want="the sweep walked robot 'rabbit', but its reference $TMP/poly is a gait of robot "
grep -qF "$want'mu2004_five_link'" "$TMP/err" || fail "(f) message: $(cat "$TMP/err")"
[[ $(wc -l <"$TMP/err") -eq 1 ]] || fail "(f) not one line: $(cat "$TMP/err")"
[[ -e "$TMP/sweep/report.html" ]] && fail "(f) a page was written"
# The same with --robot naming the reference's robot: the sweep's is still another.
run report --robot configs/robots/mu2004_five_link.yaml "$TMP/sweep"
[[ $RC -eq 2 ]] || fail "(f) exit $RC with --robot of the reference's robot"
grep -q "the sweep walked robot 'rabbit'" "$TMP/err" || fail "(f) message: $(cat "$TMP/err")"

# (g) a comparison has no page: the message says so and where to look, not "not a gaitopt
# result folder".
cp -r "$TMP/poly" "$TMP/poly_copy"
run compare "$TMP/poly" "$TMP/poly_copy" --out "$TMP/cmp"
[[ $RC -eq 0 ]] || fail "(g) compare exited $RC: $(cat "$TMP/err")"
run report "$TMP/cmp"
[[ $RC -eq 2 ]] && grep -q "a comparison (gaitopt compare) has no page of its own: open its comparison.md" "$TMP/err" ||
  fail "(g) exit $RC: $(cat "$TMP/err")"
echo "report_cli_test: all checks passed"
