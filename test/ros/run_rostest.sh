#!/usr/bin/env bash
# Runs one rostest launch file against this build's devel space: run_rostest.sh DEVEL_DIR FILE.test
# (rostest starts its own rosmaster). On failure, prints the test results and the nodes' logs.
set -euo pipefail
devel=$1
shift
export PATH=/usr/bin:$PATH          # ROS tools need Debian's python3, not a pyenv shim
export ROS_HOME=${ROS_HOME:-$(mktemp -d)}
set +u  # catkin's setup scripts read unset variables
# shellcheck disable=SC1091
source "$devel/setup.bash"
set -u
# Not --text: rostest's verdict is only reliable when it reads the tests' XML results.
if rostest "$@"; then
  exit 0
fi
echo "---- test results ($ROS_HOME/test_results)"
find "$ROS_HOME/test_results" -name '*.xml' -exec cat {} \; 2>/dev/null | grep -E 'failure|testcase' | head -50 || true
echo "---- node logs"
find "$ROS_HOME/log" -name '*.log' -newer "$devel/setup.bash" -exec tail -n 40 {} \; 2>/dev/null | head -200 || true
exit 1
