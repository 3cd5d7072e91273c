#!/usr/bin/env bash
# The core test suite under AddressSanitizer + UndefinedBehaviorSanitizer, and the
# multi-threaded solver tests under ThreadSanitizer. Any report fails the run.
# The heavy tests (paper maps x 20 seeds, soak, ROS integration) run in the plain build only.
# Usage: scripts/sanitize.sh [asan|tsan|all]   (default all)
set -euo pipefail
cd "$(dirname "$0")/.."
what=${1:-all}
EACI_WITH_ROS=OFF scripts/install_deps.sh
export PATH=/usr/bin:$PATH
jobs=$(nproc)

configure() {  # configure BUILD_DIR SANITIZERS
  cmake -S . -B "$1" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DEACI_WITH_ROS=OFF -DEACI_BUILD_SOAK=OFF \
    -DEACI_SANITIZE="$2" >/dev/null
}

if [ "$what" = asan ] || [ "$what" = all ]; then
  echo "sanitize: AddressSanitizer + UndefinedBehaviorSanitizer (build/asan)"
  configure build/asan address,undefined
  cmake --build build/asan -j"$jobs" --target eaci_tests eaci_plan test_planning_service \
    test_planning_service_memory test_costmap_replay test_route_defect test_emptied_costmap test_costmap_source test_costmap_mirror
  # Wall-clock checks (the 1 ms limit on 4 M cells) belong to the plain build.
  ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 \
    ctest --test-dir build/asan --output-on-failure -j"$jobs" -E '^PaperMaps\.|OneMillisecondLimit'
fi

if [ "$what" = tsan ] || [ "$what" = all ]; then
  echo "sanitize: ThreadSanitizer on the multi-threaded solver tests (build/tsan)"
  configure build/tsan thread
  cmake --build build/tsan -j"$jobs" --target eaci_tests test_planning_service
  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
    build/tsan/bin/eaci_tests --gtest_filter='PlannerDeterminism.*:PlannerThreads.*:Landmarks.*'
  # The planning service: plans, reconfigures and cancels from many threads at once.
  TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 \
    build/tsan/bin/test_planning_service --gtest_filter='PlanningServiceThreads.*:PlanningService.Cancel*:PlanningService.SavedCostmaps*'
fi
