#!/usr/bin/python3
"""Asks a running move_base for plans on the lab map and measures them.

For each goal: /move_base/make_plan from the start, then the plan's pose count, length, total
heading change (sum of |turn| between consecutive segments), minimum clearance (distance from
a pose to the nearest occupied cell centre of the map image) and the call's wall time.
Start move_base first (launch/move_base_demo.launch; see docs/ros.md), then:
    /usr/bin/python3 scripts/probe_make_plan.py [--map maps/lab.yaml] [--start 0.4,0.4]
"""
import argparse
import math
import os
import time

import rospy
import yaml
from geometry_msgs.msg import PoseStamped
from nav_msgs.srv import GetPlan

LAB_GOALS = [(4.4, 2.6), (2.45, 1.5), (1.1, 2.2), (4.2, 0.5), (0.5, 2.6)]  # across the L, into the U, past the cubes


def occupied_centres(yaml_path):
    """Centres (m) of the occupied cells of a map_server map with a binary P5 PGM image."""
    meta = yaml.safe_load(open(yaml_path))
    data = open(os.path.join(os.path.dirname(yaml_path), meta["image"]), "rb").read()
    header = [t for line in data.split(b"\n")[:4] if not line.startswith(b"#") for t in line.split()]
    width, height = int(header[1]), int(header[2])
    pixels = data[-width * height:]
    res, (ox, oy) = meta["resolution"], meta["origin"][:2]
    return [(ox + (c + 0.5) * res, oy + (height - 1 - r + 0.5) * res)
            for r in range(height) for c in range(width) if pixels[r * width + c] < 128]


def pose(x, y):
    p = PoseStamped()
    p.header.frame_id = "map"
    p.pose.position.x, p.pose.position.y, p.pose.orientation.w = x, y, 1.0
    return p


def measure(points, obstacles):
    length = sum(math.dist(points[i], points[i + 1]) for i in range(len(points) - 1))
    headings = [math.atan2(b[1] - a[1], b[0] - a[0]) for a, b in zip(points, points[1:]) if a != b]
    turn = sum(abs(math.remainder(h2 - h1, 2 * math.pi)) for h1, h2 in zip(headings, headings[1:]))
    clearance = min(math.dist(p, o) for p in points for o in obstacles)
    return length, math.degrees(turn), clearance


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", default=os.path.join(os.path.dirname(__file__), "..", "maps", "lab.yaml"))
    parser.add_argument("--start", default="0.4,0.4")
    args = parser.parse_args()
    start = tuple(float(v) for v in args.start.split(","))
    obstacles = occupied_centres(args.map)
    rospy.init_node("probe_make_plan", anonymous=True)
    rospy.wait_for_service("/move_base/make_plan", 30)
    make_plan = rospy.ServiceProxy("/move_base/make_plan", GetPlan)
    for gx, gy in LAB_GOALS:
        t0 = time.time()
        plan = make_plan(start=pose(*start), goal=pose(gx, gy), tolerance=0.0).plan
        ms = (time.time() - t0) * 1000
        points = [(p.pose.position.x, p.pose.position.y) for p in plan.poses]
        if len(points) < 2:
            print("goal (%.2f, %.2f): no plan" % (gx, gy))
            continue
        length, turn, clearance = measure(points, obstacles)
        print("goal (%.2f, %.2f): %d poses, length %.2f m, turn %.0f deg, min clearance %.3f m, %.0f ms"
              % (gx, gy, len(points), length, turn, clearance, ms))


if __name__ == "__main__":
    main()
