#!/usr/bin/env python3
"""How the car arrived at each goal, from the traces scripts/drive_goals.py writes (--trace: t,x,y,yaw
of the true pose): per goal, the heading it arrived with (its displacement over the last second before
it first came within 0.1 m of the goal), the goal's yaw as drive_goals.py sends it (the straight line
from where the car set off: the previous goal, or --start for the first), the angle between them, and
the seconds it spent below 0.2 m/s (speed averaged over 0.5 s) in the stretch that ends at the goal,
and every other slow stretch of 0.3 s or more on the way (where, and how long: at the start, a
turn in place; on the way, a bend taken slowly); and how far the car drove to the goal (two routes
that cost about the same to a planner can differ by half a metre on the floor).
A car that arrives far off the goal's yaw crawls and turns there (docs/notebook/2026-12-05-drive-tuning-beside-navfn.md, "Arriving lined up").

Usage:
    python3 scripts/goal_approach.py [--goals "x,y;x,y"] [--start x,y] TRACE.csv [TRACE.csv ...]
    (defaults: the five lab goals from (0.4, 0.4), as drive_goals.py drives them)
"""
import argparse
import math
import os

import numpy as np

LAB_GOALS = [(4.4, 2.6), (2.45, 1.5), (1.1, 2.2), (4.2, 0.5), (0.5, 2.6)]  # drive_goals.py's
LAB_START = (0.4, 0.4)  # launch/move_base_demo.launch's start


def points(text):
    return [tuple(float(v) for v in p.split(",")) for p in text.split(";")]


def angle_between(a, b):
    return abs((a - b + 180.0) % 360.0 - 180.0)


def approaches(trace, goals, start):
    """Rows (goal, arrival heading deg, goal yaw deg, off deg, slow s at the goal, [(s, x, y) of the
    slow stretches before it], metres driven) for one trace."""
    data = np.genfromtxt(trace, delimiter=",", names=True)
    t, x, y = data["t"], data["x"], data["y"]
    dt = np.diff(t)
    step = np.hypot(np.diff(x), np.diff(y))
    speed = step / np.maximum(dt, 1e-6)
    window = max(1, int(round(0.5 / max(float(np.median(dt)), 1e-3))))
    slow = np.convolve(speed, np.ones(window) / window, mode="same") < 0.2
    rows, begin, previous = [], 0, start
    for gx, gy in goals:
        near = np.nonzero(np.hypot(x[begin:] - gx, y[begin:] - gy) < 0.1)[0]
        if len(near) == 0:
            rows.append(((gx, gy), None, None, None, None, [], None))
            break
        i = begin + int(near[0])
        j = int(np.searchsorted(t, t[i] - 1.0))
        heading = math.degrees(math.atan2(y[i] - y[j], x[i] - x[j]))
        goal_yaw = math.degrees(math.atan2(gy - previous[1], gx - previous[0]))
        k = i - 1  # the slow stretch that runs into the goal
        while k > begin and slow[k]:
            k -= 1
        stretches, m = [], begin
        while m <= k:
            if slow[m]:
                n = m
                while n <= k and slow[n]:
                    n += 1
                if t[n] - t[m] >= 0.3:
                    stretches.append((float(dt[m:n].sum()), x[m], y[m]))
                m = n
            else:
                m += 1
        rows.append(((gx, gy), heading, goal_yaw, angle_between(heading, goal_yaw), float(dt[k + 1:i].sum()), stretches,
                     float(step[begin:i].sum())))
        begin, previous = i, (gx, gy)
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--goals", help="x,y;x,y;... (default: the five lab goals)")
    parser.add_argument("--start", help="x,y where the car starts (default: the lab's, 0.4,0.4)")
    parser.add_argument("traces", nargs="+")
    args = parser.parse_args()
    goals = points(args.goals) if args.goals else LAB_GOALS
    start = points(args.start)[0] if args.start else LAB_START
    print("| trace | goal | driven | arrived heading | goal yaw | off | slow at the goal | slow on the way |")
    print("|---|---|---:|---:|---:|---:|---:|---|")
    for trace in args.traces:
        for goal, heading, yaw, off, slow, stretches, driven in approaches(trace, goals, start):
            label = os.path.splitext(os.path.basename(trace))[0]
            if heading is None:
                print("| %s | (%.2f, %.2f) | not reached | | | | | |" % (label, goal[0], goal[1]))
            else:
                way = "; ".join("%.1f s at (%.2f, %.2f)" % s for s in stretches)
                print("| %s | (%.2f, %.2f) | %.2f m | %.0f° | %.0f° | %.0f° | %.1f s | %s |" % (
                    label, goal[0], goal[1], driven, heading, yaw, off, slow, way))


if __name__ == "__main__":
    main()
