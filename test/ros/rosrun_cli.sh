#!/usr/bin/env bash
# `rosrun eaci_planner eaci_plan` against this build's devel space plans on the lab map:
#   rosrun_cli.sh DEVEL_DIR LAB_MAP.yaml
# rosrun must find exactly one eaci_plan (the link in devel/lib/eaci_planner); with more it
# would ask which one to run, so stdin is closed to make that a failure instead of a hang.
set -euo pipefail
devel=$1 map=$2
export PATH=/usr/bin:$PATH          # ROS tools need Debian's python3, not a pyenv shim
export ROS_HOME=${ROS_HOME:-$(mktemp -d)}
set +u
# shellcheck disable=SC1091
source "$devel/setup.bash"
set -u
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
rosrun eaci_planner eaci_plan --map "$map" --start-xy 0.4,0.4 --goal-xy 4.4,2.6 --seed 1 --quiet \
  --json "$out/lab.json" </dev/null
grep -q '"path"' "$out/lab.json" || { echo "rosrun eaci_plan wrote no route" >&2; exit 1; }
echo "rosrun eaci_planner eaci_plan: planned on $map"
