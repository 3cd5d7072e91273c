#!/usr/bin/env bash
# Configures and builds eaci_planner into build/ (Release). Extra arguments go to cmake.
# With ROS found, the nodes land in devel/lib/eaci_planner and `source devel/setup.bash`
# makes `roslaunch eaci_planner ...` work.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
export PATH=/usr/bin:$PATH   # catkin needs Debian's python3 (with catkin_pkg), not a pyenv shim
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DPYTHON_EXECUTABLE=/usr/bin/python3 \
  -DEACI_WITH_ROS="${EACI_WITH_ROS:-ON}" "$@" >/dev/null
cmake --build build -j"$(nproc)"
