#!/usr/bin/env bash
# End-to-end checks of `gaitopt export-urdf` (its numbers against DART: dynamics/urdf_export_test).
# Usage: export_urdf_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"

# (a) the five-link robot: a URDF tree of 7 links and 6 joints rooted at stance_foot, with the
# foot box of the robot file (heel 0.05 + toe 0.15 m).
run export-urdf --robot "$ROBOT" --out "$TMP/five.urdf"
[[ $RC -eq 0 ]] || fail "(a) export-urdf exited $RC, stderr: $(cat "$TMP/err")"
"$PY" - "$TMP/five.urdf" <<'PY' || fail "(a) the URDF's tree"
import sys, xml.etree.ElementTree as ET
robot = ET.parse(sys.argv[1]).getroot()
links = [l.get("name") for l in robot.findall("link")]
joints = robot.findall("joint")
assert robot.get("name") == "mu2004_five_link", robot.get("name")
assert len(links) == 7 and len(joints) == 6, (links, len(joints))
children = {j.find("child").get("link") for j in joints}
assert set(links) - children == {"stance_foot"}, set(links) - children
box = robot.find("link[@name='swing_foot']/collision/geometry/box").get("size").split()
assert abs(float(box[0]) - 0.2) < 1e-12, box
PY

# (b) an --out that is not a .urdf file (it could be the robot file itself): exit 2, unwritten.
cp "$ROBOT" "$TMP/robot.yaml"
run export-urdf --robot "$TMP/robot.yaml" --out "$TMP/robot.yaml"
[[ $RC -eq 2 ]] || fail "(b) --out robot.yaml: exit code $RC, expected 2"
cmp -s "$ROBOT" "$TMP/robot.yaml" || fail "(b) the robot file was overwritten"
# and a robot file named *.urdf, given as --out too (here through a link to it): exit 2, unwritten
cp "$ROBOT" "$TMP/robot.urdf" && ln -s "$TMP/robot.urdf" "$TMP/link.urdf"
run export-urdf --robot "$TMP/robot.urdf" --out "$TMP/link.urdf"
[[ $RC -eq 2 ]] && grep -qF "is the robot file itself" "$TMP/err" ||
  fail "(b) --out the robot file: exit code $RC: $(cat "$TMP/err")"
cmp -s "$ROBOT" "$TMP/robot.urdf" || fail "(b) the robot file named .urdf was overwritten"

# (c) a missing robot file: exit 2, naming it.
run export-urdf --robot "$TMP/no_such_robot.yaml" --out "$TMP/x.urdf"
[[ $RC -eq 2 ]] || fail "(c) missing robot file: exit code $RC, expected 2"
grep -qF "no_such_robot.yaml" "$TMP/err" || fail "(c) stderr lacks the file name: $(cat "$TMP/err")"

# (d) a link named like a foot the URDF adds: exit 2, naming the clash; no file written.
sed 's/name: torso,/name: swing_foot,/' "$ROBOT" >"$TMP/clash.yaml"
run export-urdf --robot "$TMP/clash.yaml" --out "$TMP/clash.urdf"
[[ $RC -eq 2 ]] || fail "(d) clashing link name: exit code $RC, expected 2"
grep -qF "'swing_foot' is used twice" "$TMP/err" || fail "(d) stderr: $(cat "$TMP/err")"
[[ ! -e "$TMP/clash.urdf" ]] || fail "(d) a URDF was written"

# (e) an --out that is a folder named like a URDF: exit 2, the folder left as it was.
mkdir "$TMP/d.urdf" && echo "user data" >"$TMP/d.urdf/notes"
run export-urdf --robot "$ROBOT" --out "$TMP/d.urdf"
[[ $RC -eq 2 ]] || fail "(e) --out a folder: exit code $RC, expected 2"
grep -qF "is a folder" "$TMP/err" || fail "(e) stderr: $(cat "$TMP/err")"
[[ $(cat "$TMP/d.urdf/notes") == "user data" ]] || fail "(e) the folder's file was changed"

echo "export_urdf_cli: all checks passed"
