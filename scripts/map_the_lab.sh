#!/usr/bin/env bash
# The paper's flow (Section 7), simulated: the car with its laser is driven round the lab world
# (scripts/scripted_teleop.py, the hand on the joystick) while gmapping builds a 5 cm map
# (launch/gmapping_lab.launch, encoder noise on); map_server's map_saver saves it; EACI plans on
# it offline (eaci_plan: the demo's start and goal) and the saved map is drawn beside the bundled
# one. Then drive on it, localised by amcl, with scripts/drive_compare.sh (docs/ros.md).
# Needs gmapping (not packaged by Debian: build it outside the project, docs/ros.md), map_server
# and the package's devel or install space sourced.
# Usage: scripts/map_the_lab.sh [OUT_DIR] [LAUNCH_ARG:=VALUE ...]   (default out/gmapping:
#        lab_gmapping.yaml/.pgm, lab_gmapping_plan.png, beside_lab.png; e.g. encoder_noise_ticks:=0)
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-out/gmapping}
[ $# -gt 0 ] && shift
command -v roslaunch >/dev/null || { echo "map_the_lab: roslaunch not found: source the ROS setup first" >&2; exit 1; }
rospack find eaci_planner >/dev/null 2>&1 || { echo "map_the_lab: eaci_planner not found: source its devel or install space" >&2; exit 1; }
rospack find gmapping >/dev/null 2>&1 || {
  echo "map_the_lab: gmapping not found. Debian does not package it: build ros-perception/openslam_gmapping and" >&2
  echo "  ros-perception/slam_gmapping in a catkin workspace of their own and source it (docs/ros.md, 'gmapping')" >&2
  exit 1; }
rospack find map_server >/dev/null 2>&1 || { echo "map_the_lab: map_server not found: source the navigation workspace" >&2; exit 1; }
mkdir -p "$out"
port=$((12300 + RANDOM % 100))
# shellcheck source=scripts/ros_session.sh
source scripts/ros_session.sh   # pids, ros_core, ros_cleanup (the scripts run from the repository root)
ros_core "$port" "$out/roscore.log"
roslaunch eaci_planner gmapping_lab.launch "$@" >"$out/gmapping.log" 2>&1 & pids+=($!)
sleep 5
echo "map_the_lab: driving the tour while gmapping maps (log: $out/gmapping.log)"
/usr/bin/python3 scripts/scripted_teleop.py
sleep 5  # gmapping publishes the map every 2 s
(cd "$out" && rosrun map_server map_saver -f lab_gmapping >map_saver.log 2>&1)  # the YAML names its image beside it
ros_cleanup
echo "map_the_lab: saved $out/lab_gmapping.yaml"
plan=$(command -v eaci_plan || true)
[ -n "$plan" ] || plan=$(catkin_find --first-only eaci_planner eaci_plan 2>/dev/null || true)
[ -x "${plan:-}" ] || plan=build/bin/eaci_plan
"$plan" --map "$out/lab_gmapping.yaml" --start-xy 0.4,0.4 --goal-xy 4.4,2.6 --params config/eaci_planner.yaml \
  --inflate 0.55 --inscribed-radius 0.1125 --cost-scaling-factor 5 --png "$out/lab_gmapping_plan.png" --json "$out/lab_gmapping_plan.json"
/usr/bin/python3 - "$out" <<'PY'
import os, sys
from PIL import Image, ImageDraw
out = sys.argv[1]
a = Image.open("maps/lab.pgm").convert("RGB")
b = Image.open(os.path.join(out, "lab_gmapping.pgm")).convert("RGB")
scale = 6
a, b = a.resize((a.width * scale, a.height * scale), Image.NEAREST), b.resize((b.width * scale, b.height * scale), Image.NEAREST)
canvas = Image.new("RGB", (a.width + b.width + 30, max(a.height, b.height) + 40), "white")
canvas.paste(a, (10, 30)); canvas.paste(b, (a.width + 20, 30))
d = ImageDraw.Draw(canvas)
d.text((10, 8), "maps/lab.yaml (bundled)", fill="black")
d.text((a.width + 20, 8), "gmapping, saved by map_saver (grey: unknown)", fill="black")
canvas.save(os.path.join(out, "beside_lab.png"))
print("map_the_lab: %s/beside_lab.png" % out)
PY
