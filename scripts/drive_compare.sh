#!/usr/bin/env bash
# Times every lab goal with EACI beside navfn. For each of --runs runs, each planner in turn
# (alternating, so that the machine's load falls on both alike): a roscore of its own,
# launch/move_base_demo.launch with that global planner and the project's config otherwise
# unchanged (the same costmaps, DWA and car, from the same start), scripts/drive_goals.py for
# --rounds rounds of the goals; then the per-goal comparison over all runs (drive_goals.py
# --compare; the first planner is the reference). Needs the navigation stack (move_base,
# map_server, navfn, dwa_local_planner) and the plugin: source the project's devel or install
# space and the navigation workspace first (docs/ros.md; docs/notebook/2026-12-01-driving-to-the-lab-goals.md).
#
# Usage: scripts/drive_compare.sh [--runs N] [--rounds R] [--out DIR] [--map YAML] [--goals "x,y;x,y"]
#                                 [--start x,y[,yaw]] [--world WORLD.yaml] [--launch NAME:=VALUE ...]
#                                 [LABEL=PLANNER[@PARAMS.yaml] ...]
#   defaults: 3 runs of 1 round; navfn=navfn/NavfnROS eaci=eaci_planner/EaciGlobalPlanner
#   PARAMS.yaml is loaded into move_base's namespace over the config (the launch file's
#   extra_params), e.g. eaci-tc1=eaci_planner/EaciGlobalPlanner@tc1.yaml with
#   "EaciGlobalPlanner: {turn_cost: 1.0}". --start: where the car starts, yaw in radians (default 0).
#   --world: obstacles the map does not hold, for the car's laser (diff_drive_sim's boxes and
#   moving_box, e.g. config/lab_boxes.yaml; the launch file's world_params). --launch: more arguments
#   of launch/move_base_demo.launch, e.g. world_map:=maps/lab.yaml localization:=amcl
#   encoder_noise_ticks:=2 (driving on a map gmapping made, in the lab's world, localised by amcl).
set -euo pipefail
cd "$(dirname "$0")/.."
runs_count=3 rounds=1 out=out/drive map="" goals="" start="" world=""
specs=() launch_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs_count=$2; shift 2 ;;
    --rounds) rounds=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --map) map=$2; shift 2 ;;
    --goals) goals=$2; shift 2 ;;
    --start) start=$2; shift 2 ;;
    --world) world=$(realpath "$2"); shift 2 ;;
    --launch) launch_args+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
    -*) echo "drive_compare: unknown option $1 (--help)" >&2; exit 2 ;;
    *) specs+=("$1"); shift ;;
  esac
done
start_x="" start_y="" start_yaw=0
if [ -n "$start" ]; then
  IFS=, read -r start_x start_y start_yaw_given extra <<<"$start"
  [ -n "$start_y" ] && [ -z "$extra" ] || { echo "drive_compare: --start wants x,y or x,y,yaw (got $start)" >&2; exit 2; }
  start_yaw=${start_yaw_given:-0}
fi
[ ${#specs[@]} -gt 0 ] || specs=(navfn=navfn/NavfnROS eaci=eaci_planner/EaciGlobalPlanner)
command -v roslaunch >/dev/null || { echo "drive_compare: roslaunch not found: source the ROS setup first" >&2; exit 1; }
rospack find move_base >/dev/null 2>&1 || {
  echo "drive_compare: move_base not found: source the navigation workspace (docs/ros.md)" >&2; exit 1; }
rospack find eaci_planner >/dev/null 2>&1 || {
  echo "drive_compare: eaci_planner not found: source its devel or install space" >&2; exit 1; }
mkdir -p "$out"

port=$((11600 + RANDOM % 300))
# shellcheck source=scripts/ros_session.sh
source scripts/ros_session.sh   # pids, ros_core, ros_cleanup (the scripts run from the repository root)

declare -A files
for run in $(seq 1 "$runs_count"); do
  for spec_item in "${specs[@]}"; do
    label=${spec_item%%=*} spec=${spec_item#*=}
    planner=${spec%%@*} params=""
    [ "$spec" != "$planner" ] && params=$(realpath "${spec#*@}")
    name=$label.run$run
    echo "drive_compare: run $run of $runs_count, $label ($planner${params:+, $params}), master http://localhost:$port"
    ros_core "$port" "$out/$name.roscore.log"
    roslaunch eaci_planner move_base_demo.launch base_global_planner:="$planner" extra_params:="$params" \
      ${map:+map_file:=$(realpath "$map")} ${start:+start_x:=$start_x start_y:=$start_y start_yaw:=$start_yaw} \
      ${world:+world_params:="$world"} ${launch_args[@]+"${launch_args[@]}"} \
      >"$out/$name.launch.log" 2>&1 & pids+=($!)
    /usr/bin/python3 scripts/drive_goals.py --rounds "$rounds" --json "$out/$name.json" --trace "$out/$name.csv" \
      ${map:+--map "$map"} ${goals:+--goals "$goals"} | tee "$out/$name.txt"
    ros_cleanup
    port=$((port + 1))
    files[$label]="${files[$label]:+${files[$label]},}$out/$name.json"
  done
done
compare_args=()
for spec_item in "${specs[@]}"; do label=${spec_item%%=*}; compare_args+=("$label=${files[$label]}"); done
/usr/bin/python3 scripts/drive_goals.py --compare "${compare_args[@]}" | tee "$out/compare.md"
