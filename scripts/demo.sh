#!/usr/bin/env bash
# The main job: plan with EACI on the bundled lab map as the robot does (the move_base config's
# parameters, with the corner rounding a robot's smoothing has fixed, and its costmap's inflation: 0.55 m, cost_scaling_factor 5, the car's inscribed
# radius 0.11 m, so the route keeps off the walls) and write a picture and a JSON summary.
#   out/demo.png   the map with its inflation costs, EACI's final pheromone, its islands, the grid
#                  route the ants found and the smoothed route a robot drives
#   out/demo.json  both routes and every figure of the run
# It builds only what it runs: the CLI (eaci_plan), Release, without ROS or tests, in build/demo
# (the first run installs the CLI's Debian packages if missing and compiles; later runs take seconds).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh --cli
cmake -S . -B build/demo -DCMAKE_BUILD_TYPE=Release -DEACI_WITH_ROS=OFF -DEACI_BUILD_TESTS=OFF >/dev/null
cmake --build build/demo -j"$(nproc)" --target eaci_plan
mkdir -p out
build/demo/bin/eaci_plan --map maps/lab.yaml --start-xy 0.4,0.4 --goal-xy 4.4,2.6 \
  --algorithm eaci --seed 1 --params config/eaci_planner.yaml --set round_corners=2 --set smooth_tolerance=0.1 \
  --inflate 0.55 --inscribed-radius 0.11 --cost-scaling-factor 5 --json out/demo.json --png out/demo.png
echo "demo: open out/demo.png to see the routes; out/demo.json has the numbers"
