# Sourced by the study scripts that take BUILD_DIR OUT_DIR and work in a folder of their own
# (scripts/dart_side_by_side.sh, scripts/ensemble_front.sh, scripts/ensemble_walks.sh,
# scripts/mu_cases.sh), with their arguments: sets `build`, `out` (created), `bin` (the built
# gaitopt, or exit 1 naming it) and `work`, a temporary folder removed when the script exits.
build=${1:?usage: $0 BUILD_DIR OUT_DIR}
out=${2:?usage: $0 BUILD_DIR OUT_DIR}
bin="$build/apps/gaitopt"
[[ -x "$bin" ]] || { echo "error: $bin not built" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
