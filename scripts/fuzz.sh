#!/usr/bin/env bash
# Fuzzes the input parsers with libFuzzer, ASan and UBSan: robot, gait and OCP YAML, trajectory
# CSV, state JSON and the command-line options (fuzz/). Builds build-fuzz with clang, runs each target for SECONDS (one at a
# time), keeps each target's corpus in build-fuzz/corpus/ (it grows from run to run, seeded from
# configs/ and fuzz/seeds/) and writes every crash, sanitizer report, stray exception, hang
# (> 10 s) or leak to build-fuzz/findings/. Prints one row per target and exits 1 on a finding.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 60)
set -euo pipefail

seconds=${1:-60}
[[ $seconds =~ ^[1-9][0-9]*$ ]] || { echo "usage: $0 [SECONDS_PER_TARGET]" >&2; exit 2; }
cd "$(dirname "$0")/.."
build="build-fuzz"
hang_seconds=10

targets=(robot_yaml gait_yaml ocp_yaml trajectory_csv state_json cli_options)
declare -A seeds=([robot_yaml]=configs/robots [gait_yaml]=configs/gaits [ocp_yaml]=configs/ocp
  [trajectory_csv]=fuzz/seeds/trajectory_csv [state_json]=configs/states
  [cli_options]=fuzz/seeds/cli_options)
declare -A dicts=([robot_yaml]=yaml [gait_yaml]=yaml [ocp_yaml]=yaml [trajectory_csv]=csv
  [state_json]=json [cli_options]=cli)

bash scripts/install-deps.sh --fuzz
# -O1 without NDEBUG: assertions (ours and Eigen's) stay on.
cmake -S . -B "$build" -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS=-O1 -DGAITOPT_FUZZ=ON -DGAITOPT_BUILD_TESTS=OFF -DGAITOPT_BUILD_BENCH=OFF \
  >/dev/null
echo "fuzz: building the targets in $build (log: $build/build.log)"
cmake --build "$build" -j "${JOBS:-$(nproc)}" --target "${targets[@]/%/_fuzz}" \
  >"$build/build.log" 2>&1 || { tail -n 40 "$build/build.log"; exit 1; }
mkdir -p "$build/findings" "$build/logs"
# As OSS-Fuzz: with ASan's default 256 MB quarantine the RSS passed 1 GB in six minutes.
export ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=10:allocator_release_to_os_interval_ms=500}

# run_target NAME: fuzzes NAME for $seconds; prints its table row; returns 1 on a finding.
run_target() {
  local name=$1 corpus="$build/corpus/$1" log="$build/logs/$1.log" start="$build/logs/$1.start"
  mkdir -p "$corpus"
  touch "$start"
  local rc=0
  "$build/fuzz/${name}_fuzz" -max_total_time="$seconds" -timeout="$hang_seconds" \
    -print_final_stats=1 -artifact_prefix="$build/findings/$name-" \
    -dict="fuzz/dict/${dicts[$name]}.dict" "$corpus" "${seeds[$name]}" >"$log" 2>&1 || rc=$?
  local runs rate size found
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  size=$(grep -o 'corp: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
  found=$(find "$build/findings" -name "$name-*" -newer "$start" | wc -l)
  printf '%-16s %8s %12s %8s %8s %9s\n' "$name" "$seconds" "${runs:-?}" "${rate:-?}" \
    "${size:-?}" "$found"
  if ((rc != 0 && found == 0)); then
    echo "  $name exited $rc without a finding: see $log" >&2
    return 1
  fi
  ((found == 0))
}

printf '%-16s %8s %12s %8s %8s %9s\n' target "time [s]" runs exec/s corpus findings
status=0
for name in "${targets[@]}"; do run_target "$name" || status=1; done
if ((status != 0)); then
  echo "findings (reproduce: $build/fuzz/TARGET_fuzz FILE; logs in $build/logs/):"
  find "$build/findings" -newer "$build/logs/${targets[0]}.start" -type f -printf '  %p\n'
fi
exit "$status"
