#!/usr/bin/env python3
"""rostest node (gmapping_lab.test): once the car has driven its tour, the map gmapping publishes
has the paper's 5 cm cells and holds the lab (maps/lab.yaml, 4.8 x 3.0 m, walls one cell thick
on its edges, obstacles known by hand): free where the car drove, occupied on the walls it saw
beside it and on the cube it passed, unknown outside the lab. gmapping's map frame starts at the
car's odometry frame, which starts on the world's, so the lab's coordinates hold up to its error,
a cell or two: each check looks within 0.1 m."""
import sys
import unittest

import numpy as np
import rospy
import rostest
from nav_msgs.msg import OccupancyGrid, Odometry

FREE = [(0.4, 0.4), (1.75, 0.4), (3.2, 0.4), (1.75, 1.4), (0.4, 1.4)]   # on the tour
WALLS = [(1.75, 0.025), (3.2, 0.025), (0.025, 0.8), (1.275, 0.825)]   # bottom wall, left wall, the cube at x 1.1-1.45, y 0.65-1.0
OUTSIDE = [(-0.6, -0.6), (5.4, 3.6)]


class GmappingLab(unittest.TestCase):
    def test_the_map_holds_the_lab(self):
        rospy.init_node("gmapping_lab_test")
        # The tour goes out to (3.2, 0.4) and ends back at the start: wait for that, then for a
        # map gmapping made after it (it publishes every 2 s).
        state = {"away": False, "back": False}

        def on_truth(msg):
            p = msg.pose.pose.position
            distance = np.hypot(p.x - 0.4, p.y - 0.4)
            state["away"] = state["away"] or distance > 2.0
            state["back"] = state["away"] and distance < 0.08

        rospy.Subscriber("/diff_drive_sim/ground_truth", Odometry, on_truth)
        deadline = rospy.get_time() + 170
        while not state["back"] and rospy.get_time() < deadline and not rospy.is_shutdown():
            rospy.sleep(0.5)
        self.assertTrue(state["back"], "the car did not come back from its tour")
        rospy.sleep(4.0)
        grid = rospy.wait_for_message("/map", OccupancyGrid, timeout=60)
        info = grid.info
        self.assertAlmostEqual(info.resolution, 0.05, places=4)
        cells = np.array(grid.data, dtype=np.int16).reshape(info.height, info.width)

        def around(x, y, reach=0.1):
            c = int((x - info.origin.position.x) / info.resolution)
            r = int((y - info.origin.position.y) / info.resolution)
            k = int(round(reach / info.resolution))
            return cells[max(r - k, 0):r + k + 1, max(c - k, 0):c + k + 1]

        for x, y in FREE:
            self.assertTrue((around(x, y, 0.05) == 0).any(), "no free cell near (%.2f, %.2f)" % (x, y))
        for x, y in WALLS:
            self.assertTrue((around(x, y) == 100).any(), "no occupied cell near the wall at (%.2f, %.2f)" % (x, y))
        for x, y in OUTSIDE:
            self.assertTrue((around(x, y, 0.0) == -1).all(), "(%.2f, %.2f), outside the lab, is not unknown" % (x, y))


if __name__ == "__main__":
    rostest.rosrun("eaci_planner", "gmapping_lab", GmappingLab, sys.argv)
