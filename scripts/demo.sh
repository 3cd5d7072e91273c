#!/usr/bin/env bash
# The main job: plan with EACI on the bundled lab map and write a picture and a JSON summary.
#   out/demo.png   the map, EACI's final pheromone, its islands and the route
#   out/demo.json  the route and every figure of the run
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
mkdir -p out
build/bin/eaci_plan --map maps/lab.yaml --start-xy 0.4,0.4 --goal-xy 4.4,2.6 \
  --algorithm eaci --seed 1 --json out/demo.json --png out/demo.png
echo "demo: open out/demo.png to see the route; out/demo.json has the numbers"
