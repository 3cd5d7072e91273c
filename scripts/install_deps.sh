#!/usr/bin/env bash
# Installs the Debian 12 packages eaci_planner builds and tests with, when they are missing:
# the core's, and ROS 1 Noetic from Debian's own packages for the ROS layer (skip those with
# EACI_WITH_ROS=OFF). The navigation stack (nav_core, costmap_2d, move_base) is not packaged
# in Debian: with it installed, the move_base plugin is built too.
# Usage: scripts/install_deps.sh [--cli] [extra-package ...]
#   --cli  only what the command-line planner (eaci_plan) builds with: no test or benchmark
#          libraries, no ROS (scripts/demo.sh)
set -euo pipefail

cli_only=false
if [ "${1:-}" = "--cli" ]; then cli_only=true; shift; fi
packages=(build-essential cmake pkg-config libyaml-cpp-dev libeigen3-dev libcli11-dev nlohmann-json3-dev libstb-dev)
# python3-pandas, python3-matplotlib: scripts/bench_report.py (docs/benchmarks.md's tables and figures from
# eaci_bench's records; test_bench_scen.cpp runs it).
$cli_only || packages+=(libgtest-dev libbenchmark-dev python3-pandas python3-matplotlib)
if ! $cli_only && [ "${EACI_WITH_ROS:-ON}" != "OFF" ]; then
  packages+=(catkin python3-catkin-pkg libroscpp-dev libnav-msgs-dev libgeometry-msgs-dev libstd-msgs-dev libstd-srvs-dev python3-std-srvs
             libtf2-dev libtf2-ros-dev libtf2-geometry-msgs-dev pluginlib-dev libvisualization-msgs-dev libsensor-msgs-dev
             rospack-tools python3-rospkg python3-roslaunch python3-rosmaster python3-rostest rosout tf2-tools
             python3-rospy python3-std-msgs python3-nav-msgs
             libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure)
fi
packages+=("$@")

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  sudo="sudo"
fi
echo "install_deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
