#!/usr/bin/env bash
# Times make_plan of the project's move_base config beside navfn's and global_planner's on maps,
# nav2's planner benchmark protocol: for each map a roscore of its own and
# launch/compare_planners.launch (three move_base nodes with the same costmaps: EACI with
# config/move_base_params.yaml as documented, navfn, global_planner), the first request on the
# new costmaps timed apart, then --requests random pairs of free cells more than 3 m apart, each
# asked of every node in turn 3 times (the median kept), and the comparisons
# (scripts/probe_make_plan.py). Needs the navigation stack and the plugin sourced (docs/ros.md).
#
# Usage: scripts/compare_make_plan.sh [--out DIR] [--requests N] [--third PLANNER|none] [--profile] MAP.yaml ...
#   defaults: out/make_plan, 20 requests, global_planner/GlobalPlanner; --profile: EACI's per-phase
#   profile logged (config/rosconsole_profile.conf) and summed up (scripts/profile_summary.py)
#   e.g. build/bin/eaci_bench map --kind rooms --size 1200 --seed 1 --room-cells 40,80 --door-cells 16,20 \
#            --out out/maps/rooms1200.yaml
#        scripts/compare_make_plan.sh out/maps/rooms1200.yaml
set -euo pipefail
cd "$(dirname "$0")/.."
out=out/make_plan requests=20 third=global_planner/GlobalPlanner profile=false
maps=()
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    --requests) requests=$2; shift 2 ;;
    --third) third=$2; shift 2 ;;
    --profile) profile=true; shift ;;
    -h|--help) sed -n '2,16p' "$0"; exit 0 ;;
    -*) echo "compare_make_plan: unknown option $1 (--help)" >&2; exit 2 ;;
    *) maps+=("$1"); shift ;;
  esac
done
[ ${#maps[@]} -gt 0 ] || { echo "compare_make_plan: give at least one map (--help)" >&2; exit 2; }
rospack find move_base >/dev/null 2>&1 || { echo "compare_make_plan: move_base not found: source the navigation workspace" >&2; exit 1; }
mkdir -p "$out"
# shellcheck source=scripts/ros_session.sh
source scripts/ros_session.sh   # pids, ros_core, ros_cleanup (the scripts run from the repository root)
$profile && export ROSCONSOLE_CONFIG_FILE=$PWD/config/rosconsole_profile.conf
nodes=move_base,move_base_other third_arg=()
[ "$third" = none ] || { nodes=$nodes,move_base_third; third_arg=(third_planner:="$third"); }
for map in "${maps[@]}"; do
  name=$(basename "$map" .yaml)
  port=$((11900 + RANDOM % 90))
  ros_core "$port" "$out/$name.roscore.log"
  roslaunch eaci_planner compare_planners.launch map_file:="$(realpath "$map")" "${third_arg[@]}" \
    >"$out/$name.launch.log" 2>&1 & pids+=($!)
  # The first request on each node's new costmap (the planner's first copy, cold buffers), apart,
  # once every node offers make_plan and its start-up (the costmaps' first inflation) is over.
  for _ in $(seq 1 240); do
    [ "$(rosservice list 2>/dev/null | grep -c '^/move_base[a-z_]*/make_plan$')" -ge "$(tr , '\n' <<<"$nodes" | wc -l)" ] && break
    sleep 0.5
  done
  sleep 5
  /usr/bin/python3 scripts/probe_make_plan.py --map "$map" --random 1 --seed 7 --min-separation 3 --nodes "$nodes" --wait 120 \
    --save "$out/$name-first-{node}.json" >/dev/null
  /usr/bin/python3 scripts/probe_make_plan.py --map "$map" --random "$requests" --seed 1 --min-separation 3 \
    --nodes "$nodes" --repeat 3 --save "$out/$name-{node}.json" >"$out/$name.probe.log"
  echo "== $name"
  /usr/bin/python3 - "$out/$name" "$nodes" <<'PY' | tee "$out/$name.first.txt"
import json, sys
prefix, nodes = sys.argv[1], sys.argv[2].split(",")
first = [json.load(open("%s-first-%s.json" % (prefix, n))) for n in nodes]
print("first plan on new costmaps: " + ", ".join("%s %.1f ms" % (f["planner"].split("/")[-1], f["results"][0]["ms"]) for f in first))
PY
  rest=${nodes#move_base,}
  for other in ${rest//,/ }; do
    /usr/bin/python3 scripts/probe_make_plan.py --compare "$out/$name-$other.json" "$out/$name-move_base.json" \
      | tee "$out/$name.compare-$other.txt"
  done
  ros_cleanup
  $profile && /usr/bin/python3 scripts/profile_summary.py "$out/$name.launch.log" | tee "$out/$name.profile.txt"
done
