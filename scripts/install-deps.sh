#!/usr/bin/env bash
# Installs the Debian 12 packages gaitopt needs, only those that are missing.
# Idempotent: a machine that has everything runs no apt-get at all.
# Usage: scripts/install-deps.sh [--demo | --fuzz]
#   --demo  only what make demo builds and runs (the CLI and its pictures): a fresh machine shows
#           a result minutes sooner without the test, benchmark, browser and MPI packages.
#   --fuzz  also clang and libFuzzer (libclang-rt-14-dev), for scripts/fuzz.sh only: make demo
#           and make test build with GCC and never need them.
set -euo pipefail

# What `make demo` needs: the compiler, the libraries of the CLI, and matplotlib for its pictures.
# libmumps-seq-dev (also a dependency of coinor-libipopt-dev): the KKT solver hands MUMPS the
# rare matrix its pivoting factorization finds (nearly) singular (ocp/solve/kkt/mumps_factor.hpp),
# and the solve profile times MUMPS's calls, both through its C header (dmumps_c.h).
packages=(
  build-essential cmake pkg-config ninja-build
  coinor-libipopt-dev libmumps-seq-dev libeigen3-dev libnlopt-cxx-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev libfmt-dev
  python3 python3-matplotlib python3-numpy python3-pil
)
# What the tests, benchmarks, bindings, report test, MPI libraries and the DART plant add (make
# test, make build). libdart-dev pulls assimp, FCL, Bullet and all of Boost: the demo goes without.
full_packages=(
  libgtest-dev libgmock-dev libbenchmark-dev libboost-dev
  python3-dev pybind11-dev python3-pytest
  chromium
  valgrind
  openmpi-bin libopenmpi-dev
  libdart-dev libdart-utils-urdf-dev python3-dartpy
)
fuzz_packages=(clang libclang-rt-14-dev)

case "${1:-}" in
  "") packages+=("${full_packages[@]}") ;;
  --demo) ;;
  --fuzz) packages+=("${full_packages[@]}" "${fuzz_packages[@]}") ;;
  *) echo "usage: $0 [--demo | --fuzz]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "install-deps: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get -o DPkg::Lock::Timeout=600 update -q
$SUDO apt-get -o DPkg::Lock::Timeout=600 install -y -q --no-install-recommends "${missing[@]}"
