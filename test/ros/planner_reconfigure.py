#!/usr/bin/env python3
"""rostest node: eaci_planner_node's parameters change at run time through dynamic_reconfigure.
A bad value at start is named on every request, which fails, until a reconfigure fixes it; a bad
value from dynamic_reconfigure is rejected with an error naming it, plans go on with the values in
force, and the reconfigure's answer carries them.

The node (planner_reconfigure.test) starts on the lab map with kappa: 0.0, out of (0, 1.3] (inside
the cfg's range, so dynamic_reconfigure does not clamp it).
"""
import math
import threading
import time
import unittest

import rospy
import rostest
from dynamic_reconfigure.client import Client
from geometry_msgs.msg import PoseStamped
from nav_msgs.msg import Path
from nav_msgs.srv import GetPlan
from rosgraph_msgs.msg import Log

NODE = "/eaci_planner_node"
START = (0.4, 0.4)
GOAL = (4.4, 2.6)
WALL_GOAL = (0.025, 1.5)  # a border-wall cell, one cell (0.05 m) from free space


def pose(xy, yaw=0.0):
    p = PoseStamped()
    p.header.frame_id = "map"
    p.pose.position.x, p.pose.position.y = xy
    p.pose.orientation.z = math.sin(yaw / 2)
    p.pose.orientation.w = math.cos(yaw / 2)
    return p


def yaw_of(p):
    q = p.pose.orientation
    return 2.0 * math.atan2(q.z, q.w)


def same_heading(a, b):
    return abs(math.cos(a) - math.cos(b)) < 1e-6 and abs(math.sin(a) - math.sin(b)) < 1e-6


class PlannerReconfigure(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.wait_for_service(NODE + "/make_plan", timeout=30)
        cls.make_plan = rospy.ServiceProxy(NODE + "/make_plan", GetPlan)
        cls.client = Client(NODE, timeout=30)
        cls.errors = []
        cls.lock = threading.Lock()
        log = rospy.Subscriber("/rosout", Log, cls.on_log)
        deadline = time.time() + 10.0  # the node's errors reach only a connected subscriber
        while log.get_num_connections() == 0 and time.time() < deadline:
            time.sleep(0.05)

    @classmethod
    def on_log(cls, msg):
        if msg.level == Log.ERROR and msg.name == NODE:
            with cls.lock:
                cls.errors.append(msg.msg)

    def plan(self, goal=GOAL, tolerance=0.0, start_yaw=0.0, goal_yaw=0.0):
        return self.make_plan(pose(START, start_yaw), pose(goal, goal_yaw), tolerance).plan.poses

    def clear_errors(self):
        with self.lock:
            del self.errors[:]

    def assert_logged(self, text):
        """The node logs (since clear_errors) an error containing `text`."""
        deadline = time.time() + 5.0
        while time.time() < deadline:
            with self.lock:
                if any(text in e for e in self.errors):
                    return
            time.sleep(0.05)
        with self.lock:
            self.fail("no error containing %r; errors: %r" % (text, self.errors))

    def assert_refused_naming(self, text):
        """The next plan is empty and the node logs an error containing `text`."""
        self.clear_errors()
        self.assertEqual(self.plan(), [], "planned although a parameter is bad")
        self.assert_logged(text)

    def assert_rejected(self, change, text, in_force):
        """Reconfiguring with `change` is rejected with an error containing `text`; the answer
        carries the values in force (`in_force`), and plans go on."""
        self.clear_errors()
        config = self.client.update_configuration(change)
        self.assert_logged(text)
        for name, value in in_force.items():
            self.assertEqual(config[name], value, name)
        self.assert_reaches(self.plan())

    def assert_reaches(self, poses, goal=GOAL, within=1e-6):
        self.assertGreater(len(poses), 2)
        last = poses[-1].pose.position
        self.assertLessEqual(math.hypot(last.x - goal[0], last.y - goal[1]), within)

    def test_1_a_bad_start_value_is_named_until_it_is_fixed(self):
        start_error = NODE + "/kappa must be in (0, 1.3] (got 0): refusing to plan until it is fixed"
        for _ in range(2):  # every request, not only the first
            self.assert_refused_naming(start_error)
        # Changing another parameter is not a fix: rejected, kappa still named.
        self.clear_errors()
        config = self.client.update_configuration({"cost_factor": 1.0})
        self.assert_logged("reconfigure rejected: " + NODE + "/kappa must be in (0, 1.3] (got 0)")
        self.assertEqual(config["cost_factor"], 0.8)  # the value in force, written back
        self.assert_refused_naming(start_error)
        config = self.client.update_configuration({"kappa": 0.5})
        self.assertEqual(config["kappa"], 0.5)
        self.assert_reaches(self.plan())

    def test_2_a_bad_value_at_run_time_is_rejected_and_plans_go_on(self):
        self.assert_rejected({"kappa": 0.0},
                             "reconfigure rejected: " + NODE + "/kappa must be in (0, 1.3] (got 0); "
                             "the values in force stay (kappa stays 0.5)", {"kappa": 0.5})
        self.assert_rejected({"algorithm": "dijkstra", "cost_factor": 2.0},
                             "reconfigure rejected: " + NODE + "/algorithm must be eaci or astar (got 'dijkstra'",
                             {"algorithm": "astar", "cost_factor": 0.8})
        # Outside the cfg's range: clamped by dynamic_reconfigure (as global_planner's), then valid.
        config = self.client.update_configuration({"kappa": 1.5})
        self.assertEqual(config["kappa"], 1.3)
        self.assert_reaches(self.plan())
        config = self.client.update_configuration({"kappa": 0.5})
        self.assertEqual(config["kappa"], 0.5)

    def test_3_default_tolerance_and_the_requests_own(self):
        self.client.update_configuration({"default_tolerance": 0.0})
        self.assertEqual(self.plan(goal=WALL_GOAL), [])
        self.assert_reaches(self.plan(goal=WALL_GOAL, tolerance=0.2), WALL_GOAL, 0.2)  # the request's own
        self.client.update_configuration({"default_tolerance": 0.2})
        self.assert_reaches(self.plan(goal=WALL_GOAL), WALL_GOAL, 0.2)
        self.client.update_configuration({"default_tolerance": 0.0})
        self.assertEqual(self.plan(goal=WALL_GOAL), [])

    def test_4_orientation_mode(self):
        # global_planner's numbers: 4 backward (-x along the route), 0 none (heading 0).
        self.client.update_configuration({"orientation_mode": 4})
        poses = self.plan(start_yaw=0.7, goal_yaw=1.2)
        self.assert_reaches(poses)
        for k in range(len(poses) - 1):
            a, b = poses[k].pose.position, poses[k + 1].pose.position
            if math.hypot(b.x - a.x, b.y - a.y) < 1e-9:
                continue
            along = math.atan2(b.y - a.y, b.x - a.x)
            self.assertTrue(same_heading(yaw_of(poses[k]), along + math.pi), "pose %d" % k)
        self.assertTrue(same_heading(yaw_of(poses[-1]), 1.2))
        self.client.update_configuration({"orientation_mode": 0})
        poses = self.plan(start_yaw=0.7, goal_yaw=1.2)
        self.assertTrue(same_heading(yaw_of(poses[0]), 0.7))
        for k in range(1, len(poses) - 1):
            self.assertTrue(same_heading(yaw_of(poses[k]), 0.0), "pose %d" % k)
        self.assertTrue(same_heading(yaw_of(poses[-1]), 1.2))
        self.client.update_configuration({"orientation_mode": 1})

    def test_5_publish_plan(self):
        received = []
        sub = rospy.Subscriber(NODE + "/plan", Path, lambda msg: received.append(msg))
        rospy.sleep(1.0)  # the latched last plan arrives first
        self.client.update_configuration({"publish_plan": False})
        before = len(received)
        self.assert_reaches(self.plan())
        rospy.sleep(1.0)
        self.assertEqual(len(received), before, "published although publish_plan is false")
        self.client.update_configuration({"publish_plan": True})
        self.assert_reaches(self.plan())
        deadline = time.time() + 5.0
        while len(received) == before and time.time() < deadline:
            time.sleep(0.05)
        self.assertGreater(len(received), before, "not published although publish_plan is true")
        sub.unregister()

    def test_6_turn_cost(self):
        # The price of turning reaches the planner at run time: unsmoothed, so that the returned
        # poses are the grid route's cells, whose heading changes are what turn_cost prices. The
        # lab route from START to GOAL cannot be straight, so a dear turn leaves fewer of them.
        def total_turn(poses):
            headings = [math.atan2(b.pose.position.y - a.pose.position.y, b.pose.position.x - a.pose.position.x)
                        for a, b in zip(poses, poses[1:])]
            return sum(abs(math.atan2(math.sin(h2 - h1), math.cos(h2 - h1))) for h1, h2 in zip(headings, headings[1:]))

        self.client.update_configuration({"smooth_path": False, "turn_cost": 0.0})
        free = self.plan()
        self.assert_reaches(free)
        config = self.client.update_configuration({"turn_cost": 50.0})
        self.assertEqual(config["turn_cost"], 50.0)
        dear = self.plan()
        self.assert_reaches(dear)
        self.assertGreater(total_turn(dear), 0.0)
        self.assertLess(total_turn(dear), total_turn(free) - math.pi / 8,
                        "turn_cost 50 left the route turning %.3f rad against %.3f rad at 0"
                        % (total_turn(dear), total_turn(free)))
        self.client.update_configuration({"smooth_path": True, "turn_cost": 0.0})


if __name__ == "__main__":
    rospy.init_node("planner_reconfigure_test")
    rostest.rosrun("eaci_planner", "planner_reconfigure", PlannerReconfigure)
