#!/usr/bin/env bash
# The CMake package end to end: `cmake --install` of the build into a temporary prefix (headers,
# static libraries, gaitoptConfig.cmake and its version file), then examples/controller, a
# separate project, configured with find_package(gaitopt) against that prefix only, built, and
# run on the trajectory.csv of a freshly designed gait: it must walk 3 steps on the reference
# (track_gait checks the tracking error and every step's advance), and refuse a broken CSV.
# Usage: find_package_test.sh <build dir> <repo root> <gaitopt binary>
set -u
[[ $# -eq 3 ]] || { echo "usage: $0 <build dir> <repo root> <gaitopt binary>" >&2; exit 1; }
BUILD=$1
ROOT=$2
GAITOPT=$3
# shellcheck source=tests/apps/cli_test_lib.sh
source "$ROOT/tests/apps/cli_test_lib.sh" gaitopt "$GAITOPT" "$ROOT"
cd "$ROOT" || fail "no repo root $ROOT"
GEN=()
command -v ninja >/dev/null && GEN=(-G Ninja)

cmake --install "$BUILD" --prefix "$TMP/prefix" >"$TMP/install.log" 2>&1 ||
  fail "cmake --install: $(tail -5 "$TMP/install.log")"
for f in lib/cmake/gaitopt/gaitoptConfig.cmake lib/cmake/gaitopt/gaitoptConfigVersion.cmake \
         lib/cmake/gaitopt/gaitoptTargets.cmake include/gaitopt/sim/scenario/scenario.hpp \
         include/gaitopt/gaits/trajectory/trajectory_csv.hpp lib/libgaitopt_sim.a bin/gaitopt; do
  [[ -e "$TMP/prefix/$f" ]] || fail "not installed: $f"
done

# Only the prefix: the source tree's own include paths must not leak into the example.
cmake -S examples/controller -B "$TMP/controller" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$TMP/prefix" >"$TMP/configure.log" 2>&1 ||
  fail "configure examples/controller: $(tail -20 "$TMP/configure.log")"
cmake --build "$TMP/controller" >"$TMP/build.log" 2>&1 ||
  fail "build examples/controller: $(tail -30 "$TMP/build.log")"
grep -q -- "-I$ROOT" "$TMP/build.log" && fail "the example compiled against the source tree"

run poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$TMP/poly" --no-plots
[[ $RC -eq 0 ]] || fail "poly exited $RC: $(cat "$TMP/err")"
# The long-heel fixture: the polynomial gait's ZMP leaves the shipped 5 cm heel (tests/apps).
"$TMP/controller/track_gait" tests/apps/mu2004_five_link_long_heel.yaml "$TMP/poly/trajectory.csv" 3 \
  >"$TMP/track.log" 2>&1 || fail "track_gait: $(cat "$TMP/track.log")"
grep -q "3 of 3 steps" "$TMP/track.log" || fail "track_gait: $(cat "$TMP/track.log")"

# A trajectory whose derived columns disagree with its angles is refused by the reader (exit 2).
awk -F, -v OFS=, 'NR == 3 { $3 = $3 + 0.1 } 1' "$TMP/poly/trajectory.csv" >"$TMP/broken.csv"
cmp -s "$TMP/broken.csv" "$TMP/poly/trajectory.csv" && fail "the broken CSV is not broken"
"$TMP/controller/track_gait" configs/robots/mu2004_five_link.yaml "$TMP/broken.csv" 3 \
  >"$TMP/broken.log" 2>&1
rc=$?
[[ $rc -eq 2 ]] || fail "track_gait on a broken CSV exited $rc: $(cat "$TMP/broken.log")"
echo "find_package_test: all checks passed"
