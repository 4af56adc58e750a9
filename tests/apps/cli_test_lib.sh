# shellcheck shell=bash
# Shared helpers of the end-to-end tests. Every script starts with one of
#   source "$(dirname "$0")/cli_test_lib.sh" gaitopt "$@"      # <gaitopt binary> <repo root>
#   source "$(dirname "$0")/cli_test_lib.sh" gaitopt-mpi "$@"  # the same and an optional [mpi]
#   source "$(dirname "$0")/cli_test_lib.sh" root "$@"         # <repo root> (the plot tests)
# which checks the script's arguments and sets GAITOPT and ROOT.
set -u
# shellcheck disable=SC2034  # GAITOPT and ROOT are read by the sourcing script
case "$1:$#" in
  gaitopt:3 | gaitopt-mpi:3 | gaitopt-mpi:4)
    GAITOPT=$2
    ROOT=$3
    ;;
  root:2) ROOT=$2 ;;
  *)
    case $1 in
      root) echo "usage: $0 <repo root>" >&2 ;;
      gaitopt) echo "usage: $0 <gaitopt binary> <repo root>" >&2 ;;
      *) echo "usage: $0 <gaitopt binary> <repo root> [mpi]" >&2 ;;
    esac
    exit 1
    ;;
esac
PY=/usr/bin/python3

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# ctest counts a script that exits with SKIP_CODE as skipped, not passed (SKIP_RETURN_CODE in
# tests/CMakeLists.txt). skip REASON ends a script that cannot run here.
SKIP_CODE=77
skip() {
  echo "SKIP: $*"
  exit "$SKIP_CODE"
}

# has_text FILE TEXT WHAT: FILE holds TEXT (a fixed string), else fails naming WHAT with the file.
has_text() {
  grep -qF -- "$2" "$1" || fail "$3: $(cat "$1")"
}

# Runs gaitopt with the given arguments, keeping stdout, stderr and the exit code.
run() {
  "$GAITOPT" "$@" >"$TMP/out" 2>"$TMP/err"
  RC=$?
}

# Runs the Python assertions read from stdin with `d` bound to the JSON in file $2 (default
# $TMP/out); $1 names the check. The snippet comes from a quoted heredoc, so it may use any quotes.
check_json() {
  local name=$1
  local file=${2:-$TMP/out}
  {
    printf '%s\n' "import json, sys" "with open(sys.argv[1]) as f:" "    d = json.load(f)"
    cat
  } >"$TMP/check.py"
  "$PY" "$TMP/check.py" "$file" || fail "$name"
}
