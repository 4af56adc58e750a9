#!/usr/bin/env bash
# scripts/library_walks.sh on a two-point library of the default problem (0.45 and 0.6 m/s at
# 0.35 m): the solved points walked under computed torque and the blend at the cell's centre
# (0.525 m/s) under computed torque with the plan's double-support torques, each 20 steps on the
# nominal plant on the rigid ground, as the shipped library's rows say they do
# (results/library_walks/walks.csv);
# the rows of walks.csv and summary.csv agree; a walk that is not GAITS/RATE/MASS/LENGTH/LAW/
# GROUND exits 2 naming it.
# Usage: library_walks_test.sh <gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
cd "$ROOT" || fail "no repo root $ROOT"
build=$(dirname "$(dirname "$GAITOPT")")
[[ -x $build/apps/gaitopt ]] || skip "gaitopt is not at BUILD/apps/gaitopt"
printf 'name: two\nocp: %s\ngrid:\n  speed: [0.45, 0.6]\n  step_length: 0.35\n' \
  "$ROOT/configs/ocp/mu2004_walk.yaml" >"$TMP/two.yaml"
bash scripts/library_walks.sh "$build" "$TMP/out" "$TMP/two.yaml" \
  points/250/0/0/computed_torque/rigid cells/250/0/0/computed_torque_plan_dsp/rigid >"$TMP/log" 2>&1 ||
  fail "exited $?: $(cat "$TMP/log")"
"$PY" - "$TMP/out" <<'PY' || fail "walks"
import csv, sys
rows = list(csv.DictReader(open(f"{sys.argv[1]}/walks.csv")))
got = {(r["gaits"], r["law"], r["gait"]): int(r["steps"]) for r in rows}
want = {("points", "computed_torque", "v0.450_L0.350_s+0.000"): 20,
        ("points", "computed_torque", "v0.600_L0.350_s+0.000"): 20,
        ("cells", "computed_torque_plan_dsp", "v0.525_L0.35"): 20}
assert got == want, (got, [r["failure"] for r in rows])
summary = {r["gaits"]: r for r in csv.DictReader(open(f"{sys.argv[1]}/summary.csv"))}
assert (summary["points"]["walks"], summary["points"]["walked"]) == ("2", "2"), summary
assert (summary["cells"]["walks"], summary["cells"]["walked"], summary["cells"]["fell"]) == ("1", "1", "0"), summary
md = open(f"{sys.argv[1]}/summary.md").read()
assert "| cell centres (blends) | 250 Hz | +0 | +0 | `computed_torque_plan_dsp` | rigid | 1 | 1 | 0 |" in md, md
PY
bash scripts/library_walks.sh "$build" "$TMP/bad" "$TMP/two.yaml" points/250/0/computed_torque/rigid \
  >"$TMP/log" 2>&1
rc=$?
[[ $rc -eq 2 ]] || fail "a walk without its length error exited $rc"
grep -q "walk 'points/250/0/computed_torque/rigid' is not GAITS/RATE/MASS/LENGTH/LAW/GROUND" "$TMP/log" ||
  fail "bad walk not named: $(cat "$TMP/log")"
echo "library_walks.sh: points and the cell's blend walked and tabled; a bad walk refused"
