# Two commands do everything on a fresh Debian 12 machine:
#   make demo   install missing packages, configure, build the gaitopt tool only, run the quick
#               part of the main job into results/ and print where its report page is
#               (make demo-full: every solve, walk, sweep and library of the README, much longer)
#   make test   same set-up, then the whole test suite (Release, then Debug+ASan/UBSan) via ctest,
#               the quick tests before the full ones, and one optimise under valgrind
#               (make test-quick: the Release build's quick tests only, a few minutes)
#   make studies  every study of configs/studies/ into build/studies/ (STUDIES="a b" for some)
JOBS ?= $(shell nproc)
BUILD ?= build
# The configs whose solves the inertia audit follows: every shipped one whose KKT matrices leave
# the static pivots, and the two too large to decompose densely also on coarse meshes (@SSP,DSP).
INERTIA_AUDIT_CONFIGS ?= $(addprefix configs/ocp/,mu2004_walk_robust.yaml \
  mu2004_walk_strike.yaml mu2004_walk_work.yaml mu2004_walk_cot.yaml mu2004_walk_cot.yaml@12,4 \
  mu2004_walk_ensemble.yaml mu2004_walk_ensemble.yaml@6,4 compass_gait_walk.yaml \
  three_link_walk.yaml)
SAN_BUILD ?= build-sanitize
# The sanitizer build keeps assertions (no NDEBUG) but compiles at -O1, as OSS-Fuzz does: Eigen at
# -O0 made the sanitizer suite several times slower than the Release one for no extra findings.
# Line tables only (-g1): the sanitizers' stack traces keep file and line, and the build is a
# fifth faster than with full debug information.
# The Python module is left out there: its test runs in the Release build only.
SAN_OPT ?= -g1 -O1
# Looked up when a recipe runs (=, not :=): on a fresh machine ninja arrives with the deps.
CMAKE_GEN = $(shell command -v ninja >/dev/null 2>&1 && echo "-G Ninja")

.PHONY: deps configure build test test-quick test-release test-sanitize valgrind demo demo-full \
  bench studies ocp-study dart-side-by-side library-throughput fidelity inertia-audit fuzz \
  fresh-demo format clean

# Each target names every option, so one build folder serves them all in any order.
# The demo builds the CLI alone and needs none of the test, benchmark, binding or MPI packages;
# the tests do not need the benchmarks (CI time); build, bench and demo-full have everything.
DEMO_FLAGS := -DGAITOPT_BUILD_TESTS=OFF -DGAITOPT_BUILD_BENCH=OFF -DGAITOPT_PYTHON=OFF \
  -DGAITOPT_MPI=OFF -DGAITOPT_DART=OFF
TEST_FLAGS := -DGAITOPT_BUILD_TESTS=ON -DGAITOPT_BUILD_BENCH=OFF -DGAITOPT_PYTHON=ON -DGAITOPT_MPI=ON \
  -DGAITOPT_DART=ON
FULL_FLAGS := -DGAITOPT_BUILD_TESTS=ON -DGAITOPT_BUILD_BENCH=ON -DGAITOPT_PYTHON=ON -DGAITOPT_MPI=ON \
  -DGAITOPT_DART=ON
CONFIGURE_FLAGS = $(FULL_FLAGS)
DEPS_FLAGS =
demo: CONFIGURE_FLAGS = $(DEMO_FLAGS)
demo: DEPS_FLAGS = --demo
test-release test-quick: CONFIGURE_FLAGS = $(TEST_FLAGS)

deps:
	@bash scripts/install-deps.sh $(DEPS_FLAGS)

configure: deps
	@cmake -S . -B $(BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Release $(CONFIGURE_FLAGS) >/dev/null

build: configure
	@cmake --build $(BUILD) -j $(JOBS)

# Tests are labelled quick or full (tests/CMakeLists.txt). The quick ones run first, so a broken
# build shows in minutes; the full ones run whatever the quick ones gave, and either failing fails.
CTEST = ctest --output-on-failure -j $(JOBS)
QUICK_THEN_FULL = { $(CTEST) -L quick; quick=$$?; $(CTEST) -L full && exit $$quick; }
test-quick: build
	@cd $(BUILD) && $(CTEST) -L quick

test-release: build
	@cd $(BUILD) && $(QUICK_THEN_FULL)

test-sanitize: deps
	@cmake -S . -B $(SAN_BUILD) $(CMAKE_GEN) -DCMAKE_BUILD_TYPE=Debug -DGAITOPT_SANITIZE=ON \
	  -DCMAKE_CXX_FLAGS_DEBUG="$(SAN_OPT)" -DGAITOPT_BUILD_BENCH=OFF \
	  -DGAITOPT_PYTHON=OFF >/dev/null
	@cmake --build $(SAN_BUILD) -j $(JOBS)
	@cd $(SAN_BUILD) && export ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 && \
	  $(QUICK_THEN_FULL)

# One optimise of the small RABBIT problem under memcheck: errors or leaks fail (about 15 s).
valgrind: build
	@bash scripts/valgrind.sh $(BUILD)

test: test-release test-sanitize valgrind

# The demo runs the tool only: tests are built by `make test`, benchmarks by `make bench`.
demo: configure
	@cmake --build $(BUILD) -j $(JOBS) --target gaitopt_cli
	@bash scripts/demo.sh $(BUILD)

demo-full: build
	@bash scripts/demo.sh $(BUILD) --full

bench: build
	@bash scripts/bench.sh $(BUILD)

studies: build
	@bash scripts/studies.sh $(BUILD) $(BUILD)/studies $(STUDIES)

# The measurements behind results/ that are too long for `make bench` (minutes each; the README
# and results/README.md say which file each one makes). fresh-demo needs root and the mirror.
ocp-study: build
	@bash scripts/ocp_study.sh $(BUILD) $(BUILD)/ocp_study

dart-side-by-side: build
	@bash scripts/dart_side_by_side.sh $(BUILD) $(BUILD)/dart_side_by_side

library-throughput: build
	@bash scripts/library_throughput.sh $(BUILD)

fidelity: build
	@/usr/bin/python3 scripts/fidelity_chart.py $(BUILD)/apps/gaitopt $(BUILD)/fidelity

# The KKT solver's inertia against MUMPS's and a dense eigendecomposition's (bench/inertia_audit.cpp).
inertia-audit: build
	@$(BUILD)/bench/inertia_audit results/inertia_audit.md 4 $(INERTIA_AUDIT_CONFIGS)

fuzz:
	@bash scripts/fuzz.sh $(FUZZ_SECONDS)

fresh-demo:
	@bash scripts/fresh_machine_demo.sh

format:
	@clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	@rm -rf $(BUILD) $(SAN_BUILD)
