#!/usr/bin/env bash
# scripts/paired_times.py with a stand-in for gaitopt: a script that sleeps as long as its config
# says, writes a summary.json whose solve time is 1.5 times that sleep and whose cost counts the
# --set pairs it was handed. Then a slow case's ratio to a fast base is the ratio of their sleeps,
# the table and the CSV beside it hold the same figures, and a malformed case, two cases with one
# label and a program that fails all stop with "error: ..." naming what went wrong.
# Usage: paired_times_test.sh <repo root>
# shellcheck source=tests/apps/cli_test_lib.sh
source "$(dirname "$0")/cli_test_lib.sh" root "$@"  # PY, TMP (removed on exit), fail
script="$ROOT/scripts/paired_times.py"

fake="$TMP/fake_gaitopt"
cat >"$fake" <<'SH'
#!/usr/bin/env bash
# fake_gaitopt optimize --config FILE --out DIR ... [--set K=V]...: FILE holds the seconds to sleep.
sets=0
while [[ $# -gt 0 ]]; do
  case $1 in
    --config) config=$2; shift ;;
    --out) out=$2; shift ;;
    --set) sets=$((sets + 1)); shift ;;
  esac
  shift
done
[[ $(cat "$config") == fail ]] && { echo "the stand-in refuses $config" >&2; exit 3; }
seconds=$(cat "$config")
sleep "$seconds"
mkdir -p "$out"
awk -v s="$seconds" -v n="$sets" \
  'BEGIN { printf "{\"wall_time_s\": %.17g, \"iterations\": 7, \"cost\": %d}\n", 1.5 * s, n }' \
  >"$out/summary.json"
SH
chmod +x "$fake"
echo 0.05 >"$TMP/fast.yaml"
echo 0.2 >"$TMP/slow.yaml"
echo fail >"$TMP/bad.yaml"

"$PY" "$script" --runs 3 --out "$TMP/pairs.md" "fast=$fake:$TMP/fast.yaml" \
  "slow=$fake:$TMP/slow.yaml:a=1:b=2" >"$TMP/printed" 2>"$TMP/progress" ||
  fail "exit $? on good cases: $(cat "$TMP/progress")"
has_text "$TMP/progress" "paired_times: round 3 of 3 done" "progress"
has_text "$TMP/printed" "3 rounds after one warm-up" "round count"
has_text "$TMP/printed" "--set a=1 --set b=2" "the slow case's command"
cmp -s "$TMP/printed" "$TMP/pairs.md" || fail "the printed table is not the one written"
"$PY" - "$TMP/pairs.csv" <<'PY' || fail "CSV: $(cat "$TMP/pairs.csv")"
import csv, sys
rows = {r["case"]: r for r in csv.DictReader(open(sys.argv[1]))}
fast, slow = rows["fast"], rows["slow"]
assert float(fast["solve_ratio"]) == 1.0 and float(fast["process_ratio"]) == 1.0, fast
assert abs(float(slow["solve_ratio"]) - 4.0) < 1e-9, slow        # 0.3 s / 0.075 s, every round
assert abs(float(fast["solve_s"]) - 0.075) < 1e-9, fast
assert 1.5 < float(slow["process_ratio"]) < 4.5, slow            # 0.2 s of sleep against 0.05 s
assert float(slow["process_s"]) >= 0.2, slow
assert slow["cost"] == "2" and fast["cost"] == "0", rows          # the --set pairs were handed on
assert slow["iterations"] == "7" and float(slow["peak_mib"]) > 0, slow
PY

expect_error() {  # expect_error WHAT TEXT ARGS...: exits non-zero and prints "error: ...TEXT..."
  local what=$1 text=$2
  shift 2
  "$PY" "$script" --runs 1 "$@" >/dev/null 2>"$TMP/err" && fail "$what: exit 0"
  has_text "$TMP/err" "error:" "$what"
  has_text "$TMP/err" "$text" "$what"
}
expect_error "malformed case" "a case is LABEL=BINARY:CONFIG" "nolabel"
expect_error "shared label" "two cases share a label" "a=$fake:$TMP/fast.yaml" \
  "a=$fake:$TMP/slow.yaml"
expect_error "failing program" "the stand-in refuses" "ok=$fake:$TMP/fast.yaml" \
  "broken=$fake:$TMP/bad.yaml"
has_text "$TMP/err" "broken:" "the failing case's label"
echo "paired_times: ratios, table, CSV and errors as expected"
