#!/usr/bin/env python3
"""rostest node: eaci_planner/EaciCostmapPlanner behind a real Move Base Flex (mbf_costmap_nav,
planner_patience 0, planner_max_retries 0: mbf_planner.test). Every get_path outcome the planner
can be driven to on test/ros/mbf_test_map.yaml comes back as its own mbf_msgs/GetPath code
(src/ros/mbf_outcome.hpp, docs/ros.md "Move Base Flex"; all but bad parameters, which
dynamic_reconfigure cannot set: it rejects them and keeps the values in force), and a cancel sent during a long plan
returns CANCELED within a fraction of a second (the measured delay is printed).
"""
import sys
import time
import unittest

import actionlib
import rospy
import rostest
from dynamic_reconfigure.client import Client
from geometry_msgs.msg import PoseStamped
from mbf_msgs.msg import GetPathAction, GetPathGoal, GetPathResult

PLANNER = "/move_base_flex/eaci"
START = (0.5, 0.5)
GOAL = (5.5, 1.0)
FAR_GOAL = (48.0, 48.0)
BLOCK = (2.0, 2.0)          # the middle of the solid 1 m block
OFF_MAP = (-1.0, -1.0)
ROOM = (4.8, 3.6)           # free, inside the closed room
CANCEL_LATENCY_LIMIT = 0.25  # s; measured a few ms (docs/notebook/2026-12-03-behind-move-base-flex.md)


def pose(xy):
    p = PoseStamped()
    p.header.frame_id = "map"
    p.header.stamp = rospy.Time.now()
    p.pose.position.x, p.pose.position.y = xy
    p.pose.orientation.w = 1.0
    return p


class MbfPlannerTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("mbf_planner_test")
        cls.client = actionlib.SimpleActionClient("/move_base_flex/get_path", GetPathAction)
        if not cls.client.wait_for_server(rospy.Duration(90.0)):
            raise RuntimeError("no /move_base_flex/get_path")
        cls.reconfigure = Client(PLANNER, timeout=60.0)
        cls.defaults = {"max_planning_time": 5.0, "max_iterations": 100, "early_stop_iterations": 10}
        # The costmap's static layer needs the map first: plan until a route comes back.
        deadline = time.monotonic() + 90.0
        while time.monotonic() < deadline:
            if cls.get_path(START, GOAL).outcome == GetPathResult.SUCCESS:
                return
            time.sleep(1.0)

    @classmethod
    def get_path(cls, start, goal, tolerance=0.1, cancel_after=None):
        goal_msg = GetPathGoal(use_start_pose=True, start_pose=pose(start), target_pose=pose(goal),
                               tolerance=tolerance, planner="eaci")
        cls.client.send_goal(goal_msg)
        cls.latency = None
        if cancel_after is not None and not cls.client.wait_for_result(rospy.Duration(cancel_after)):
            cancelled = time.monotonic()
            cls.client.cancel_goal()
            cls.client.wait_for_result(rospy.Duration(60.0))
            cls.latency = time.monotonic() - cancelled
        else:
            cls.client.wait_for_result(rospy.Duration(60.0))
        return cls.client.get_result()

    def setUp(self):
        self.reconfigure.update_configuration(self.defaults)

    def expect(self, outcome, start, goal, **kwargs):
        result = self.get_path(start, goal, **kwargs)
        self.assertIsNotNone(result)
        print("get_path %s -> %s: outcome %d, cost %.1f, %d poses, %r" %
              (start, goal, result.outcome, result.cost, len(result.path.poses), result.message), file=sys.stderr)
        self.assertEqual(result.outcome, outcome, result.message)
        return result

    def test_success(self):
        result = self.expect(GetPathResult.SUCCESS, START, GOAL)
        self.assertGreater(len(result.path.poses), 10)
        self.assertGreater(result.cost, 0.0)
        self.assertIn("route", result.message)

    def test_start_off_map(self):
        self.expect(GetPathResult.OUT_OF_MAP, OFF_MAP, GOAL)

    def test_goal_off_map(self):
        self.expect(GetPathResult.OUT_OF_MAP, START, (60.0, 60.0))

    def test_start_in_obstacle(self):
        self.expect(GetPathResult.INVALID_START, BLOCK, GOAL)

    def test_goal_in_obstacle(self):
        self.expect(GetPathResult.INVALID_GOAL, START, BLOCK)

    def test_unreachable_goal(self):
        self.expect(GetPathResult.NO_PATH_FOUND, START, ROOM)

    def test_time_limit(self):
        self.reconfigure.update_configuration({"max_planning_time": 0.001})
        self.expect(GetPathResult.PAT_EXCEEDED, START, FAR_GOAL)

    def test_cancel(self):
        self.reconfigure.update_configuration({"max_planning_time": 60.0, "max_iterations": 1000000,
                                               "early_stop_iterations": 0})
        started = time.monotonic()
        result = self.expect(GetPathResult.CANCELED, START, FAR_GOAL, cancel_after=1.0)
        print("cancel after %.2f s: CANCELED %.1f ms after the cancel" % (time.monotonic() - started - self.latency,
                                                                           self.latency * 1000.0), file=sys.stderr)
        self.assertLess(self.latency, CANCEL_LATENCY_LIMIT)


if __name__ == "__main__":
    rostest.rosrun("eaci_planner", "mbf_planner", MbfPlannerTest)
