# shellcheck shell=bash
# The start every `scripts/*.sh BUILD_DIR OUT_DIR` study shares, sourced after `set -euo
# pipefail`: build, out and bin from the arguments (refused when gaitopt is not built), a scratch
# folder $work removed on exit, and OUT made.
build=${1:?usage: $0 BUILD_DIR OUT_DIR}
out=${2:?usage: $0 BUILD_DIR OUT_DIR}
bin="$build/apps/gaitopt"
[[ -x "$bin" ]] || { echo "error: $bin not built" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
