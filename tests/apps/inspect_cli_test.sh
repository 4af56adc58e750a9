#!/usr/bin/env bash
# End-to-end checks of `gaitopt inspect`.
# Usage: inspect_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"

# (a) default standing posture of the five-link robot.
run inspect --robot "$ROBOT"
[[ $RC -eq 0 ]] || fail "(a) inspect exited $RC, stderr: $(cat "$TMP/err")"
check_json "(a) total mass, D symmetric, G zero at the standing posture" <<'PY'
expected = ["robot", "n_links", "total_mass", "gravity", "friction", "links", "joints", "state",
            "D", "H_dtheta", "G", "tau", "kinetic_energy", "potential_energy", "com",
            "swing_tip", "hip", "link_segments"]
assert sorted(d) == sorted(expected), f"top-level keys {list(d)}"
assert abs(d["total_mass"] - 29.81) <= 1e-9, f"total_mass {d['total_mass']}"
seg = d["link_segments"]
assert abs(seg[4]["end"][0] - d["swing_tip"]["position"][0]) < 1e-12, "swing shank ends at E"
assert abs(seg[1]["end"][1] - d["hip"]["position"][1]) < 1e-12, "stance thigh ends at hip"
n = d["n_links"]
D = d["D"]
assert len(D) == n and all(len(row) == n for row in D), "D is not n x n"
for i in range(n):
    for j in range(n):
        assert abs(D[i][j] - D[j][i]) <= 1e-12, f"D[{i}][{j}]={D[i][j]} != D[{j}][{i}]={D[j][i]}"
assert len(d["G"]) == n and all(abs(g) <= 1e-12 for g in d["G"]), f"G {d['G']}"
PY

# (b) a mid-stride state: swing tip about 0.36 m behind the stance tip, on the ground.
cat >"$TMP/state.json" <<'JSON'
{"theta": [0.0206, -0.5461, 0, 3.3194, 3.6327], "dtheta": [0, 0, 0, 0, 0]}
JSON
run inspect --robot "$ROBOT" --state "$TMP/state.json"
[[ $RC -eq 0 ]] || fail "(b) inspect --state exited $RC, stderr: $(cat "$TMP/err")"
check_json "(b) swing tip position" <<'PY'
x, y = d["swing_tip"]["position"]
assert abs(x - (-0.360)) <= 2e-3, f"swing_tip x {x}, expected -0.360"
assert abs(y) <= 2e-3, f"swing_tip y {y}, expected 0"
PY

# (c) a missing robot file: exit 2, "error:" and the file name on stderr.
MISSING="$TMP/no_such_robot.yaml"
run inspect --robot "$MISSING"
[[ $RC -eq 2 ]] || fail "(c) missing robot file: exit code $RC, expected 2"
grep -q "error:" "$TMP/err" || fail "(c) stderr lacks 'error:': $(cat "$TMP/err")"
grep -qF "no_such_robot.yaml" "$TMP/err" || fail "(c) stderr lacks the file name: $(cat "$TMP/err")"

# (d) a state vector of the wrong length: exit 2, naming the key.
cat >"$TMP/short.json" <<'JSON'
{"theta": [0.0, 0.0, 0.0, 3.14]}
JSON
run inspect --robot "$ROBOT" --state "$TMP/short.json"
[[ $RC -eq 2 ]] || fail "(d) wrong-length theta: exit code $RC, expected 2"
grep -q "error:" "$TMP/err" || fail "(d) stderr lacks 'error:': $(cat "$TMP/err")"
grep -qF "'theta'" "$TMP/err" || fail "(d) stderr does not name the key theta: $(cat "$TMP/err")"

# (e) theta as a deeply nested object: exit 2, naming the key. Found with fuzz/state_json_fuzz:
# the error message dumped the value, recursing once per level until the stack overflowed.
"$PY" -c 'n = 100000; print("{\"theta\": " + "{\"a\": " * n + "1" + "}" * n + "}")' \
  >"$TMP/deep.json"
run inspect --robot "$ROBOT" --state "$TMP/deep.json"
[[ $RC -eq 2 ]] || fail "(e) deeply nested theta: exit code $RC, expected 2"
grep -qF "key 'theta': expected an array of 5 numbers" "$TMP/err" ||
  fail "(e) stderr does not name the key theta: $(cat "$TMP/err")"

echo "inspect_cli_test: all checks passed"
