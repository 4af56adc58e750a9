#!/usr/bin/env bash
# Failed and interrupted solves: a solve that does not converge or is infeasible
# exits with its documented code (4, 3), names Ipopt's status and the worst violated constraint
# by name, phase and node, writes its point to OUT.failed (marked by FAILED.txt and
# "converged": false) and never touches a previous good result in OUT; a killed run leaves OUT
# whole, and no run leaves staging folders behind.
# Usage: failed_solve_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
OCP="$ROOT/configs/ocp/rabbit_kelly2017.yaml"
OUT="$TMP/result"

# A good result in OUT, fingerprinted, that no later failure may change.
run optimize --config "$OCP" --out "$OUT" --rate 100 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "good solve exited $RC: $(cat "$TMP/err")"
GOOD=$(cat "$OUT"/* | md5sum)
unchanged() { [[ "$(cat "$OUT"/* | md5sum)" == "$GOOD" ]] || fail "$1: OUT was changed"; }

# (a) not converged: an iteration limit of 3.
sed "s|max_iterations: 500|max_iterations: 3|; s|\.\./|$ROOT/configs/|" "$OCP" >"$TMP/short.yaml"
run optimize --config "$TMP/short.yaml" --out "$OUT" --quiet --no-plots
[[ $RC -eq 4 ]] || fail "(a) expected exit 4, got $RC: $(cat "$TMP/err")"
grep -Eq "^error: solver status Maximum_Iterations_Exceeded after 3 iterations; worst violated \
constraint: [a-z_]+ \((ssp|link)[^)]*\): .* outside \[.*\] by [0-9.e+-]+; worst variable bound: .*\
 written to $OUT.failed$" "$TMP/err" || fail "(a) message: $(cat "$TMP/err")"
unchanged "(a)"
[[ -f "$OUT.failed/FAILED.txt" && -f "$OUT.failed/trajectory.csv" ]] || fail "(a) OUT.failed"
grep -q "Maximum_Iterations_Exceeded" "$OUT.failed/FAILED.txt" || fail "(a) FAILED.txt"
check_json "(a) failed summary" "$OUT.failed/summary.json" <<'PY'
assert d["status"] == "Maximum_Iterations_Exceeded" and d["converged"] is False, d["status"]
w = d["worst_violation"]
assert w["constraint"] and w["phase"] in ("ssp", "link") and w["violation"] > 1e-3, w
assert w["violation"] == d["max_violation"] or d["worst_bound_violation"], (w, d["max_violation"])
# the cost is the exported point's, whose terms it sums (the last iterate's had been kept when
# the least-violated point evaluated was exported)
terms = sum(d["cost_terms"]["terms"].values())
assert abs(terms - d["cost"]) <= 1e-9 * abs(d["cost"]), (terms, d["cost"], d.get("point"))
PY

# (a') the five-link default stopped after 3 iterations exports the least-violated point it
# evaluated, not its last iterate: its cost is that point's too.
run optimize --config "$ROOT/configs/ocp/mu2004_walk.yaml" --out "$TMP/five" --quiet --no-plots \
  --set solver.max_iterations=3
[[ $RC -eq 4 ]] || fail "(a') expected exit 4, got $RC: $(cat "$TMP/err")"
check_json "(a') its cost" "$TMP/five.failed/summary.json" <<'PY'
assert d["point"] == "least-violated point evaluated", d["point"]
terms = sum(d["cost_terms"]["terms"].values())
assert abs(terms - d["cost"]) <= 1e-9 * abs(d["cost"]), (terms, d["cost"])
PY

# (b) infeasible: torque limits of 0.1 N m cannot carry RABBIT to the step; Ipopt proves local
# infeasibility (155 iterations, 1.5 s). The touchdown position is what cannot be met.
sed 's/torque_limit: 100/torque_limit: 0.1/' "$ROOT/configs/robots/rabbit.yaml" >"$TMP/weak_robot.yaml"
sed "s|\.\./robots/rabbit.yaml|$TMP/weak_robot.yaml|; s|\.\./|$ROOT/configs/|" "$OCP" >"$TMP/weak.yaml"
run optimize --config "$TMP/weak.yaml" --out "$OUT" --quiet --no-plots
[[ $RC -eq 3 ]] || fail "(b) expected exit 3, got $RC: $(cat "$TMP/err")"
grep -q "^error: solver status Infeasible_Problem_Detected after [0-9]* iterations; worst \
violated constraint: touchdown_position (link, row 0): " "$TMP/err" || fail "(b) $(cat "$TMP/err")"
unchanged "(b)"
check_json "(b) failed summary" "$OUT.failed/summary.json" <<'PY'
assert d["status"] == "Infeasible_Problem_Detected" and d["converged"] is False
w = d["worst_violation"]
assert w["constraint"] == "touchdown_position" and w["phase"] == "link" and w["node"] is None, w
assert w["row"] == 0 and w["violation"] > 0.1, w
PY

# (c) a successful run replaces OUT whole and clears the stale OUT.failed.
run optimize --config "$OCP" --out "$OUT" --rate 50 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(c) exited $RC: $(cat "$TMP/err")"
[[ ! -e "$OUT.failed" ]] || fail "(c) a stale OUT.failed survived a good run"
rows=$(($(wc -l <"$OUT/trajectory.csv") - 1))
[[ $rows -eq 36 ]] || fail "(c) expected 36 rows at 50 Hz over 0.7 s, got $rows"
GOOD=$(cat "$OUT"/* | md5sum)

# (d) a run killed mid-solve leaves the previous OUT whole: RABBIT on 1000 segments takes about
# 10 s (Release), killed after 2 s.
sed "s|segments: 25|segments: 1000|; s|\.\./|$ROOT/configs/|" "$OCP" >"$TMP/long.yaml"
timeout -s KILL 2 "$GAITOPT" optimize --config "$TMP/long.yaml" --out "$OUT" --quiet --no-plots \
  >/dev/null 2>&1
[[ $? -eq 137 ]] || fail "(d) the run was not killed"
unchanged "(d)"

# (f) OUT.failed is cleared only when it holds a failed solve: a converged result named so, here
# the warm start of the next run, is kept by that run's success; and a failure of a run started
# from it is refused rather than written over it (exit 2), the folder left as it was.
run optimize --config "$OCP" --out "$TMP/z.failed" --rate 50 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(f) exited $RC: $(cat "$TMP/err")"
KEPT=$(cat "$TMP/z.failed"/* | md5sum)
run optimize --config "$OCP" --out "$TMP/z" --rate 50 --quiet --no-plots --warm-start "$TMP/z.failed"
[[ $RC -eq 0 && -d "$TMP/z.failed" ]] || fail "(f) a converged z.failed was removed ($RC)"
check_json "(f) the warm start is recorded" "$TMP/z/summary.json" <<'PY'
assert d["warm_start"].endswith("/z.failed"), d.get("warm_start")
PY
run optimize --config "$TMP/short.yaml" --out "$TMP/z" --quiet --no-plots --warm-start "$TMP/z.failed" \
  --set solver.max_iterations=1
[[ $RC -eq 2 ]] || fail "(f) a failure onto its warm start exited $RC: $(cat "$TMP/err")"
[[ "$(cat "$TMP/z.failed"/* | md5sum)" == "$KEPT" ]] || fail "(f) the warm start was changed"

# (e) no staging or temporary files are left anywhere.
leftovers=$(find "$TMP" -name '*.tmp*' -o -name '*.old-*')
[[ -z "$leftovers" ]] || fail "(e) left behind: $leftovers"
echo "failed solve CLI: all checks passed"
