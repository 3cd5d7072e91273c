#!/usr/bin/env bash
# Installs eaci_planner as a ROS package into a scratch catkin workspace
# (catkin_make_isolated --install) and checks it from the INSTALL space, not the devel space:
#   1. rospack finds the package in the install space;
#   2. `rosrun eaci_planner eaci_plan` plans on the installed lab map;
#   3. rostest of the installed demo: the car drives EACI's route to the goal;
#   4. where nav_core is installed: the plugin library is installed and
#      `rospack plugins --attrib=plugin nav_core` lists it.
# Usage: scripts/install_check.sh [workspace]   (default: a fresh directory under /tmp, removed on success)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/install_deps.sh"
export PATH=/usr/bin:$PATH   # catkin and the ROS tools need Debian's python3, not a pyenv shim
ws=${1:-$(mktemp -d /tmp/eaci_install.XXXXXX)}
mkdir -p "$ws/src"
ln -sfn "$root" "$ws/src/eaci_planner"
fail() { echo "install_check: FAILED: $*" >&2; exit 1; }

echo "install_check: building and installing into $ws/install"
(cd "$ws" && catkin_make_isolated --install --install-space "$ws/install" \
   --cmake-args -DCMAKE_BUILD_TYPE=Release -DEACI_BUILD_TESTS=OFF -DPYTHON_EXECUTABLE=/usr/bin/python3 \
   >"$ws/build.log" 2>&1) || { tail -n 40 "$ws/build.log"; fail "catkin_make_isolated --install (log: $ws/build.log)"; }

set +u  # catkin's setup scripts read unset variables
# shellcheck disable=SC1091
source "$ws/install/setup.bash"
set -u
export ROS_HOME="$ws/ros_home"
share=$(rospack find eaci_planner)
[ "$share" = "$ws/install/share/eaci_planner" ] || fail "rospack finds eaci_planner in $share, not in the install space"
echo "install_check: rospack finds $share"

json="$ws/lab.json"
rosrun eaci_planner eaci_plan --map "$share/maps/lab.yaml" --start-xy 0.4,0.4 --goal-xy 4.4,2.6 \
  --seed 1 --quiet --json "$json" || fail "rosrun eaci_planner eaci_plan on the installed lab map"
grep -q '"path"' "$json" || fail "eaci_plan wrote no route to $json"
echo "install_check: rosrun eaci_planner eaci_plan planned on the installed lab map"

rostest eaci_planner demo_arrives.test || fail "rostest eaci_planner demo_arrives.test (logs in $ROS_HOME/log)"
echo "install_check: the installed demo drove the car to the goal"

if rospack find nav_core >/dev/null 2>&1; then
  [ -f "$ws/install/lib/libeaci_global_planner.so" ] || fail "nav_core is installed but the plugin library is not"
  plugins=$(rospack plugins --attrib=plugin nav_core)
  grep -q "^eaci_planner $share/plugins.xml" <<<"$plugins" || fail "rospack plugins --attrib=plugin nav_core does not list eaci_planner: $plugins"
  echo "install_check: rospack plugins lists $share/plugins.xml for nav_core"
else
  echo "install_check: nav_core is not installed here: the move_base plugin is not built (see docs/ros.md)"
fi
[ $# -ge 1 ] || rm -rf "$ws"
echo "install_check: passed"
