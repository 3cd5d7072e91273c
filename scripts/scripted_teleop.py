#!/usr/bin/python3
"""Drives the simulated car through waypoints as a person with a joystick would: turn towards the
next point, then drive to it, steering as it goes. The paper mapped its lab this way (Section 7:
driven by hand while gmapping built the map); this is that hand, scripted, so a map comes out the
same from run to run.

It watches the car's true pose (diff_drive_sim's ~ground_truth: the driver sees the car) and
publishes cmd_vel. The waypoints must be joined by straight lines through free space; the default
tours the bundled lab (maps/lab.yaml) from the demo's start (0.4, 0.4): along its walls, between
its obstacles and into the U.
    /usr/bin/python3 scripts/scripted_teleop.py [--waypoints "x,y;x,y;..."] [--speed 0.2]
Exit 0 once the last waypoint is reached, 1 when the car has not moved towards one for --stall s.
"""
import argparse
import math
import sys

import rospy
from geometry_msgs.msg import Twist
from nav_msgs.msg import Odometry

LAB_TOUR = [(1.75, 0.4), (3.2, 0.4), (4.4, 0.4), (4.4, 1.35), (4.4, 2.6), (3.2, 2.6), (2.0, 2.6), (0.4, 2.6),
            (0.4, 1.4), (1.75, 1.4), (2.45, 1.5), (1.75, 1.4), (1.75, 0.4), (0.4, 0.4)]


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--waypoints", help="x,y;x,y;... in metres, map frame (default: a tour of the lab)")
    parser.add_argument("--speed", type=float, default=0.2, help="m/s on the straight")
    parser.add_argument("--turn-speed", type=float, default=0.8, help="rad/s turning on the spot")
    parser.add_argument("--reach", type=float, default=0.05, help="m: a waypoint is reached within this")
    parser.add_argument("--stall", type=float, default=30.0, help="s without getting nearer a waypoint: give up")
    args = parser.parse_args(rospy.myargv()[1:])  # without the __name:= and remappings roslaunch adds
    waypoints = LAB_TOUR if not args.waypoints else [
        tuple(float(v) for v in w.split(",")) for w in args.waypoints.split(";")]

    rospy.init_node("scripted_teleop")
    pose = [None]

    def on_truth(msg):
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        pose[0] = (p.x, p.y, math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z)))

    rospy.Subscriber("/diff_drive_sim/ground_truth", Odometry, on_truth, queue_size=10)
    cmd = rospy.Publisher("cmd_vel", Twist, queue_size=1)
    rate = rospy.Rate(20)
    while pose[0] is None and not rospy.is_shutdown():
        rate.sleep()
    for number, (wx, wy) in enumerate(waypoints, 1):
        best, best_time = float("inf"), rospy.get_time()
        while not rospy.is_shutdown():
            x, y, yaw = pose[0]
            distance = math.hypot(wx - x, wy - y)
            if distance < args.reach:
                break
            if distance < best - 0.01:
                best, best_time = distance, rospy.get_time()
            elif rospy.get_time() - best_time > args.stall:
                cmd.publish(Twist())
                sys.exit("scripted_teleop: no nearer waypoint %d (%.2f, %.2f) in %.0f s; the car is at (%.2f, %.2f)" % (
                    number, wx, wy, args.stall, x, y))
            error = math.atan2(math.sin(math.atan2(wy - y, wx - x) - yaw), math.cos(math.atan2(wy - y, wx - x) - yaw))
            twist = Twist()
            if abs(error) > 0.15:  # turn on the spot first
                twist.angular.z = math.copysign(min(args.turn_speed, max(0.3, 2.0 * abs(error))), error)
            else:
                twist.linear.x = min(args.speed, max(0.05, distance))
                twist.angular.z = 2.0 * error
            cmd.publish(twist)
            rate.sleep()
        rospy.loginfo("scripted_teleop: waypoint %d of %d (%.2f, %.2f) reached", number, len(waypoints), wx, wy)
    cmd.publish(Twist())
    rospy.sleep(0.5)


if __name__ == "__main__":
    main()
