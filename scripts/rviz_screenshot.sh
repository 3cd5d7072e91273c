#!/usr/bin/env bash
# A screenshot of RViz showing what the planner node planned on the lab: launch/demo.launch with
# rviz:=true on a virtual display (Xvfb, software OpenGL); once RViz listens, a goal as its
# "2D Nav Goal" sends it (the route before smoothing and the islands are made only while someone
# listens), and SECONDS later (default 6) ImageMagick's import grabs the window. Needs Debian's rviz, xvfb and imagemagick, and the package's devel or
# install space sourced.
# With --seeing: launch/move_base_demo.launch instead, the car with its laser among the boxes of
# config/lab_boxes.yaml (the scan, the boxes, the global costmap and EACI's plan; needs the
# navigation stack), default docs/figures/rviz_seeing.png.
# Usage: scripts/rviz_screenshot.sh [--seeing] [OUT.png] [SECONDS]     (default docs/figures/rviz_demo.png)
set -euo pipefail
cd "$(dirname "$0")/.."
launch=(demo.launch) default_out=docs/figures/rviz_demo.png
if [ "${1:-}" = "--seeing" ]; then
  launch=(move_base_demo.launch "world_params:=$PWD/config/lab_boxes.yaml") default_out=docs/figures/rviz_seeing.png
  shift
fi
out=${1:-$default_out} wait_s=${2:-6}
for tool in Xvfb import rviz roslaunch; do
  command -v "$tool" >/dev/null || { echo "rviz_screenshot: $tool not found (apt-get install rviz xvfb imagemagick; source the ROS setup)" >&2; exit 1; }
done
display=:$((70 + RANDOM % 20)) port=$((12100 + RANDOM % 100))
export DISPLAY=$display LIBGL_ALWAYS_SOFTWARE=1
# shellcheck source=scripts/ros_session.sh
source scripts/ros_session.sh   # pids, ros_core, ros_cleanup (the scripts run from the repository root)
Xvfb "$display" -screen 0 1400x900x24 >/dev/null 2>&1 & pids+=($!)
ros_core "$port" /dev/null
roslaunch eaci_planner "${launch[@]}" rviz:=true >"${RVIZ_SHOT_LOG:-/dev/null}" 2>&1 & pids+=($!)
sleep 10
rostopic pub -1 /move_base_simple/goal geometry_msgs/PoseStamped \
  '{header: {frame_id: map}, pose: {position: {x: 4.2, y: 0.5}, orientation: {w: 1.0}}}' >/dev/null
sleep "$wait_s"
mkdir -p "$(dirname "$out")"
for attempt in 1 2 3; do  # a software-GL RViz sometimes shows a blank frame: grab again
  import -display "$display" -window root -crop 1200x800+0+0 +repage "$out"
  [ "$(identify -format '%[fx:standard_deviation > 0.01]' "$out")" = 1 ] && { echo "rviz_screenshot: $out"; exit 0; }
  sleep 2
done
echo "rviz_screenshot: RViz showed a blank window three times ($out)" >&2
exit 1
