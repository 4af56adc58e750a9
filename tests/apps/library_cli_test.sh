#!/usr/bin/env bash
# End-to-end checks of `gaitopt library` on a tiny library of RABBIT (Kelly 2017, 8 segments):
# 3 speeds x 1 step length all converge and are indexed; a rerun has nothing to do; a lost row
# and a torn last line are solved again, and only they; a failed point is skipped on rerun and
# solved with --retry-failed; a solve that cannot converge is listed with its status and
# folder; another grid in the same folder and a bad config exit 2; --set replaces a value of the
# library config and is recorded; `gaitopt interpolate`
# blends two solved points and refuses a query off the grid.
# With a third argument `mpi`: instead, the same library on two MPI ranks gives the same rows
# as on one process.
# Usage: library_cli_test.sh <path to gaitopt binary> <repo root> [mpi]
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt-mpi "$@"
MODE=${3:-}
cd "$ROOT" || fail "no repo root $ROOT"
# No pictures: python would take longer than the solves.
export GAITOPT_SCRIPTS="$TMP/no_scripts"
NAMES="v0.600_L0.500_s+0.000 v0.700_L0.500_s+0.000 v0.800_L0.500_s+0.000"

# The base problem: RABBIT with 8 segments (about 0.1 s a solve), paths made absolute.
sed "s|segments: 25|segments: 8|; s|\.\./|$ROOT/configs/|" configs/ocp/rabbit_kelly2017.yaml \
  >"$TMP/rabbit8.yaml"
grep -q "segments: 8" "$TMP/rabbit8.yaml" || fail "rabbit8.yaml: no segments line to edit"
# library NAME OCP SPEEDS: a library YAML in $TMP/NAME.yaml.
library() {
  printf 'name: %s\nocp: %s\ngrid:\n  speed: %s\n' "$1" "$2" "$3" >"$TMP/$1.yaml"
}
library tiny rabbit8.yaml "[0.6, 0.7, 0.8]"

# check_index NAME DIR SOLVED FAILED: index.json counts, and every row converged as it says.
check_index() {
  EXPECT_SOLVED=$3 EXPECT_FAILED=$4 check_json "$1 index.json" "$2/index.json" <<'PY'
import os
solved, failed = int(os.environ["EXPECT_SOLVED"]), int(os.environ["EXPECT_FAILED"])
assert d["points_total"] == 3, d["points_total"]
assert (d["points_solved"], d["points_failed"]) == (solved, failed), (d["points_solved"], d["points_failed"])
assert len(d["points"]) == solved + failed
assert d["axes"]["speed"] == [0.6, 0.7, 0.8] and d["axes"]["step_length"] == [0.5], d["axes"]
assert d["axes"]["slope"] == [0.0], d["axes"]
assert d["last_run"]["points_per_second"] >= 0, d["last_run"]
for p in d["points"]:
    if p["converged"]:
        assert p["status"] == "Solve_Succeeded" and p["iterations"] > 0, p
        assert 0 < p["cost_of_transport"] < 10 and p["poly_cost_of_transport"] > 0, p
PY
}

if [[ $MODE == mpi ]]; then
  command -v mpirun >/dev/null || skip "no mpirun"
  run library --config "$TMP/tiny.yaml" --out "$TMP/one" --jobs 2 --quiet
  [[ $RC -eq 0 ]] || fail "(mpi) one-process run exited $RC: $(cat "$TMP/err")"
  mpirun --allow-run-as-root --oversubscribe -np 2 "$GAITOPT" library --config "$TMP/tiny.yaml" \
    --out "$TMP/two" --quiet >"$TMP/out" 2>"$TMP/err"
  RC=$?
  [[ $RC -eq 0 ]] || fail "(mpi) mpirun exited $RC: $(cat "$TMP/err")"
  grep -q "on 2 workers" "$TMP/out" || fail "(mpi) not 2 workers: $(cat "$TMP/out")"
  check_index "(mpi)" "$TMP/two" 3 0
  "$PY" - "$TMP/one/index.csv" "$TMP/two/index.csv" <<'PY' || fail "(mpi) rows differ"
import csv, sys
one, two = ({r["point"]: r for r in csv.DictReader(open(p))} for p in sys.argv[1:])
assert sorted(one) == sorted(two) and len(one) == 3, (sorted(one), sorted(two))
for name, a in one.items():
    b = two[name]
    assert a["converged"] == b["converged"] == "1", (a, b)
    for key in ("cost", "cost_of_transport", "poly_cost_of_transport"):
        x, y = float(a[key]), float(b[key])
        assert abs(x - y) <= 1e-6 * max(abs(x), abs(y)), (name, key, x, y)
PY
  for p in $NAMES; do
    [[ -s "$TMP/two/points/$p/trajectory.csv" ]] || fail "(mpi) no trajectory for $p"
  done
  echo "library MPI CLI: all checks passed"
  exit 0
fi

# (a) the tiny library: 3 points solved from the root (0.7 m/s, the base speed 0.714), the
# others warm-started from it.
L="$TMP/lib"
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
[[ $RC -eq 0 ]] || fail "(a) exited $RC: $(cat "$TMP/err")"
grep -q "^library: 3 of 3 points to solve on 2 workers$" "$TMP/out" || fail "(a) $(cat "$TMP/out")"
grep -q "^library: 3 points solved, 0 failed in" "$TMP/out" || fail "(a) $(cat "$TMP/out")"
[[ $(wc -l <"$L/index.csv") -eq 4 ]] || fail "(a) index.csv: $(cat "$L/index.csv")"
head -n 1 "$L/index.csv" | grep -qx "point,speed,step_length,slope,status,converged,cost,\
cost_of_transport,poly_cost_of_transport,iterations,solve_time_s,start,message" ||
  fail "(a) header: $(head -n 1 "$L/index.csv")"
check_index "(a)" "$L" 3 0
check_json "(a) starts" "$L/index.json" <<'PY'
start = {p["point"]: p["start"] for p in d["points"]}
assert start["v0.700_L0.500_s+0.000"] == "polynomial", start
assert start["v0.600_L0.500_s+0.000"] == "warm:v0.700_L0.500_s+0.000", start
assert start["v0.800_L0.500_s+0.000"] == "warm:v0.700_L0.500_s+0.000", start
# Faster walking costs more torque; the cost of transport of the optimum beats the polynomial.
cost = {p["speed"]: p["cost"] for p in d["points"]}
assert cost[0.6] < cost[0.7] < cost[0.8], cost
for p in d["points"]:
    assert p["cost_of_transport"] < p["poly_cost_of_transport"], p
PY
for p in $NAMES; do
  [[ -s "$L/points/$p/trajectory.csv" && -s "$L/points/$p/summary.json" ]] || fail "(a) $p files"
done
check_json "(a) claim" "$L/library.json" <<'PY'
assert d["name"] == "tiny" and d["axes"]["speed"] == [0.6, 0.7, 0.8], d
PY
cp "$L/index.csv" "$TMP/index_a.csv"

# (a') interpolate: halfway between two solved speeds the corners weigh 1/2 each and the step
# lasts step_length / speed; outside the grid exits 3; a folder that is no library exits 2. The
# library's one step length may be left out; the query and the export contract's verdict are
# recorded.
run interpolate --library "$L" --speed 0.65 --out "$TMP/mid" --no-plots
[[ $RC -eq 0 ]] || fail "(a') interpolate exited $RC: $(cat "$TMP/err")"
check_json "(a') interpolate" "$TMP/mid/summary.json" <<'PY'
assert d["query"] == {"speed": 0.65, "step_length": 0.5, "slope": 0.0}, d["query"]
assert "breaches" in d["between_nodes"], d["between_nodes"]
w = sorted((c["point"], c["weight"]) for c in d["library_corners"])
assert [p for p, _ in w] == ["v0.600_L0.500_s+0.000", "v0.700_L0.500_s+0.000"], w
assert all(abs(x - 0.5) < 1e-12 for _, x in w), w
assert abs(d["duration"] - 0.5 / 0.65) < 1e-9, d["duration"]
# RABBIT's steps end in its single impact, which a blend does not keep: the torques recomputed
# from the blended motion load its passive ankle, and the step does not close on itself.
assert d["unactuated_torque_Nm"] > 1e-3 and d["periodicity_error"] > 1e-6, d
PY
grep -q "warning: the blend needs .* N m at a joint without an actuator" "$TMP/err" ||
  fail "(a') no warning of the loaded passive ankle: $(cat "$TMP/err")"
grep -q "warning: the blended step does not close on itself" "$TMP/err" ||
  fail "(a') no warning of the open step: $(cat "$TMP/err")"
run interpolate --library "$L" --step-length 0.5 --out "$TMP/nospeed" --no-plots
[[ $RC -eq 2 ]] && grep -q -- "--speed: the library has 3 values of it, from 0.6 to 0.8" "$TMP/err" ||
  fail "(a') a speed left out of a library of three exited $RC: $(cat "$TMP/err")"
run interpolate --library "$L" --speed 0.65 --at foo --out "$TMP/atfoo" --no-plots
[[ $RC -eq 2 ]] && grep -q -- "--at: key 'foo': expected KEY=VALUE, e.g. --at" "$TMP/err" ||
  fail "(a') --at without '=' exited $RC: $(cat "$TMP/err")"
run interpolate --library "$L" --speed 0.65 --at a.b=1 --at a.b=2 --out "$TMP/attwice" --no-plots
[[ $RC -eq 2 ]] && grep -q "given twice" "$TMP/err" ||
  fail "(a') a key given twice to --at exited $RC: $(cat "$TMP/err")"
run interpolate --library "$L" --speed 0.9 --step-length 0.5 --out "$TMP/far" --no-plots
[[ $RC -eq 3 ]] || fail "(a') outside the grid exited $RC: $(cat "$TMP/err")"
grep -q "speed 0.9 is outside the library's range \[0.6, 0.8\]" "$TMP/err" || fail "(a') $(cat "$TMP/err")"
run interpolate --library "$TMP" --speed 0.7 --step-length 0.5 --out "$TMP/none" --no-plots
[[ $RC -eq 2 ]] || fail "(a') not a library exited $RC"
# A solved point whose trajectory.csv is gone: a damaged library (exit 2 naming the file), not
# a point without a gait (exit 3).
cp -r "$L" "$TMP/damaged" && rm "$TMP/damaged/points/"*/trajectory.csv
run interpolate --library "$TMP/damaged" --speed 0.65 --step-length 0.5 --out "$TMP/dmg" --no-plots
[[ $RC -eq 2 ]] && grep -q "trajectory.csv: missing beside its summary.json" "$TMP/err" ||
  fail "(a') damaged library exited $RC: $(cat "$TMP/err")"

# A point's gait is the point's: a folder copied over another point's, or a gait without its
# summary, is a damaged library (exit 2), not a gait to blend; and a file the points were solved
# from, edited since (here the OCP config beside a copy of the library), is refused by name.
cp -r "$L" "$TMP/copied" && rm -r "$TMP/copied/points/v0.700_L0.500_s+0.000" &&
  cp -r "$TMP/copied/points/v0.600_L0.500_s+0.000" "$TMP/copied/points/v0.700_L0.500_s+0.000"
run interpolate --library "$TMP/copied" --speed 0.65 --step-length 0.5 --out "$TMP/cp" --no-plots
[[ $RC -eq 2 ]] && grep -q "v0.700_L0.500_s+0.000/trajectory.csv: a step of 0.5 m in 0.833333 s" \
  "$TMP/err" || fail "(a') a copied point exited $RC: $(cat "$TMP/err")"
cp -r "$L" "$TMP/nosummary" && rm "$TMP/nosummary/points/v0.600_L0.500_s+0.000/summary.json"
run interpolate --library "$TMP/nosummary" --speed 0.65 --step-length 0.5 --out "$TMP/ns" --no-plots
[[ $RC -eq 2 ]] && grep -q "summary.json: missing beside its trajectory.csv" "$TMP/err" ||
  fail "(a') a point without its summary exited $RC: $(cat "$TMP/err")"
mkdir -p "$TMP/moved" && cp -r "$L" "$TMP/moved/" && cp "$TMP/rabbit8.yaml" "$TMP/moved/" &&
  echo "# edited" >>"$TMP/moved/rabbit8.yaml"
run interpolate --library "$TMP/moved/$(basename "$L")" --speed 0.65 --step-length 0.5 \
  --out "$TMP/mv" --no-plots
[[ $RC -eq 2 ]] && grep -q "rabbit8.yaml has changed since the library was solved" "$TMP/err" ||
  fail "(a') an edited OCP config exited $RC: $(cat "$TMP/err")"

# An edited library.json (an axis gone, or not increasing) is refused by name, not read as
# another grid or reported as a JSON library's exception.
cp -r "$L" "$TMP/edited" && "$PY" - "$TMP/edited/library.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); d["axes"]["speed"] = [0.8, 0.6]; json.dump(d, open(sys.argv[1], "w"))
PY
run interpolate --library "$TMP/edited" --speed 0.65 --step-length 0.5 --out "$TMP/ed" --no-plots
[[ $RC -eq 2 ]] && grep -q "library.json: key 'axes.speed': expected an increasing list" "$TMP/err" ||
  fail "(a') an edited library.json exited $RC: $(cat "$TMP/err")"

# A copy of a shipped library elsewhere finds its base problem among the shipped configs, by
# the contents library.json recorded (its path relative to the folder no longer leads there).
printf 'name: shipped\nocp: %s\ngrid:\n  speed: [0.6, 0.7]\n' "$ROOT/configs/ocp/rabbit_kelly2017.yaml" \
  >"$TMP/shipped.yaml"
run library --config "$TMP/shipped.yaml" --out "$TMP/shipped" --jobs 1 --quiet
[[ $RC -eq 0 ]] || fail "(a') the shipped problem's library exited $RC: $(cat "$TMP/err")"
mkdir -p "$TMP/far/away" && cp -r "$TMP/shipped" "$TMP/far/away/"
run interpolate --library "$TMP/far/away/shipped" --speed 0.65 --step-length 0.5 \
  --out "$TMP/far_mid" --no-plots
[[ $RC -eq 0 ]] || fail "(a') a moved library of a shipped problem exited $RC: $(cat "$TMP/err")"

# (b) a rerun has nothing to do and leaves index.csv as it was.
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
[[ $RC -eq 0 ]] || fail "(b) exited $RC: $(cat "$TMP/err")"
grep -q "^library: 0 of 3 points to solve" "$TMP/out" || fail "(b) $(cat "$TMP/out")"
cmp -s "$L/index.csv" "$TMP/index_a.csv" || fail "(b) index.csv changed"
check_index "(b)" "$L" 3 0

# (c) resume after a kill: the 0.6 row lost and the 0.8 row torn (no newline, cut short). Only
# those two are solved again, warm from the 0.7 point; the torn fragment is not a row.
{
  head -n 1 "$TMP/index_a.csv"
  grep "^v0.700" "$TMP/index_a.csv"
  grep "^v0.800" "$TMP/index_a.csv" | head -c 40
} >"$L/index.csv"
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
[[ $RC -eq 0 ]] || fail "(c) exited $RC: $(cat "$TMP/err")"
grep -q "^library: 2 of 3 points to solve" "$TMP/out" || fail "(c) $(cat "$TMP/out")"
solved=$(grep -o '^library: \[[0-9]/2\] [^:]*' "$TMP/out" | sed 's/.*\] //' | sort | tr '\n' ' ')
[[ $solved == "v0.600_L0.500_s+0.000 v0.800_L0.500_s+0.000 " ]] || fail "(c) solved: $solved"
check_index "(c)" "$L" 3 0
"$PY" - "$L/index.csv" <<'PY' || fail "(c) index.csv: $(cat "$L/index.csv")"
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
full = [r for r in rows[1:] if len(r) == len(rows[0])]
assert sorted(r[0] for r in full) == ["v0.600_L0.500_s+0.000", "v0.700_L0.500_s+0.000",
                                      "v0.800_L0.500_s+0.000"], rows
assert all(r[11] == "warm:v0.700_L0.500_s+0.000" for r in full if not r[0].startswith("v0.700")), full
PY
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
grep -q "^library: 0 of 3 points to solve" "$TMP/out" || fail "(c) rerun: $(cat "$TMP/out")"

# (d) a failed point (0.8 marked converged=0, as a failed solve leaves it) is skipped by a
# rerun and solved again with --retry-failed.
sed -i 's/^\(v0\.800_L0\.500_s+0\.000,[^,]*,[^,]*,[^,]*,\)[^,]*,1,/\1Maximum_Iterations_Exceeded,0,/' \
  "$L/index.csv"
grep -q "^v0.800.*,Maximum_Iterations_Exceeded,0," "$L/index.csv" || fail "(d) edit: $(cat "$L/index.csv")"
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
[[ $RC -eq 0 ]] || fail "(d) exited $RC: $(cat "$TMP/err")"
grep -q "^library: 0 of 3 points to solve" "$TMP/out" || fail "(d) failed point redone: $(cat "$TMP/out")"
check_index "(d) skipped" "$L" 2 1
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2 --retry-failed
[[ $RC -eq 0 ]] || fail "(d) retry exited $RC: $(cat "$TMP/err")"
grep -q "^library: 1 of 3 points to solve" "$TMP/out" || fail "(d) retry: $(cat "$TMP/out")"
grep -q "^library: \[1/1\] v0.800_L0.500_s+0.000: " "$TMP/out" || fail "(d) retry: $(cat "$TMP/out")"
check_index "(d) retried" "$L" 3 0
# A point whose last row is an error (a full disk, a worker killed twice: a failure of the run,
# not of the solver) left by an earlier run: the rerun says it is not solved (exit 1, naming it;
# it said the library was complete, exit 0), and --retry-failed redoes it.
sed -i 's/^\(v0\.800_L0\.500_s+0\.000,[^,]*,[^,]*,[^,]*,\)[^,]*,1,/\1error,0,/' "$L/index.csv"
grep -q "^v0.800.*,error,0," "$L/index.csv" || fail "(d) edit to error: $(cat "$L/index.csv")"
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2
[[ $RC -eq 1 ]] && grep -q "1 point(s) ended in an error in an earlier run and are not solved (the first: v0.800_L0.500_s+0.000: .*rerun with --retry-failed" "$TMP/err" ||
  fail "(d) an earlier error: exit $RC: $(cat "$TMP/err")"
run library --config "$TMP/tiny.yaml" --out "$L" --jobs 2 --retry-failed
[[ $RC -eq 0 ]] && grep -q "^library: 1 of 3 points to solve" "$TMP/out" ||
  fail "(d) error redone: $RC $(cat "$TMP/out")"
check_index "(d) error redone" "$L" 3 0

# (e) another grid into the same folder is refused, naming library.json; the index is kept.
library other rabbit8.yaml "[0.6, 0.7]"
cp "$L/index.csv" "$TMP/index_d.csv"
run library --config "$TMP/other.yaml" --out "$L" --jobs 1
[[ $RC -eq 2 ]] || fail "(e) expected exit 2, got $RC: $(cat "$TMP/err")"
grep -q "library.json" "$TMP/err" || fail "(e) message: $(cat "$TMP/err")"
cmp -s "$L/index.csv" "$TMP/index_d.csv" || fail "(e) index.csv changed"

# (f) a solve that cannot converge (3 iterations): listed as failed with its status, its
# folder DIR/points/<point>.failed, and the run still exits 0; the neighbour of a failed root
# starts from the polynomial gait.
sed "s|max_iterations: 500|max_iterations: 3|" "$TMP/rabbit8.yaml" >"$TMP/rabbit8_short.yaml"
printf 'name: short\nocp: rabbit8_short.yaml\ngrid:\n  speed: [0.7, 0.8]\n' >"$TMP/short.yaml"
run library --config "$TMP/short.yaml" --out "$TMP/short" --jobs 1
[[ $RC -eq 0 ]] || fail "(f) exited $RC: $(cat "$TMP/err")"
grep -q "^library: 0 points solved, 2 failed" "$TMP/out" || fail "(f) $(cat "$TMP/out")"
grep -q "FAILED Maximum_Iterations_Exceeded (polynomial)" "$TMP/out" || fail "(f) $(cat "$TMP/out")"
check_json "(f) index.json" "$TMP/short/index.json" <<'PY'
assert d["points_total"] == 2 and d["points_solved"] == 0 and d["points_failed"] == 2, d
for p in d["points"]:
    assert not p["converged"] and p["status"] == "Maximum_Iterations_Exceeded", p
    assert p["start"] == "polynomial" and p["cost_of_transport"] is None, p
    assert p["iterations"] == 3, p
PY
for p in v0.700_L0.500_s+0.000 v0.800_L0.500_s+0.000; do
  [[ -f "$TMP/short/points/$p.failed/FAILED.txt" ]] || fail "(f) no $p.failed folder"
  [[ ! -e "$TMP/short/points/$p" ]] || fail "(f) $p written as solved"
done

# (g) bad configs exit 2 naming the file and key.
printf 'name: bad\nocp: rabbit8.yaml\ngrid:\n  slope: [0, 10]\n' >"$TMP/bad.yaml"
run library --config "$TMP/bad.yaml" --out "$TMP/bad"
[[ $RC -eq 2 ]] || fail "(g) expected exit 2, got $RC: $(cat "$TMP/err")"
grep -q "bad.yaml:4: key 'grid.slope\[1\]'.*degrees?" "$TMP/err" || fail "(g) $(cat "$TMP/err")"
printf 'name: bad\nocp: rabbit8.yaml\ngrid:\n  speed: {from: 0.5, to: 0.9, count: 2.5}\n' >"$TMP/bad.yaml"
run library --config "$TMP/bad.yaml" --out "$TMP/bad"
[[ $RC -eq 2 ]] && grep -q "key 'grid.speed.count'" "$TMP/err" || fail "(g) count: $(cat "$TMP/err")"
run library --config "$TMP/missing.yaml" --out "$TMP/bad"
[[ $RC -eq 2 ]] && grep -q "missing.yaml" "$TMP/err" || fail "(g) missing: $(cat "$TMP/err")"
# A rate too low for the shortest step is refused before any solve, and no folder is claimed at
# it (every point was solved, then refused at its export, and a rerun at a good rate refused).
run library --config "$TMP/tiny.yaml" --out "$TMP/bad" --rate 5
[[ $RC -eq 2 ]] && grep -q "5 Hz samples the 0.625 s step 4 time(s), fewer than the 10" "$TMP/err" ||
  fail "(g) rate: $(cat "$TMP/err")"
# A step beyond the legs' reach anywhere in the grid is refused before any solve (exit 3, as
# optimize), where each such point was an error row and the run exited 1.
printf 'name: far\nocp: rabbit8.yaml\ngrid:\n  speed: [0.6]\n  step_length: [0.5, 3.0]\n' >"$TMP/bad.yaml"
run library --config "$TMP/bad.yaml" --out "$TMP/bad"
[[ $RC -eq 3 ]] && grep -q "key 'step_length': 3 m is out of reach" "$TMP/err" ||
  fail "(g) reach: exit $RC: $(cat "$TMP/err")"
# One key dotted and nested: solved twice under the second's values, plotted and read wrongly.
printf 'name: bad\nocp: rabbit8.yaml\ngrid:\n  speed: [0.7]\n  constraints.rate_limit: [8, 10]\n  constraints: {rate_limit: [6, 12]}\n' >"$TMP/bad.yaml"
run library --config "$TMP/bad.yaml" --out "$TMP/bad"
[[ $RC -eq 2 ]] && grep -q "the key constraints.rate_limit is given twice" "$TMP/err" ||
  fail "(g) key twice: $(cat "$TMP/err")"
[[ ! -e "$TMP/bad" ]] || fail "(g) a bad config created its folder"

# A library of one slope is queried on it by default, as a config key of one value is (it was
# queried at the base problem's slope 0 and refused).
printf 'name: sl\nocp: rabbit8.yaml\ngrid:\n  speed: [0.6, 0.7]\n  step_length: [0.5]\n  slope: [0.05]\n' >"$TMP/sl.yaml"
run library --config "$TMP/sl.yaml" --out "$TMP/sl" --jobs 1 --quiet
[[ $RC -eq 0 ]] || fail "(g') a slope library exited $RC: $(cat "$TMP/err")"
run interpolate --library "$TMP/sl" --speed 0.65 --step-length 0.5 --out "$TMP/sl_mid" --no-plots
[[ $RC -eq 0 ]] || fail "(g') interpolate on its one slope exited $RC: $(cat "$TMP/err")"
check_json "(g') one slope" "$TMP/sl_mid/summary.json" <<'PY'
assert abs(d["slope_rad"] - 0.05) < 1e-12, d["slope_rad"]
PY

# (h) --set replaces a value of the library config, checked as the file is and recorded in each
# point's summary.json; a bad value exits 2 naming --set and creates nothing.
run library --config "$TMP/tiny.yaml" --set "grid.speed=[0.7]" --out "$TMP/set" --jobs 1 --quiet
[[ $RC -eq 0 ]] || fail "(h) exited $RC: $(cat "$TMP/err")"
check_json "(h) index.json" "$TMP/set/index.json" <<'PY'
assert d["points_total"] == 1 and d["axes"]["speed"] == [0.7], d["axes"]
PY
check_json "(h) point summary" "$TMP/set/points/v0.700_L0.500_s+0.000/summary.json" <<'PY'
assert d["config_overrides"] == ["grid.speed=[0.7]"], d.get("config_overrides")
PY
run library --config "$TMP/tiny.yaml" --set "grid.speed=fast" --out "$TMP/set_bad"
[[ $RC -eq 2 ]] && grep -q "(--set grid.speed=fast).*key 'grid.speed'" "$TMP/err" ||
  fail "(h) bad value: $RC $(cat "$TMP/err")"
[[ ! -e "$TMP/set_bad" ]] || fail "(h) a bad --set created its folder"

# (i) a grid axis over a config key of the base problem (here the friction margin, with the
# ground-contact rows on so the cones bind; given nested, as --set spells it): every point keeps
# its tip forces inside its own narrowed cone (mu 0.8 less the margin), the cone binds at 0.5
# and costs torque, each point's summary records its value, and interpolate blends along it.
sed "s|ground_contact: false.*|ground_contact: true|" "$TMP/rabbit8.yaml" >"$TMP/rabbit8_contact.yaml"
printf 'name: margin
ocp: rabbit8_contact.yaml
grid:
  speed: 0.7
  constraints: {friction_margin: [0.0, 0.5]}
' \
  >"$TMP/margin.yaml"
run library --config "$TMP/margin.yaml" --out "$TMP/margin" --jobs 2 --quiet
[[ $RC -eq 0 ]] || fail "(i) exited $RC: $(cat "$TMP/err")"
head -n 1 "$TMP/margin/index.csv" | grep -q "^point,speed,step_length,slope,constraints.friction_margin,status," ||
  fail "(i) header: $(head -n 1 "$TMP/margin/index.csv")"
"$PY" - "$TMP/margin" <<'PY' || fail "(i) points"
import json, sys
root = sys.argv[1]
index = json.load(open(f"{root}/index.json"))
assert index["axes"]["constraints.friction_margin"] == [0.0, 0.5], index["axes"]
cost = {}
for p in index["points"]:
    assert p["converged"], p
    margin = p["config_values"][0]
    s = json.load(open(f"{root}/points/{p['point']}/summary.json"))
    assert s["config_overrides"] == [f"constraints.friction_margin={margin:g}"], s["config_overrides"]
    for ratio in (s["max_friction_ratio"], s["between_nodes"]["max_friction_ratio"]):
        assert ratio <= 0.8 - margin + 2e-3, (margin, ratio)
    cost[margin] = p["cost"]
# Without a margin the optimum leans on 0.36 of its normal force; a cone of 0.3 costs torque.
assert cost[0.5] > 1.05 * cost[0.0], cost
PY
run interpolate --library "$TMP/margin" --speed 0.7 --step-length 0.5 \
  --at constraints.friction_margin=0.125 --out "$TMP/margin_mid" --no-plots
[[ $RC -eq 0 ]] || fail "(i) interpolate exited $RC: $(cat "$TMP/err")"
check_json "(i) interpolate" "$TMP/margin_mid/summary.json" <<'PY'
w = sorted(c["weight"] for c in d["library_corners"])
assert len(w) == 2 and abs(w[0] - 0.25) < 1e-12 and abs(w[1] - 0.75) < 1e-12, w
PY
run interpolate --library "$TMP/margin" --speed 0.7 --step-length 0.5 --out "$TMP/margin_no" --no-plots
[[ $RC -eq 2 ]] && grep -q "give --at constraints.friction_margin=VALUE" "$TMP/err" ||
  fail "(i) no --at: $RC $(cat "$TMP/err")"
# The same axis from the command line, on the library of (a).
run library --config "$TMP/tiny.yaml" --set "grid.speed=0.7" \
  --set "grid.constraints.friction_margin=[0.05, 2]" --out "$TMP/margin_bad"
[[ $RC -eq 2 ]] && grep -q "grid.constraints.friction_margin.*refuses 2" "$TMP/err" ||
  fail "(i) bad margin: $RC $(cat "$TMP/err")"
# (j) A point the polynomial gait does not reach directly is solved along the base config's
# continuation: here Ipopt gets 8 iterations a solve, which RABBIT-8 needs 14 of, and the
# continuation's retry from its best iterate finishes the path. Without it the point failed.
cp "$TMP/rabbit8.yaml" "$TMP/rabbit8c.yaml" &&
  printf 'continuation:\n  parameters: none\n  steps: 1\n' >>"$TMP/rabbit8c.yaml"
sed -i "s|max_iterations: 500|max_iterations: 8|" "$TMP/rabbit8c.yaml"
grep -q "max_iterations: 8" "$TMP/rabbit8c.yaml" || fail "(j) no max_iterations line to edit"
library cont rabbit8c.yaml "[0.7]"
run library --config "$TMP/cont.yaml" --out "$TMP/cont" --jobs 1 --quiet
[[ $RC -eq 0 ]] || fail "(j) exited $RC: $(cat "$TMP/err")"
POINT_A="$L/index.json" check_json "(j) continuation" "$TMP/cont/index.json" <<'PY'
import os
(p,) = d["points"]
assert p["converged"] and p["start"] == "polynomial,continuation", p
assert p["iterations"] > 8, p
# The optimum that (a) reached with Ipopt's full 500 iterations, without a continuation.
(a,) = [q for q in json.load(open(os.environ["POINT_A"]))["points"] if q["point"] == p["point"]]
assert abs(p["cost"] - a["cost"]) < 1e-4 * a["cost"], (p["cost"], a["cost"])
PY
check_json "(j) summary" "$TMP/cont/points/v0.700_L0.500_s+0.000/summary.json" <<'PY'
stages = d["continuation"]["stages"]
assert not stages[0]["converged"] and stages[-1]["converged"], stages
PY
echo "library CLI: all checks passed"
