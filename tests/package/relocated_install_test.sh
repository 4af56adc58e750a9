#!/usr/bin/env bash
# An installed tree needs no source tree (io/data_dir.hpp): `cmake --install` of the build into a
# temporary prefix, the prefix moved elsewhere, and the source tree (which holds the build tree)
# hidden under an empty tmpfs in a private mount namespace, as if the checkout were deleted. The
# moved tool then optimises a shipped config with its pictures, walks the result on the shipped
# rigid ground with the robot its summary.json names, and makes the report page with the GIF; the
# installed Python module imports from the moved prefix and solves RABBIT.
# Needs root for the mount namespace: skipped (ctest counts it) where it cannot make one.
# Usage: relocated_install_test.sh <build dir> <repo root> <gaitopt binary>
set -u
[[ $# -eq 3 ]] || { echo "usage: $0 <build dir> <repo root> <gaitopt binary>" >&2; exit 1; }
BUILD=$1
ROOT=$2
# shellcheck source=tests/apps/cli_test_lib.sh
source "$ROOT/tests/apps/cli_test_lib.sh" gaitopt "$3" "$ROOT"
unshare --mount --propagation private true 2>/dev/null ||
  skip "cannot make a mount namespace here (not root?)"
cmake --install "$BUILD" --prefix "$TMP/prefix" >"$TMP/install.log" 2>&1 ||
  fail "cmake --install: $(tail -5 "$TMP/install.log")"
mv "$TMP/prefix" "$TMP/moved"
for f in share/gaitopt/configs/ocp/rabbit_kelly2017.yaml share/gaitopt/configs/grounds/rigid.yaml \
         share/gaitopt/plots/gait_plots.py; do
  [[ -f "$TMP/moved/$f" ]] || fail "not installed: $f"
done
mkdir "$TMP/work"
# A program of another project, built against the moved package, reads the shipped configs from
# it, not from the source tree the package was built from (io/data_dir.hpp).
mkdir "$TMP/consumer"
cat >"$TMP/consumer/CMakeLists.txt" <<'CM'
cmake_minimum_required(VERSION 3.25)
project(data_dir_consumer LANGUAGES CXX)
set(CMAKE_CXX_STANDARD 20)
find_package(gaitopt 0.1 REQUIRED)
add_executable(shipped_ground shipped_ground.cpp)
target_link_libraries(shipped_ground PRIVATE gaitopt::sim)
CM
cat >"$TMP/consumer/shipped_ground.cpp" <<'CPP'
#include <iostream>
#include "io/data_dir.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/scenario/scenario_settings.hpp"
int main() {
  std::cout << gaitopt::io::dataDir() << '\n';
  gaitopt::sim::loadGround(gaitopt::sim::groundPath("rigid"));  // throws when it is not there
}
CPP
GEN=()
command -v ninja >/dev/null && GEN=(-G Ninja)
cmake -S "$TMP/consumer" -B "$TMP/consumer/build" "${GEN[@]}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$TMP/moved" >"$TMP/consumer.log" 2>&1 &&
  cmake --build "$TMP/consumer/build" >>"$TMP/consumer.log" 2>&1 ||
  fail "the consumer project: $(tail -20 "$TMP/consumer.log")"
# The checks run inside the namespace, where $ROOT is an empty folder.
unshare --mount --propagation private bash -s "$ROOT" "$TMP" <<'SH' || fail "see above"
set -u
ROOT=$1 TMP=$2
G="$TMP/moved/bin/gaitopt"
mount -t tmpfs -o size=1m tmpfs "$ROOT" || { echo "FAIL: cannot hide $ROOT"; exit 1; }
[[ -z $(ls -A "$ROOT") ]] || { echo "FAIL: $ROOT is not hidden"; exit 1; }
cd "$TMP/work" || exit 1
check() { # check NAME COMMAND...: runs it, fails with its output unless it exits 0
  local name=$1
  shift
  "$@" >out.log 2>err.log || { echo "FAIL: $name exited $?: $(tail -5 err.log)"; exit 1; }
  ! grep -q "warning" err.log || { echo "FAIL: $name warned: $(cat err.log)"; exit 1; }
}
check consumer "$TMP/consumer/build/shipped_ground"
[[ $(cat out.log) == "$TMP/moved/share/gaitopt" ]] || { echo "FAIL: consumer: $(cat out.log)"; exit 1; }
check optimize "$G" optimize --config "$TMP/moved/share/gaitopt/configs/ocp/rabbit_kelly2017.yaml" \
  --out opt --rate 200 --quiet
[[ -f opt/trajectory.csv && -f opt/overview.png ]] || { echo "FAIL: optimize: no pictures"; exit 1; }
# The pictures are drawn in the staging folder opt.tmp-PID, renamed to opt when complete: no
# line may name it.
! grep -q 'opt\.tmp-' out.log || { echo "FAIL: optimize named its staging folder: $(cat out.log)"; exit 1; }
# A configs/... path as the docs spell it names the shipped file: there is no configs/ here.
check shipped "$G" optimize --config configs/ocp/rabbit_kelly2017.yaml --out opt_shipped --rate 200 \
  --quiet --no-plots
[[ -f opt_shipped/trajectory.csv ]] || { echo "FAIL: optimize of the shipped config"; exit 1; }
check state "$G" inspect --robot configs/robots/mu2004_five_link.yaml \
  --state configs/states/mu2004_table41.json
grep -q '"robot": "mu2004_five_link"' out.log || { echo "FAIL: inspect --state: $(cat out.log)"; exit 1; }
check simulate "$G" simulate --reference opt --controller hzd --steps 3 --no-poincare --rate 100 \
  --out walk --quiet
grep -q '"steps_completed": 3' walk/summary.json || { echo "FAIL: simulate: $(cat out.log)"; exit 1; }
ls walk/*.png >/dev/null 2>&1 || { echo "FAIL: simulate: no pictures"; exit 1; }
# A build with DART installs its plant as a module the tool loads at the first DART walk.
if ls "$TMP"/moved/lib*/gaitopt/libgaitopt_dart.so >/dev/null 2>&1; then
  check dart "$G" simulate --reference opt --controller hzd --ground dart --steps 3 --no-poincare \
    --no-plots --out dart --quiet
  grep -q '"steps_completed": 3' dart/summary.json || { echo "FAIL: dart: $(cat out.log)"; exit 1; }
  echo "ok: RABBIT walked 3 steps in DART through the installed module"
fi
check report "$G" report walk
[[ -s walk/report.html && -s walk/walk.gif ]] || { echo "FAIL: report: no page or GIF"; exit 1; }
echo "ok: optimize, simulate and report with pictures from $TMP/moved, the checkout hidden"
module=$(ls "$TMP"/moved/lib*/python3/dist-packages/gaitopt*.so 2>/dev/null | head -n 1)
if [[ -z $module ]]; then
  echo "the Python module was not built (GAITOPT_PYTHON=OFF): import not checked"
  exit 0
fi
PYTHONPATH=$(dirname "$module") /usr/bin/python3 - "$TMP/moved" <<'PY' || { echo "FAIL: python"; exit 1; }
import sys
import gaitopt
assert gaitopt.__file__.startswith(sys.argv[1]), gaitopt.__file__
r = gaitopt.optimize(sys.argv[1] + "/share/gaitopt/configs/ocp/rabbit_kelly2017.yaml", rate_hz=200)
assert abs(r["cost"] - 390.79) < 0.01, r["cost"]  # RABBIT's optimum (Kelly 2017 setting)
print(f"ok: import gaitopt from the moved prefix, RABBIT's optimum {r['cost']:.2f}")
# A walk reads its ground from the installed share/gaitopt, three folders above the module.
robot = gaitopt.Robot(sys.argv[1] + "/share/gaitopt/configs/robots/rabbit.yaml")
w = gaitopt.simulate(robot, r["trajectory"], steps=2, controller="hzd", ground="rigid")
assert w["steps_completed"] == 2 and not w["fell"], w["failure"]
print("ok: the module walked RABBIT on the installed rigid ground")
PY
SH
echo "relocated_install_test: all checks passed"
