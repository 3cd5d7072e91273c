#!/usr/bin/env python3
"""rostest node: the demo's car reports arrival, and its true pose is then near the goal.

Private parameters: goal_x, goal_y (m), tolerance (m), timeout (s).
"""
import math
import threading
import unittest

import rospy
import rostest
from nav_msgs.msg import Odometry
from std_msgs.msg import Bool


class DemoArrives(unittest.TestCase):
    def test_car_arrives_at_the_goal(self):
        goal = (rospy.get_param("~goal_x"), rospy.get_param("~goal_y"))
        tolerance = rospy.get_param("~tolerance", 0.15)
        timeout = rospy.get_param("~timeout", 150.0)
        arrived = threading.Event()
        pose = {}

        def on_arrived(msg):
            if msg.data:
                arrived.set()

        def on_truth(msg):
            pose["xy"] = (msg.pose.pose.position.x, msg.pose.pose.position.y)

        rospy.Subscriber("/pid_path_follower/arrived", Bool, on_arrived)
        rospy.Subscriber("/diff_drive_sim/ground_truth", Odometry, on_truth)
        self.assertTrue(arrived.wait(timeout), "the follower did not report arrival within %.0f s" % timeout)
        rospy.sleep(0.5)
        self.assertIn("xy", pose, "no ground truth from diff_drive_sim")
        miss = math.hypot(pose["xy"][0] - goal[0], pose["xy"][1] - goal[1])
        self.assertLessEqual(miss, tolerance, "stopped %.3f m from the goal (%.2f, %.2f)" % (miss, goal[0], goal[1]))


if __name__ == "__main__":
    rospy.init_node("arrival_check")
    rostest.rosrun("eaci_planner", "demo_arrives", DemoArrives)
