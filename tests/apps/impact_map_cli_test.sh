#!/usr/bin/env bash
# End-to-end checks of `gaitopt impact-map`: outputs, counts, exit codes, determinism over jobs.
# Usage: impact_map_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
ROBOT="$ROOT/configs/robots/mu2004_five_link.yaml"
GRID=(--step-lengths 0.1:0.9:5 --knee-bias 5:45:3 --approach-angles 10:170:9)

# (a) a 5 x 3 x 9 grid with one job: files, row count, counts summing to the grid size.
run impact-map --robot "$ROBOT" --out "$TMP/j1" "${GRID[@]}" --jobs 1 --quiet --no-plots
[[ $RC -eq 0 ]] || fail "(a) impact-map exited $RC: $(cat "$TMP/err")"
[[ -f "$TMP/j1/impact_map.csv" && -f "$TMP/j1/summary.json" ]] || fail "(a) outputs missing"
[[ ! -e "$TMP/j1/impact_map.csv.tmp" ]] || fail "(a) temporary CSV left behind"
rows=$(($(wc -l <"$TMP/j1/impact_map.csv") - 1))
[[ $rows -eq 135 ]] || fail "(a) expected 135 rows, got $rows"
[[ ! -s "$TMP/err" ]] || fail "(a) --quiet still wrote to stderr: $(cat "$TMP/err")"
check_json "(a) summary" "$TMP/j1/summary.json" <<'PY'
assert d["points"] == 135 and sum(d["counts"].values()) == 135, d["counts"]
assert set(d["counts"]) == {"single", "double", "either", "neither"}
assert d["counts"]["single"] > 0 and d["counts"]["double"] > 0, d["counts"]
assert d["grid"]["knee_bias_deg"] == {"first": 5.0, "last": 45.0, "count": 3}
for axis in ("step_length", "knee_bias_deg", "approach_angle_deg"):
    for b in d["boundaries"][axis]:
        assert b["lines"] > 0 and b["min"] <= b["median"] <= b["max"], b
# The complementarity law's types, per type of Mu's criterion, account for every point of it.
lcp = d["lcp_counts_by_mu_type"]
for mu, n in d["counts"].items():
    assert sum(lcp[mu].values()) == n, (mu, lcp[mu], n)
PY

# (b) two jobs give a byte-identical CSV; the progress bar goes to stderr without --quiet.
run impact-map --robot "$ROBOT" --out "$TMP/j2" "${GRID[@]}" --jobs 2 --no-plots
[[ $RC -eq 0 ]] || fail "(b) impact-map exited $RC: $(cat "$TMP/err")"
cmp -s "$TMP/j1/impact_map.csv" "$TMP/j2/impact_map.csv" || fail "(b) --jobs 1 and 2 differ"
grep -q "100% 135/135" "$TMP/err" || fail "(b) no progress bar: $(cat "$TMP/err")"

# (c) bad ranges: exit 2 with a message naming the problem, and no output folder.
bad() {
  local name=$1 pattern=$2
  shift 2
  run impact-map --robot "$ROBOT" --out "$TMP/bad" --quiet --no-plots "$@"
  [[ $RC -eq 2 ]] || fail "($name) expected exit 2, got $RC: $(cat "$TMP/err")"
  grep -q -- "$pattern" "$TMP/err" || fail "($name) message: $(cat "$TMP/err")"
  [[ ! -e "$TMP/bad" ]] || fail "($name) an output folder was created for a bad input"
}
bad c1 "n must be an integer" --step-lengths 0.1:0.9:0
bad c2 "not a finite number" --knee-bias nan:30:3
bad c3 "first < last" --approach-angles 120:60:3
# equal ends and a count above 1: the one point mapped three times, counted three times
bad c3b "first < last, or first = last when count is 1" --approach-angles 90:90:3
bad c4 "--knee-bias: 0..30 deg outside the open range (0, 180) deg" --knee-bias 0:30:4
bad c5 "outside the open range (0, 180) deg" --approach-angles 10:180:5
bad c6 "longer than the legs reach" --step-lengths 0.5:1.3:3
bad c7 "expected a:b:n or a" --step-lengths 0.1:0.9
run impact-map --robot "$ROOT/configs/robots/compass_gait.yaml" --out "$TMP/cg" --quiet --no-plots
[[ $RC -eq 2 ]] && grep -q "needs legs of thigh and shank" "$TMP/err" || fail "(c8) $(cat "$TMP/err")"

# (d) the picture, when matplotlib is installed.
if "$PY" -c "import matplotlib" 2>/dev/null; then
  run impact-map --robot "$ROBOT" --out "$TMP/plot" "${GRID[@]}" --quiet
  [[ $RC -eq 0 && -s "$TMP/plot/impact_map.png" ]] || fail "(d) no picture: $(cat "$TMP/err")"
  # Three rows: Mu's types, his slices and ratios, the complementarity law's types.
  "$PY" -c "import sys, matplotlib.image as im; h, w = im.imread(sys.argv[1]).shape[:2]; assert h > 0.7 * w, (w, h)" \
    "$TMP/plot/impact_map.png" || fail "(d) expected the complementarity row"
  run impact-map --robot "$ROBOT" --out "$TMP/plot" "${GRID[@]}" --quiet
  [[ $RC -eq 0 ]] || fail "(d) rerun into its own folder: exit $RC: $(cat "$TMP/err")"
fi
echo "impact-map CLI: all checks passed"
