#!/usr/bin/env bash
# End-to-end checks of `gaitopt compare`: the report of two gait folders, of three (Mu's
# polynomial gait, the same with its hip searched for the foot, and the first again), each named
# for what it is, and exit 2 with the missing file named when a folder is not a gait result.
# Usage: compare_cli_test.sh <path to gaitopt binary> <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"
"$PY" -c "import matplotlib" 2>/dev/null || skip "no matplotlib"
cd "$ROOT" || fail "no repo root $ROOT"

# (a) the polynomial gait against itself at a lower rate: the table's B/A column is 1.
for rate in 1000 200; do
  run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
    --out "$TMP/poly$rate" --rate "$rate" --no-plots
  [[ $RC -eq 0 ]] || fail "poly exited $RC: $(cat "$TMP/err")"
done
run compare "$TMP/poly1000" "$TMP/poly200" --out "$TMP/cmp"
[[ $RC -eq 0 ]] || fail "(a) compare exited $RC: $(cat "$TMP/err")"
for f in comparison.md comparison.png angles_overlay.png torques_overlay.png forces_overlay.png \
  zmp_overlay.png; do
  [[ -s "$TMP/cmp/$f" ]] || fail "(a) $f missing"
done
grep -q "^| step length \[m\] | 0.350 | 0.350 | 1.00 |" "$TMP/cmp/comparison.md" ||
  fail "(a) table: $(cat "$TMP/cmp/comparison.md")"
# Written in cmp.tmp-PID and renamed to cmp when complete: no line names the staging folder.
! grep -q 'cmp\.tmp-' "$TMP/out" || fail "(a) named its staging folder: $(cat "$TMP/out")"

# (a') three folders: a column per gait, each against A, and a first row saying which hip plan each
# polynomial gait has (Mu's own design, or searched for the foot).
run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004_zmp.yaml \
  --out "$TMP/zmp" --no-plots
[[ $RC -eq 0 ]] || fail "(a') poly exited $RC: $(cat "$TMP/err")"
run compare "$TMP/poly1000" "$TMP/zmp" "$TMP/poly200" --out "$TMP/cmp3"
[[ $RC -eq 0 ]] || fail "(a') compare exited $RC: $(cat "$TMP/err")"
grep -qxF "| quantity | A: $TMP/poly1000 | B: $TMP/zmp | C: $TMP/poly200 | B/A | C/A |" \
  "$TMP/cmp3/comparison.md" || fail "(a') header: $(head -1 "$TMP/cmp3/comparison.md")"
grep -qF "| gait | polynomial, Mu's hip plan (DSP ZMP), mu2004.yaml | polynomial, hip searched for the foot (SSP ZMP), mu2004_zmp.yaml | polynomial, Mu's hip plan (DSP ZMP), mu2004.yaml |" \
  "$TMP/cmp3/comparison.md" || fail "(a') gait row: $(sed -n 3p "$TMP/cmp3/comparison.md")"
grep -q "^| step length \[m\] | 0.350 | 0.350 | 0.350 | 1.00 | 1.00 |" "$TMP/cmp3/comparison.md" ||
  fail "(a') table: $(cat "$TMP/cmp3/comparison.md")"
run compare "$TMP/poly1000" --out "$TMP/cmp1"
[[ $RC -eq 2 ]] || fail "(a') one folder: expected exit 2, got $RC"

# (b) a folder without a trajectory: exit 2 naming the file.
mkdir -p "$TMP/empty"
run compare "$TMP/poly1000" "$TMP/empty" --out "$TMP/cmp2"
[[ $RC -eq 2 ]] || fail "(b) expected exit 2, got $RC"
grep -q "empty/summary.json.*missing" "$TMP/err" || fail "(b) $(cat "$TMP/err")"
# (c) a trajectory.csv cut short (its summary.json says where the grid ends): exit 2 naming it,
# as simulate refuses it, rather than overlay a step that jumps to the stored end state.
cp -r "$TMP/poly1000" "$TMP/cut" && head -n 200 "$TMP/poly1000/trajectory.csv" >"$TMP/cut/trajectory.csv"
run compare "$TMP/poly1000" "$TMP/cut" --out "$TMP/cmp_cut"
[[ $RC -eq 2 ]] || fail "(c) expected exit 2, got $RC: $(cat "$TMP/err")"
grep -q "cut/trajectory.csv: 199 row(s) on the grid, but .* makes 701: a truncated or edited file" \
  "$TMP/err" || fail "(c) $(cat "$TMP/err")"
[[ ! -e "$TMP/cmp_cut" ]] || fail "(c) a comparison was written"
echo "compare CLI: all checks passed"
