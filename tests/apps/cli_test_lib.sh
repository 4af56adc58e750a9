# Shared helpers of the CLI end-to-end tests: sourced after GAITOPT and ROOT are set.
PY=/usr/bin/python3

TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
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
