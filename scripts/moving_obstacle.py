#!/usr/bin/python3
"""A moving obstacle the map does not hold, as a laser sees it: a synthetic sensor_msgs/LaserScan.

A disc of --radius metres moves back and forth between --from and --to at --speed m/s; a laser
fixed at --sensor (the frame `moving_obstacle_laser`, published here as a static transform from
`map`) sees it at --rate Hz: each of its 720 rays gets the distance to the disc, or +inf where it
misses (costmap_2d's obstacle layer clears along those with inf_is_valid). Feed it to a
costmap's obstacle layer (config/moving_obstacle_costmap.yaml) to have the planners route round
something that moves; the disc's position goes out on /moving_obstacle/position
(geometry_msgs/PointStamped) too.
    /usr/bin/python3 scripts/moving_obstacle.py --sensor 2.4,1.5 --from 1.0,1.2 --to 3.8,1.2
"""
import argparse
import math

import rospy
import tf2_ros
from geometry_msgs.msg import PointStamped, TransformStamped
from sensor_msgs.msg import LaserScan


def point(text):
    x, y = (float(v) for v in text.split(","))
    return x, y


def disc_at(t, a, b, speed):
    """Where the disc is t seconds in: from a to b and back."""
    length = math.hypot(b[0] - a[0], b[1] - a[1])
    if length == 0 or speed <= 0:
        return a
    s = (t * speed) % (2 * length)
    f = s / length if s <= length else 2 - s / length
    return a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])


def range_to_disc(angle, sensor, centre, radius):
    """Distance along the ray from `sensor` at `angle` to the disc, or inf."""
    dx, dy = math.cos(angle), math.sin(angle)
    cx, cy = centre[0] - sensor[0], centre[1] - sensor[1]
    along = cx * dx + cy * dy
    off2 = cx * cx + cy * cy - along * along
    if along <= 0 or off2 > radius * radius:
        return math.inf
    return along - math.sqrt(radius * radius - off2)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sensor", type=point, default=(2.4, 1.5), help="x,y of the laser in the map frame")
    parser.add_argument("--from", dest="a", type=point, default=(1.0, 1.2))
    parser.add_argument("--to", dest="b", type=point, default=(3.8, 1.2))
    parser.add_argument("--speed", type=float, default=0.3, help="m/s")
    parser.add_argument("--radius", type=float, default=0.15, help="m")
    parser.add_argument("--rate", type=float, default=10.0, help="Hz")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("moving_obstacle")
    static = tf2_ros.StaticTransformBroadcaster()
    t = TransformStamped()
    t.header.stamp = rospy.Time.now()
    t.header.frame_id = "map"
    t.child_frame_id = "moving_obstacle_laser"
    t.transform.translation.x, t.transform.translation.y = args.sensor
    t.transform.rotation.w = 1.0
    static.sendTransform(t)
    scans = rospy.Publisher("/moving_obstacle/scan", LaserScan, queue_size=1)
    where = rospy.Publisher("/moving_obstacle/position", PointStamped, queue_size=1)
    rays = 720
    began = rospy.Time.now()
    rate = rospy.Rate(args.rate)
    while not rospy.is_shutdown():
        now = rospy.Time.now()
        centre = disc_at((now - began).to_sec(), args.a, args.b, args.speed)
        scan = LaserScan()
        scan.header.stamp = now
        scan.header.frame_id = "moving_obstacle_laser"
        scan.angle_min, scan.angle_max = -math.pi, math.pi - 2 * math.pi / rays
        scan.angle_increment = 2 * math.pi / rays
        scan.range_min, scan.range_max = 0.05, 8.0
        scan.ranges = [range_to_disc(scan.angle_min + k * scan.angle_increment, args.sensor, centre, args.radius)
                       for k in range(rays)]
        scans.publish(scan)
        p = PointStamped()
        p.header = scan.header
        p.header.frame_id = "map"
        p.point.x, p.point.y = centre
        where.publish(p)
        try:
            rate.sleep()
        except rospy.ROSInterruptException:
            break


if __name__ == "__main__":
    main()
