#!/usr/bin/env bash
# Builds eaci_planner and runs every test (this is what CI runs, through .ci/run):
#   1. the plain build: unit tests, CLI tests, paper-map tests, soak, ROS integration tests;
#   2. the package installed into a scratch catkin workspace and checked from its install space
#      (scripts/install_check.sh);
#   3. the core suite under ASan + UBSan, the threaded solver tests under TSan (scripts/sanitize.sh);
#   4. a short run of every fuzz target (scripts/fuzz.sh).
# EACI_QUICK=1 runs step 1 only. The paper's benchmark maps are read from maps/paper, or
# from $EACI_MAPS_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
start=$(date +%s)
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
if [ "${EACI_QUICK:-0}" != 1 ]; then
  scripts/install_check.sh
  scripts/sanitize.sh all
  if [ -x scripts/fuzz.sh ]; then scripts/fuzz.sh "${EACI_FUZZ_SECONDS:-20}"; fi
fi
echo "test.sh: all tests passed in $(( $(date +%s) - start )) s"
