#!/usr/bin/env bash
# Builds eaci_planner and runs the whole test suite (this is what CI runs).
# The paper's benchmark maps are read from ../shared/maps, or from $EACI_MAPS_DIR.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
ctest --test-dir build --output-on-failure -j"$(nproc)"
