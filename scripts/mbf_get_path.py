#!/usr/bin/env python3
"""Sends one mbf_msgs/GetPath goal to Move Base Flex and prints the outcome code, its name, the
planner's message, the cost, the route's size and the time it took; with --cancel-after S it
cancels the goal S seconds after sending it and prints how long the CANCELED result took.

  /usr/bin/python3 scripts/mbf_get_path.py --start 0.5 0.5 --goal 5.5 1.0 [--tolerance 0.1]
      [--frame map] [--planner eaci] [--action /move_base_flex/get_path] [--cancel-after 1.0]
      [--expect CODE]   (exit 1 unless the outcome is CODE; names as in mbf_msgs/GetPathResult)

One line of key=value pairs on stdout (docs/notebook/2026-12-03-behind-move-base-flex.md lists the runs).
"""
import argparse
import sys
import time

import actionlib
import rospy
from geometry_msgs.msg import PoseStamped
from mbf_msgs.msg import GetPathAction, GetPathGoal, GetPathResult

# mbf_msgs/GetPathResult's named codes, and the plugin's own (src/ros/mbf_outcome.hpp).
CODE_NAMES = {getattr(GetPathResult, n): n for n in dir(GetPathResult)
              if n.isupper() and isinstance(getattr(GetPathResult, n), int)}
CODE_NAMES.update({72: 'EACI_BAD_PARAMETERS'})
NAME_CODES = {v: k for k, v in CODE_NAMES.items()}


def pose(frame, x, y):
    p = PoseStamped()
    p.header.frame_id = frame
    p.header.stamp = rospy.Time.now()
    p.pose.position.x = x
    p.pose.position.y = y
    p.pose.orientation.w = 1.0
    return p


def get_path(client, args):
    goal = GetPathGoal()
    goal.use_start_pose = True
    goal.start_pose = pose(args.frame, *args.start)
    goal.target_pose = pose(args.frame, *args.goal)
    goal.tolerance = args.tolerance
    goal.planner = args.planner
    sent = time.monotonic()
    client.send_goal(goal)
    cancel_latency = None
    if args.cancel_after is not None:
        if client.wait_for_result(rospy.Duration(args.cancel_after)):
            pass  # done before the cancel
        else:
            cancelled = time.monotonic()
            client.cancel_goal()
            client.wait_for_result(rospy.Duration(args.timeout))
            cancel_latency = time.monotonic() - cancelled
    else:
        client.wait_for_result(rospy.Duration(args.timeout))
    elapsed = time.monotonic() - sent
    return client.get_result(), elapsed, cancel_latency


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('--start', nargs=2, type=float, required=True, metavar=('X', 'Y'))
    parser.add_argument('--goal', nargs=2, type=float, required=True, metavar=('X', 'Y'))
    parser.add_argument('--tolerance', type=float, default=0.1)
    parser.add_argument('--frame', default='map')
    parser.add_argument('--planner', default='eaci')
    parser.add_argument('--action', default='/move_base_flex/get_path')
    parser.add_argument('--cancel-after', type=float, default=None, metavar='S')
    parser.add_argument('--timeout', type=float, default=120.0)
    parser.add_argument('--expect', default=None, help='a code or its name: exit 1 unless the outcome is it')
    parser.add_argument('--label', default='')
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node('mbf_get_path', anonymous=True)
    client = actionlib.SimpleActionClient(args.action, GetPathAction)
    if not client.wait_for_server(rospy.Duration(60.0)):
        print('no action server at %s' % args.action, file=sys.stderr)
        return 2
    result, elapsed, cancel_latency = get_path(client, args)
    if result is None:
        print('label=%s no result within %.0f s' % (args.label, args.timeout))
        return 1
    name = CODE_NAMES.get(result.outcome, '?')
    line = 'label=%s outcome=%d name=%s time=%.3fs cost=%.1f poses=%d' % (
        args.label, result.outcome, name, elapsed, result.cost, len(result.path.poses))
    if cancel_latency is not None:
        line += ' cancel_latency=%.1fms' % (cancel_latency * 1000.0)
    print(line + ' message="%s"' % result.message)
    if args.expect is not None:
        want = NAME_CODES.get(args.expect, None) if not args.expect.isdigit() else int(args.expect)
        return 0 if result.outcome == want else 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
