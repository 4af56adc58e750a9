#!/usr/bin/env bash
# The README and docs/ pages against results/: they match (scripts/docs.py check), and a number
# changed by hand in the README, a result regenerated without rendering, or a linked picture
# that a regeneration deleted makes the check fail.
# Usage: docs_test.sh SOURCE_DIR
set -euo pipefail
src="$1"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
docs="/usr/bin/python3 $src/scripts/docs.py"

$docs check --root "$src"

cp -r "$src/docs" "$src/results" "$src/README.md" "$tmp/"
$docs check --root "$tmp"

# A hand edit: the first digit of the README's first table row that holds one.
line="$(grep -n '^|.*[0-9]' "$tmp/README.md" | head -1 | cut -d: -f1)"
[ -n "$line" ] || { echo "FAIL: README has no table with a number"; exit 1; }
sed -i "${line}s/\([0-9]\)/\1\1/" "$tmp/README.md"
if $docs check --root "$tmp" 2>"$tmp/err"; then
  echo "FAIL: a number changed by hand in README.md line $line passed the check"; exit 1
fi
grep -q "README.md:$line differs" "$tmp/err" || { cat "$tmp/err"; echo "FAIL: not named"; exit 1; }

# A result regenerated without rendering: the cost of the optimal gait changes.
cp "$src/README.md" "$tmp/README.md"
/usr/bin/python3 - "$tmp/results/opt_mu2004/summary.json" <<'PY'
import json, sys
p = sys.argv[1]; d = json.load(open(p)); d["cost"] *= 1.5; json.dump(d, open(p, "w"))
PY
if $docs check --root "$tmp" 2>/dev/null; then
  echo "FAIL: a changed result passed the check"; exit 1
fi

# A picture the README shows, deleted (a regeneration once dropped the front page's walk.gif).
cp "$src/results/opt_mu2004/summary.json" "$tmp/results/opt_mu2004/summary.json"
$docs check --root "$tmp" >/dev/null
rm "$tmp/results/opt_mu2004/overview.png"
if $docs check --root "$tmp" 2>"$tmp/err"; then
  echo "FAIL: a README picture that is not there passed the check"; exit 1
fi
grep -q "links results/opt_mu2004/overview.png, which is not there" "$tmp/err" ||
  { cat "$tmp/err"; echo "FAIL: missing picture not named"; exit 1; }
# A range around the nominal writes its ends signed, and a zero end bare (never "+0" or "-0").
/usr/bin/python3 - "$src/scripts" <<'PY'
import sys
sys.path.insert(0, sys.argv[1])
from docs import signed_interval
cases = {(-10, 0, 0): "-10 .. 0", (-0.2, 5, 0): "0 .. +5", (-2.5, 7.5, 1): "-2.5 .. +7.5",
         (0, 0, 0): "0 .. 0", (-0.04, 0.04, 1): "0.0 .. 0.0"}
for (a, b, digits), want in cases.items():
    got = signed_interval(a, b, digits)
    assert got == want, f"signed_interval({a}, {b}, {digits}) = {got!r}, want {want!r}"
PY
# cs(): every matching row's cell, for a range over rows; a filter nothing matches is an error.
printf 'point,converged,cost\na,1,3.5\nb,0,nan\nc,1,2\n' >"$tmp/rows.csv"
/usr/bin/python3 - "$src/scripts" "$tmp" <<'PY'
import pathlib, sys
sys.path.insert(0, sys.argv[1])
from docs import Sources
s = Sources(pathlib.Path(sys.argv[2]))
assert s.csv_values("rows.csv", "cost", converged=1) == [3.5, 2.0], s.csv_values("rows.csv", "cost", converged=1)
try:
    s.csv_values("rows.csv", "cost", converged=2)
except KeyError as e:
    assert "no row matches" in str(e), e
else:
    raise AssertionError("a filter that matches nothing gave values")
PY

echo "docs: check passes on the tree and fails on a hand edit, a stale result and a missing picture"
