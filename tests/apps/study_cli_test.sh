#!/usr/bin/env bash
# End-to-end checks of `gaitopt study`: a study's solves against the same solves run by hand,
# its walks against `gaitopt simulate`, the warm start kept only when cheaper, a rerun that
# redoes nothing and one under other settings refused, the same tables from two runs at once, bad
# study configs refused before any solve, and a chain solved from the previous optimum alone.
# Usage: study_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
OCP="$(cd "$ROOT" && pwd)/configs/ocp"

cat >"$TMP/study.yaml" <<YAML
name: tiny
gaits: [$OCP/compass_gait_walk.yaml, $OCP/mu2004_walk.yaml]
axes:
  - {key: "phases[0].segments", name: ssp_segments, values: [20, 24]}
  - name: solver
    values: [{solver.linear_solver: mumps}, {solver.linear_solver: ldl, solver.tolerance: 1.0e-5}]
    labels: [mumps, ldl5]
warm_start: previous
walks:
  - name: rigid
    options: {ground: rigid, cop-limit: fail, steps: 2}
    controllers: [computed_torque]
    plant: {option: mass-error, values: [-0.05, 0]}
YAML

# (a) Every point solved; each cost is the one `gaitopt optimize` reaches with the same --set
# values from the same start (the guess, or the previous point's optimum).
run study --config "$TMP/study.yaml" --out "$TMP/s"
[[ $RC -eq 0 ]] || fail "(a) study exited $RC: $(cat "$TMP/err")"
grep -q "8 of 8 solves converged, 16 walks" "$TMP/out" || fail "(a) summary line: $(tail -1 "$TMP/out")"
"$GAITOPT" optimize --config "$OCP/mu2004_walk.yaml" --set 'phases[0].segments=24' \
  --set solver.linear_solver=mumps --out "$TMP/by_hand" --no-plots --quiet >/dev/null ||
  fail "(a) optimize by hand failed"
"$GAITOPT" simulate --reference "$TMP/by_hand" --controller computed_torque --ground rigid \
  --cop-limit fail --steps 2 --mass-error=-0.05 --out "$TMP/walk_by_hand" --no-plots \
  --no-poincare --quiet >/dev/null || fail "(a) simulate by hand failed"
$PY - "$TMP/s" "$TMP/by_hand/summary.json" "$TMP/walk_by_hand/summary.json" <<'PY' || fail "(a) tables"
import csv, json, sys
out, hand, walk_hand = sys.argv[1], json.load(open(sys.argv[2])), json.load(open(sys.argv[3]))
solves = list(csv.DictReader(open(f"{out}/solves.csv")))
assert [(r["gait"], r["ssp_segments"], r["solver"]) for r in solves[:4]] == [
    ("compass_gait_walk", "20", "mumps"), ("compass_gait_walk", "20", "ldl5"),
    ("compass_gait_walk", "24", "mumps"), ("compass_gait_walk", "24", "ldl5")], solves
assert all(r["converged"] == "1" for r in solves), solves
row = next(r for r in solves if r["gait"] == "mu2004_walk" and r["ssp_segments"] == "24"
           and r["solver"] == "mumps")
assert row["start"] == "guess", row  # the first point of its line has no previous point
assert abs(float(row["cost"]) - hand["cost"]) <= 1e-6 * hand["cost"], (row["cost"], hand["cost"])
assert int(row["iterations"]) == hand["iterations"], (row["iterations"], hand["iterations"])
# The export's checks between the points (summary.json between_nodes) are columns too.
for column, key in [("max_dsp_tip_drift_between_m", "max_dsp_tip_drift"),
                    ("max_rate_mismatch_between", "max_rate_mismatch"),
                    ("max_acceleration_mismatch_between", "max_acceleration_mismatch"),
                    ("max_friction_ratio_between", "max_friction_ratio")]:
    assert abs(float(row[column]) - hand["between_nodes"][key]) <= 1e-9, (column, row[column])
# The recorded --set values are the study's: the point's folder is an ordinary gait folder.
point = json.load(open(f"{out}/runs/mu2004_walk_ssp_segments=24_solver=mumps/summary.json"))
assert abs(point["cost"] - float(row["cost"])) <= 1e-9 * point["cost"], (point["cost"], row["cost"])
# A warm start is kept only when it is cheaper than the cold solve.
for r in solves:
    if r["start"] != "guess":
        assert r["solver"] == "ldl5" and r["start"].endswith("solver=mumps"), r
walks = list(csv.DictReader(open(f"{out}/walks.csv")))
assert len(walks) == 16, walks
w = next(r for r in walks if r["gait"] == "mu2004_walk" and r["ssp_segments"] == "24" and
         r["solver"] == "mumps" and r["plant"] == "-0.05")
assert int(w["steps"]) == walk_hand["steps_completed"], (w, walk_hand["steps_completed"])
assert w["failure"] == walk_hand["failure"], (w["failure"], walk_hand["failure"])
assert w["steps_requested"] == "2", w
# A walk the controller refuses (the compass gait's ankle is passive) is a row saying why.
w = next(r for r in walks if r["gait"] == "compass_gait_walk")
assert w["steps"] == "" and w["failure"].startswith("simulate exited 2: error: --controller"), w
pivot = open(f"{out}/walks_by_plant.md").read()
assert "| gait | ssp_segments | solver | walk | controller | mass-error -0.05 | mass-error 0 |" in pivot, pivot
by_axis = open(f"{out}/by_axis.md").read()
assert "| solver | ldl5 | 4 of 4 |" in by_axis, by_axis
PY

# (b) A rerun finds every run done: nothing started, the tables the same.
cp "$TMP/s/solves.csv" "$TMP/solves_before.csv"
run study --config "$TMP/study.yaml" --out "$TMP/s"
[[ $RC -eq 0 ]] || fail "(b) rerun exited $RC"
if grep -q "study: solve\|study: walk" "$TMP/out"; then fail "(b) rerun redid: $(cat "$TMP/out")"; fi
cmp -s "$TMP/s/solves.csv" "$TMP/solves_before.csv" || fail "(b) solves.csv changed on a rerun"

# A rerun under other settings is refused, naming what differs, and runs nothing.
run study --config "$TMP/study.yaml" --out "$TMP/s" --set 'walks[0].plant.values=[0]'
[[ $RC -eq 2 ]] || fail "(b) a rerun with other settings exited $RC"
grep -q "set" "$TMP/err" || fail "(b) the difference not named: $(cat "$TMP/err")"
cmp -s "$TMP/s/solves.csv" "$TMP/solves_before.csv" || fail "(b) a refused rerun wrote solves.csv"

# A file the rows were made from, edited since, is named in the refusal (the record holds the
# files' fingerprints only, which the message once listed instead).
cp "$TMP/study.yaml" "$TMP/study.yaml.orig" && echo "# edited" >>"$TMP/study.yaml"
run study --config "$TMP/study.yaml" --out "$TMP/s"
[[ $RC -eq 2 ]] && grep -q "study.yaml has changed since the folder's rows were made" "$TMP/err" ||
  fail "(b) an edited input not named, exit $RC: $(cat "$TMP/err")"
mv "$TMP/study.yaml.orig" "$TMP/study.yaml"

# (c) Two runs at once give the same tables in the same order (times aside).
run study --config "$TMP/study.yaml" --out "$TMP/s2" --jobs 2 --quiet
[[ $RC -eq 0 ]] || fail "(c) --jobs 2 exited $RC: $(cat "$TMP/err")"
$PY - "$TMP/s" "$TMP/s2" <<'PY' || fail "(c) --jobs 2 tables differ"
import csv, sys
def rows(folder, name):
    return [{k: v for k, v in r.items() if k != "wall_time_s"}
            for r in csv.DictReader(open(f"{folder}/{name}"))]
for name in ("solves.csv", "walks.csv"):
    assert rows(sys.argv[1], name) == rows(sys.argv[2], name), name
PY

# (d) Bad study configs: refused with the file, the key and why, before any solve.
bad() {  # NAME YAML EXPECTED
  printf '%s\n' "$2" >"$TMP/$1.yaml"
  run study --config "$TMP/$1.yaml" --out "$TMP/bad_$1"
  [[ $RC -eq 2 ]] || fail "(d) $1: exit $RC, expected 2"
  grep -q -- "$3" "$TMP/err" || fail "(d) $1: expected '$3' in: $(cat "$TMP/err")"
  [[ ! -d "$TMP/bad_$1/runs" ]] || fail "(d) $1: solved before refusing"
}
bad value "name: b
gaits: [$OCP/mu2004_walk.yaml]
axes: [{key: constraints.friction_margin, values: [0.1, -3]}]" "refuses '-3'"
bad labels "name: b
gaits: [$OCP/mu2004_walk.yaml]
axes: [{key: constraints.friction_margin, values: [0.1], labels: [a, b]}]" "one label per value"
bad slash "name: b
gaits: [$OCP/mu2004_walk.yaml]
axes: [{key: constraints.friction_margin, values: [0.1], labels: [a/b]}]" "cannot name a folder"
bad controller "name: b
gaits: [$OCP/mu2004_walk.yaml]
walks: [{name: w, controllers: [pid], plant: {option: mass-error, values: [0]}}]" "expected one of"
bad option "name: b
gaits: [$OCP/mu2004_walk.yaml]
walks: [{name: w, options: {speed: 2}, controllers: [computed_torque], plant: {option: mass-error, values: [0]}}]" "speed"
bad gait "name: b
gaits: [$OCP/no_such.yaml]" "no_such.yaml"
# (e) warm_start: previous_only: a point after the first is solved from the optimum before it
# alone (no solve from the guess), to the cost `optimize --warm-start` reaches by hand.
cat >"$TMP/chain.yaml" <<YAML
name: chain
gaits: [$OCP/mu2004_walk.yaml]
axes: [{key: constraints.friction_margin, values: [0.15, 0.2]}]
warm_start: previous_only
YAML
run study --config "$TMP/chain.yaml" --out "$TMP/chain"
[[ $RC -eq 0 ]] || fail "(e) exited $RC: $(cat "$TMP/err")"
first=mu2004_walk_friction_margin=0.15 second=mu2004_walk_friction_margin=0.2
grep -qx "study: solve $second from $first" "$TMP/out" || fail "(e) no warm solve: $(cat "$TMP/out")"
if grep -qx "study: solve $second" "$TMP/out"; then fail "(e) solved from the guess too"; fi
"$GAITOPT" optimize --config "$OCP/mu2004_walk.yaml" --set constraints.friction_margin=0.2 \
  --warm-start "$TMP/chain/runs/$first" --out "$TMP/chain_by_hand" --no-plots --quiet >/dev/null ||
  fail "(e) optimize by hand failed"
$PY - "$TMP/chain/solves.csv" "$TMP/chain_by_hand/summary.json" "$first" <<'PY' || fail "(e) tables"
import csv, json, sys
rows = list(csv.DictReader(open(sys.argv[1])))
hand = json.load(open(sys.argv[2]))
assert [r["start"] for r in rows] == ["guess", sys.argv[3]], rows
assert abs(float(rows[1]["cost"]) - hand["cost"]) <= 1e-9 * hand["cost"], (rows[1], hand["cost"])
PY
echo "study_cli_test: all checks passed"
