#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang + AddressSanitizer + UBSan) in build/fuzzer/ and runs
# each for SECONDS_PER_TARGET seconds on a copy of its seed corpus (fuzz/corpus/<target>/ is
# never written). Fails when any target crashes, leaks, times out or runs out of memory; the
# offending input is kept in build/fuzzer/fuzz-run/artifacts/. See docs/fuzzing.md.
#
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]      (default 30; CI: scripts/fuzz.sh 20)
# Environment:
#   EACI_FUZZ_TARGETS  targets to run, e.g. "pgm image" (default: all)
#   EACI_FUZZ_JOBS     targets run at the same time (default: the number of cores)
#   EACI_FUZZ_BUILD    build directory (default: build/fuzzer)
#   EACI_FUZZ_KEEP     set to 1 to keep the grown corpora of the previous run and go on from them
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

seconds=${1:-30}
case "$seconds" in ''|*[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2; exit 2 ;; esac
all_targets=(pgm image matrix movingai_map map_yaml parameters params_yaml cli_args)
read -r -a targets <<< "${EACI_FUZZ_TARGETS:-${all_targets[*]}}"
jobs=${EACI_FUZZ_JOBS:-$(nproc)}
build=${EACI_FUZZ_BUILD:-build/fuzzer}
case "$build" in /*) ;; *) build="$root/$build" ;; esac

# ---------------------------------------------------------------- clang with libFuzzer
# Debian 12's clang is clang 14; libFuzzer and the sanitizer runtimes are in libclang-rt-<major>-dev.
if ! command -v clang++ >/dev/null; then
  EACI_WITH_ROS=OFF scripts/install_deps.sh clang
fi
clang_major=$(clang++ -dumpversion | cut -d. -f1)
EACI_WITH_ROS=OFF scripts/install_deps.sh "libclang-rt-${clang_major}-dev"

# ---------------------------------------------------------------- build
start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DEACI_WITH_ROS=OFF -DEACI_BUILD_TESTS=OFF -DEACI_BUILD_TOOLS=OFF -DEACI_BUILD_FUZZERS=ON >/dev/null
cmake --build "$build" --target eaci_fuzzers -j"$(nproc)" -- --no-print-directory >/dev/null
echo "fuzz: built ${#targets[@]} target(s) in $(( $(date +%s) - start )) s; ${seconds} s each, ${jobs} at a time"

# ---------------------------------------------------------------- run
run="$build/fuzz-run"
mkdir -p "$run/logs" "$run/artifacts"
rm -f "$run"/logs/*.log "$run"/artifacts/*

run_target() {
  local t=$1 corpus="$run/corpus/$1"
  if [ "${EACI_FUZZ_KEEP:-0}" != 1 ] || [ ! -d "$corpus" ]; then
    rm -rf "$corpus"
    mkdir -p "$corpus"
    cp fuzz/corpus/"$t"/* "$corpus"/
  fi
  local dict=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
  local rc=0
  "$build/fuzz/fuzz_$t" -max_total_time="$seconds" -rss_limit_mb=1024 -timeout=10 -print_final_stats=1 \
    -artifact_prefix="$run/artifacts/$t-" "${dict[@]}" "$corpus" >"$run/logs/$t.log" 2>&1 || rc=$?
  echo "$rc" >"$run/logs/$t.rc"
}

for t in "${targets[@]}"; do
  [ -x "$build/fuzz/fuzz_$t" ] || { echo "fuzz: unknown target '$t' (known: ${all_targets[*]})" >&2; exit 2; }
done
rm -f "$run"/logs/*.rc
for t in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  run_target "$t" &
done
wait

declare -A status
for t in "${targets[@]}"; do
  rc=$(cat "$run/logs/$t.rc" 2>/dev/null || echo missing)
  if [ "$rc" = 0 ]; then status[$t]=ok; else status[$t]="FAILED (exit $rc)"; fi
done

# ---------------------------------------------------------------- report
failed=0
printf '%-12s %12s %8s %7s %7s %6s  %s\n' target executions exec/s cov ft corpus result
for t in "${targets[@]}"; do
  log="$run/logs/$t.log"
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -1)
  last=$(grep -E '^#[0-9]+' "$log" | tail -1 || true)
  cov=$(sed -n 's/.* cov: \([0-9]*\).*/\1/p' <<< "$last")
  ft=$(sed -n 's/.* ft: \([0-9]*\).*/\1/p' <<< "$last")
  corp=$(sed -n 's/.* corp: \([0-9]*\/[0-9a-zA-Z]*\).*/\1/p' <<< "$last")
  printf '%-12s %12s %8s %7s %7s %6s  %s\n' "$t" "${execs:-?}" "${rate:-?}" "${cov:-?}" "${ft:-?}" \
    "${corp:-?}" "${status[$t]}"
  if [ "${status[$t]}" != ok ]; then
    failed=1
    echo "---- fuzz_$t: $log (last lines)" >&2
    grep -E 'ERROR: |SUMMARY: |FUZZ_CHECK|runtime error|Test unit written|libFuzzer: ' "$log" | head -20 >&2 || true
    tail -5 "$log" >&2
  fi
done
if [ "$failed" -ne 0 ]; then
  echo "fuzz: FAILED; inputs in $run/artifacts/, reproduce with $build/fuzz/fuzz_<target> <artifact>" >&2
  exit 1
fi
echo "fuzz: all ${#targets[@]} target(s) ran ${seconds} s without a crash, leak, timeout or OOM"
