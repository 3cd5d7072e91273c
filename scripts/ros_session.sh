# Sourced by the scripts that run ROS nodes on a rosmaster of their own (drive_compare.sh,
# compare_make_plan.sh, map_the_lab.sh, rviz_screenshot.sh). What they start in the background
# goes into `pids`; ros_cleanup stops it all (SIGINT, then SIGKILL 3 s later) and runs on exit;
# ros_core PORT LOG starts a rosmaster on PORT for this shell (ROS_MASTER_URI) and gives it 3 s.
pids=()
ros_cleanup() {
  for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null || true; done
  [ ${#pids[@]} -eq 0 ] || sleep 3
  for p in "${pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  pids=()
}
ros_core() {
  export ROS_MASTER_URI=http://localhost:$1
  roscore -p "$1" >"$2" 2>&1 & pids+=($!)
  sleep 3
}
trap ros_cleanup EXIT
