# Every dependency is a Debian 12 package (scripts/install-deps.sh installs them).
find_package(PkgConfig REQUIRED)
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
# Sequential MUMPS, which Ipopt itself links (libmumps-seq-dev, a dependency of
# coinor-libipopt-dev): the KKT solver's fallback on a zero static pivot (ocp/solve/kkt/mumps_factor.hpp).
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(DMUMPS_SEQ_LIBRARY dmumps_seq REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(NLopt REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(fmt REQUIRED)
if(GAITOPT_BUILD_TESTS OR GAITOPT_BUILD_BENCH)
  # Odeint, for the independent re-simulations of ocp/transcription/chain_simulation.hpp: only the tests and
  # benchmarks include it, so the CLI (make demo) builds without Boost.
  find_package(Boost 1.74 REQUIRED)
endif()
if(GAITOPT_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(GAITOPT_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
if(GAITOPT_MPI)
  set(MPI_CXX_SKIP_MPICXX ON)  # the C API only: the C++ bindings are deprecated
  find_package(MPI COMPONENTS CXX)
  if(NOT MPI_CXX_FOUND)
    message(WARNING "MPI not found (apt-get install libopenmpi-dev): building without it")
    set(GAITOPT_MPI OFF)
  endif()
endif()
if(GAITOPT_PYTHON)
  # Debian's interpreter, not a pyenv python3 earlier on PATH: the module must load in the python
  # that has Debian's numpy and pytest.
  if(NOT PYTHON_EXECUTABLE AND EXISTS /usr/bin/python3)
    set(PYTHON_EXECUTABLE /usr/bin/python3)
  endif()
  find_package(pybind11 CONFIG)
  if(pybind11_FOUND)
    # The module links the static libraries: they must be position independent.
    set(CMAKE_POSITION_INDEPENDENT_CODE ON)
  else()
    message(WARNING "pybind11 not found (apt-get install pybind11-dev python3-dev): no Python module")
    set(GAITOPT_PYTHON OFF)
  endif()
endif()
if(GAITOPT_DART)
  # The URDF reader (dart::utils::DartLoader) comes with the utils-urdf component.
  find_package(DART 6.12 CONFIG COMPONENTS utils-urdf)
  if(NOT DART_FOUND)
    message(WARNING "DART not found (apt-get install libdart-dev libdart-utils-urdf-dev): \
building without it")
    set(GAITOPT_DART OFF)
  endif()
endif()
