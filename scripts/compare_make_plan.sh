#!/usr/bin/env bash
# Times make_plan of the project's move_base config beside navfn's on maps, nav2's planner
# benchmark protocol: for each map a roscore of its own and launch/compare_planners.launch (two
# move_base nodes with the same costmaps, EACI with config/move_base_params.yaml as documented
# and navfn), one warm-up request, then 12 random pairs of free cells more than 3 m apart, each
# asked of both nodes in turn 3 times (the median kept), and the comparison
# (scripts/probe_make_plan.py). Needs the navigation stack and the plugin sourced (docs/ros.md).
#
# Usage: scripts/compare_make_plan.sh [--out DIR] MAP.yaml ...
#   e.g. build/bin/eaci_bench map --kind rooms --size 1200 --seed 1 --room-cells 40,80 --door-cells 16,20 \
#            --out out/maps/rooms1200.yaml
#        scripts/compare_make_plan.sh out/maps/rooms1200.yaml
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/make_plan
maps=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
    -*) echo "compare_make_plan: unknown option $1 (--help)" >&2; exit 2 ;;
    *) maps+=("$1"); shift ;;
  esac
done
[ ${#maps[@]} -gt 0 ] || { echo "compare_make_plan: give at least one map (--help)" >&2; exit 2; }
rospack find move_base >/dev/null 2>&1 || { echo "compare_make_plan: move_base not found: source the navigation workspace" >&2; exit 1; }
mkdir -p "$out"
pids=()
cleanup() { for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done; sleep 3
            for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done; pids=(); }
trap cleanup EXIT
for map in "${maps[@]}"; do
  name=$(basename "$map" .yaml)
  port=$((11900 + RANDOM % 90))
  export ROS_MASTER_URI=http://localhost:$port
  roscore -p "$port" >"$out/$name.roscore.log" 2>&1 & pids+=($!)
  sleep 3
  roslaunch eaci_planner compare_planners.launch map_file:="$(realpath "$map")" >"$out/$name.launch.log" 2>&1 & pids+=($!)
  /usr/bin/python3 scripts/probe_make_plan.py --map "$map" --random 1 --seed 7 --nodes move_base,move_base_other --wait 120 \
    >/dev/null
  /usr/bin/python3 scripts/probe_make_plan.py --map "$map" --random 12 --seed 1 --min-separation 3 \
    --nodes move_base,move_base_other --repeat 3 --save "$out/$name-{node}.json" >"$out/$name.probe.log"
  echo "== $name"
  /usr/bin/python3 scripts/probe_make_plan.py --compare "$out/$name-move_base_other.json" "$out/$name-move_base.json" \
    | tee "$out/$name.compare.txt"
  cleanup
done
