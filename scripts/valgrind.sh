#!/usr/bin/env bash
# Runs one optimise of the small RABBIT benchmark (configs/ocp/rabbit_kelly2017.yaml) under
# valgrind's memcheck and fails on any memory error or leak. Prints valgrind's error
# and leak summary and the wall time.
# Usage: scripts/valgrind.sh BUILD_DIR   (a build of the gaitopt_cli target)
set -euo pipefail

[[ $# -eq 1 ]] || { echo "usage: $0 BUILD_DIR" >&2; exit 2; }
gaitopt="$1/apps/gaitopt"
cd "$(dirname "$0")/.."
[[ -x "$gaitopt" ]] || { echo "valgrind: no $gaitopt; build the gaitopt_cli target first" >&2; exit 2; }
command -v valgrind >/dev/null || bash scripts/install-deps.sh

out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
start=$(date +%s)
status=0
# Every kind of leak is an error: the run frees all its heap blocks (Ipopt, MUMPS and yaml-cpp
# included), so anything left is ours.
valgrind --leak-check=full --errors-for-leak-kinds=all --error-exitcode=1 \
  --suppressions=scripts/valgrind.supp \
  --log-file="$out/valgrind.log" \
  "$gaitopt" optimize --config configs/ocp/rabbit_kelly2017.yaml --out "$out/result" \
  --no-plots --quiet >"$out/stdout" || status=$?
grep -E "ERROR SUMMARY|definitely lost|indirectly lost|possibly lost|still reachable|All heap" \
  "$out/valgrind.log" | sed 's/^==[0-9]*== */valgrind: /'
echo "valgrind: $(($(date +%s) - start)) s, exit $status"
if [[ $status -ne 0 ]]; then
  cat "$out/stdout" "$out/valgrind.log" >&2
  exit 1
fi
