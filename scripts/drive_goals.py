#!/usr/bin/python3
"""Drives the simulated car through a running move_base to goals on the lab map and measures each drive.

For each goal, sent as a move_base action from wherever the car stopped last (facing the straight
line to the goal): the outcome (move_base's final state), the time taken, the distance from the
car's true position (diff_drive_sim's ~ground_truth, not its noisy odometry) to the goal, the
number of global plans move_base asked for, the minimum clearance of the car's centre and of its
footprint from the map's occupied cells along the drive, and whether the footprint ever touched an
occupied cell.

Footprint clearance is the distance from the car's rectangle (config/costmap_common_params.yaml,
without padding) to the centre of an occupied cell, less half a cell: contact means <= 0.

Every global plan published during a drive is checked too: its smallest centre clearance from the
occupied cells, and it counts as invalid when that is below --plan-clearance (the car's inscribed
radius with the footprint padding: inside it the costmap marks the cell lethal). And against the
global costmap as move_base published it: a plan counts as through a lethal cell when one of its
poses lies in a cell that was lethal both in the last costmap published before the plan and in the
first after it (so a box that moved between the two does not count).

When the car carries the simulated laser (diff_drive_sim with a world map), the world may hold
obstacles the map does not (boxes, a moving box): the car's footprint clearance from all of them
comes from diff_drive_sim's ~footprint_clearance, and a sample at 0 is a contact with the world.

For a long replanning run (move_base with planner_frequency > 0), --duration keeps cycling through
the goals until that many seconds have passed, and --memory-of samples a node's resident memory.

Start move_base first (launch/move_base_demo.launch; see docs/ros.md), then:
    /usr/bin/python3 scripts/drive_goals.py [--rounds 3] [--map maps/lab.yaml] [--json out.json]
    /usr/bin/python3 scripts/drive_goals.py --duration 600 --memory-of move_base --json soak.json

To time every goal beside another planner, drive both (scripts/drive_compare.sh does it, launching
move_base with each in turn) and compare the records; the first file is the reference:
    /usr/bin/python3 scripts/drive_goals.py --compare navfn=navfn1.json,navfn2.json eaci=eaci1.json,eaci2.json
"""
import argparse
import glob
import itertools
import json
import math
import os
import sys
import time

import actionlib
import numpy as np
import rospy
import yaml
from actionlib_msgs.msg import GoalStatus
from move_base_msgs.msg import MoveBaseAction, MoveBaseGoal
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid, Odometry, Path
from std_msgs.msg import Float64

LAB_GOALS = [(4.4, 2.6), (2.45, 1.5), (1.1, 2.2), (4.2, 0.5), (0.5, 2.6)]  # across the L, into the U, past the cubes
HALF_LENGTH, HALF_WIDTH = 0.1325, 0.1025  # the WHEELTEC Mini car, 265 x 205 mm
STATES = {v: k for k, v in GoalStatus.__dict__.items() if k.isupper() and isinstance(v, int)}


class OccupiedCells:
    """The occupied cells of a map_server map (binary P5 PGM, trinary reading), for clearance queries."""

    def __init__(self, yaml_path):
        meta = yaml.safe_load(open(yaml_path))
        data = open(os.path.join(os.path.dirname(os.path.abspath(yaml_path)), meta["image"]), "rb").read()
        tokens, pos = [], 0
        while len(tokens) < 4:  # P5 width height maxval, comments skipped
            end = data.index(b"\n", pos)
            line = data[pos:end].split(b"#")[0]
            tokens += line.split()
            pos = end + 1
        width, height = int(tokens[1]), int(tokens[2])
        pixels = np.frombuffer(data[-width * height:], dtype=np.uint8).reshape(height, width)
        occupied = (255 - pixels) / 255.0 > meta.get("occupied_thresh", 0.65)
        if meta.get("negate", 0):
            occupied = pixels / 255.0 > meta.get("occupied_thresh", 0.65)
        self.occupied = np.flipud(occupied)  # row 0 = lowest y
        self.res = meta["resolution"]
        self.ox, self.oy = meta["origin"][:2]

    def nearby(self, x, y, radius):
        """Centres (N x 2) of occupied cells within a square of half-side `radius` around (x, y)."""
        c0 = max(int((x - radius - self.ox) / self.res), 0)
        c1 = min(int((x + radius - self.ox) / self.res) + 1, self.occupied.shape[1])
        r0 = max(int((y - radius - self.oy) / self.res), 0)
        r1 = min(int((y + radius - self.oy) / self.res) + 1, self.occupied.shape[0])
        rows, cols = np.nonzero(self.occupied[r0:r1, c0:c1])
        return np.column_stack((self.ox + (cols + c0 + 0.5) * self.res, self.oy + (rows + r0 + 0.5) * self.res))

    def clearances(self, x, y, yaw):
        """(centre clearance, footprint clearance) in metres, capped at 0.6 m."""
        cells = self.nearby(x, y, 0.6)
        if len(cells) == 0:
            return 0.6, 0.6
        d = cells - (x, y)
        centre = float(np.min(np.hypot(d[:, 0], d[:, 1])))
        c, s = math.cos(yaw), math.sin(yaw)
        along, across = d[:, 0] * c + d[:, 1] * s, -d[:, 0] * s + d[:, 1] * c
        outside = np.hypot(np.maximum(np.abs(along) - HALF_LENGTH, 0), np.maximum(np.abs(across) - HALF_WIDTH, 0))
        return min(centre, 0.6), min(float(np.min(outside)) - self.res / 2, 0.6)


class PublishedCostmap:
    """move_base's global costmap as published (the full grid and its updates), and the plans whose poses
    fall in a cell lethal (100 on the topic: costmap_2d's 254) before and after each plan."""

    def __init__(self, ns="/move_base/global_costmap"):
        self.grid = None  # (info, numpy rows x cols) as last published
        self.before = None  # the lethal mask of the costmap published before the current one
        self.pending = []  # (stamp, [(x, y)], lethal mask before it) of plans awaiting the next costmap
        self.lethal_plans = 0
        self.checked = 0
        rospy.Subscriber(ns + "/costmap", OccupancyGrid, self.on_costmap, queue_size=2)
        rospy.Subscriber(ns + "/costmap_updates", OccupancyGridUpdate, self.on_update, queue_size=10)

    def on_costmap(self, msg):
        info = msg.info
        self.grid = (info, np.array(msg.data, dtype=np.int8).reshape(info.height, info.width))
        self.settle(msg.header.stamp.to_sec())

    def on_update(self, msg):
        if self.grid is None:
            return
        data = np.array(msg.data, dtype=np.int8).reshape(msg.height, msg.width)
        self.grid[1][msg.y:msg.y + msg.height, msg.x:msg.x + msg.width] = data
        self.settle(msg.header.stamp.to_sec())

    def lethal(self):
        return None if self.grid is None else (self.grid[1] == 100)

    def settle(self, stamp):
        """The costmap just published at `stamp` is the first after the pending plans made before it."""
        now = self.lethal()
        keep = []
        for plan_stamp, poses, before in self.pending:
            if plan_stamp > stamp or before is None:
                keep.append((plan_stamp, poses, before if before is not None else now))
                continue
            self.checked += 1
            info = self.grid[0]
            for x, y in poses:
                col = int(math.floor((x - info.origin.position.x) / info.resolution))
                row = int(math.floor((y - info.origin.position.y) / info.resolution))
                if 0 <= row < now.shape[0] and 0 <= col < now.shape[1] and before.shape == now.shape \
                        and now[row, col] and before[row, col]:
                    self.lethal_plans += 1
                    break
        self.pending = keep

    def add_plan(self, stamp, poses):
        self.pending.append((stamp, poses, self.lethal()))


class Drive:
    def __init__(self, cells, plan_clearance):
        self.cells = cells
        self.plan_clearance = plan_clearance
        self.pose = None
        self.costmap = PublishedCostmap()
        self.world_seen = False
        self.reset()
        rospy.Subscriber("/diff_drive_sim/ground_truth", Odometry, self.on_truth, queue_size=50)
        rospy.Subscriber("/diff_drive_sim/footprint_clearance", Float64, self.on_world_clearance, queue_size=50)
        self.plan_topics = []
        self.trace = []  # (t, x, y, yaw) of the true pose, every drive, for --trace
        self.plan_log = []  # (t, [(x, y), ...]) of every global plan, for --trace

    def reset(self):
        self.min_centre = self.min_footprint = float("inf")
        self.contacts = 0
        self.plans = 0
        self.invalid_plans = 0
        self.min_plan_clearance = float("inf")
        self.min_world = float("inf")
        self.world_contacts = 0
        self.lethal_plans_before = self.costmap.lethal_plans

    def on_world_clearance(self, msg):
        self.world_seen = True
        self.min_world = min(self.min_world, msg.data)
        if msg.data <= 0:
            self.world_contacts += 1

    def on_truth(self, msg):
        p, q = msg.pose.pose.position, msg.pose.pose.orientation
        yaw = math.atan2(2 * (q.w * q.z + q.x * q.y), 1 - 2 * (q.y * q.y + q.z * q.z))
        self.pose = (p.x, p.y, yaw)
        self.trace.append((msg.header.stamp.to_sec(), p.x, p.y, yaw))
        centre, footprint = self.cells.clearances(p.x, p.y, yaw)
        self.min_centre = min(self.min_centre, centre)
        self.min_footprint = min(self.min_footprint, footprint)
        if footprint <= 0:
            self.contacts += 1

    def on_plan(self, msg):
        if msg.poses:
            self.plans += 1
            clearance = min(self.cells.clearances(p.pose.position.x, p.pose.position.y, 0.0)[0] for p in msg.poses)
            self.min_plan_clearance = min(self.min_plan_clearance, clearance)
            if clearance < self.plan_clearance:
                self.invalid_plans += 1
            self.plan_log.append((msg.header.stamp.to_sec(), [(p.pose.position.x, p.pose.position.y) for p in msg.poses]))
            self.costmap.add_plan(msg.header.stamp.to_sec(), self.plan_log[-1][1])

    def watch_plans(self):
        """Counts the global planner's published plans (…/plan topics of move_base's global planner)."""
        for topic, kind in rospy.get_published_topics("/move_base"):
            if kind == "nav_msgs/Path" and topic.endswith("/plan") and topic not in self.plan_topics:
                rospy.Subscriber(topic, Path, self.on_plan, queue_size=10)
                self.plan_topics.append(topic)


def resident_kib(node_name):
    """VmRSS (KiB) of the process started as ROS node `node_name` (its __name:= argument), or None."""
    for cmdline in glob.glob("/proc/[0-9]*/cmdline"):
        try:
            args = open(cmdline, "rb").read().split(b"\0")
            if ("__name:=" + node_name).encode() in args:
                for line in open(cmdline.replace("cmdline", "status")):
                    if line.startswith("VmRSS:"):
                        return int(line.split()[1])
        except OSError:
            continue
    return None


def goal_message(x, y, yaw):
    goal = MoveBaseGoal()
    goal.target_pose.header.frame_id = "map"
    goal.target_pose.header.stamp = rospy.Time.now()
    goal.target_pose.pose.position.x, goal.target_pose.pose.position.y = x, y
    goal.target_pose.pose.orientation.z, goal.target_pose.pose.orientation.w = math.sin(yaw / 2), math.cos(yaw / 2)
    return goal


def per_goal(records):
    """{goal: (drives, reached, mean seconds of the reached, min centre clearance, min footprint clearance,
    contact samples with the map or the world)} over a record list, in the order the goals first appear."""
    table = {}
    for r in records:
        table.setdefault(tuple(r["goal"]), []).append(r)
    summary = {}
    for goal, rows in table.items():
        reached = [r for r in rows if r["state"] == "SUCCEEDED"]
        summary[goal] = (len(rows), len(reached),
                         sum(r["seconds"] for r in reached) / len(reached) if reached else float("nan"),
                         min(r["min_centre_clearance_m"] for r in rows), min(r["min_footprint_clearance_m"] for r in rows),
                         sum(r["contact_samples"] + r.get("world_contact_samples", 0) for r in rows))
    return summary


def compare(labelled_files):
    """Prints, per goal, each run's reach, mean time and clearances, and each run's time against the first's."""
    runs = []
    for item in labelled_files:
        label, _, paths = item.rpartition("=")
        records = [r for path in paths.split(",") for r in json.load(open(path))]
        runs.append((label or os.path.splitext(os.path.basename(paths.split(",")[0]))[0], per_goal(records)))
    goals = list(runs[0][1])
    for _, summary in runs[1:]:
        goals += [g for g in summary if g not in goals]
    header = "| goal | " + " | ".join("%s: reached, mean s, min clearance centre / footprint" % label for label, _ in runs)
    header += "".join(" | %s / %s time" % (label, runs[0][0]) for label, _ in runs[1:]) + " |"
    print(header)
    print("|" + "---|" * (1 + 2 * len(runs) - 1))
    for goal in goals:
        cells, ratios = [], []
        for label, summary in runs:
            if goal not in summary:
                cells.append("-")
                continue
            n, ok, mean, centre, footprint, contacts = summary[goal]
            cells.append("%d/%d, %s, %.3f / %.3f m%s" % (ok, n, "%.1f s" % mean if ok else "-", centre, footprint,
                                                           ", %d contact samples" % contacts if contacts else ""))
        reference = runs[0][1].get(goal)
        for label, summary in runs[1:]:
            ratios.append("%.2f" % (summary[goal][2] / reference[2])
                          if goal in summary and summary[goal][1] and reference and reference[1] else "-")
        print("| (%.2f, %.2f) | %s |%s" % (goal[0], goal[1], " | ".join(cells), "".join(" %s |" % r for r in ratios)))
    # The sum of the per-goal mean times over the goals every run reached at least once.
    common = [g for g in goals if all(g in summary and summary[g][1] > 0 for _, summary in runs)]
    cells = []
    for label, summary in runs:
        rows = list(summary.values())
        cells.append("%d/%d, %.1f s summed over %d goals, %.3f / %.3f m, %d contact samples" % (
            sum(r[1] for r in rows), sum(r[0] for r in rows), sum(summary[g][2] for g in common), len(common),
            min(r[3] for r in rows), min(r[4] for r in rows), sum(r[5] for r in rows)))
    reference_sum = sum(runs[0][1][g][2] for g in common)
    ratios = ["%.2f" % (sum(summary[g][2] for g in common) / reference_sum) if common else "-" for _, summary in runs[1:]]
    print("| all | %s |%s" % (" | ".join(cells), "".join(" %s |" % r for r in ratios)))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", default=os.path.join(os.path.dirname(__file__), "..", "maps", "lab.yaml"))
    parser.add_argument("--rounds", type=int, default=1, help="times to visit the goal list")
    parser.add_argument("--timeout", type=float, default=120.0, help="s per goal before it is cancelled")
    parser.add_argument("--goals", help="x,y;x,y;... (default: the five lab goals)")
    parser.add_argument("--json", help="write every drive's record here")
    parser.add_argument("--duration", type=float, help="s: cycle through the goals until this much time has passed "
                        "(instead of --rounds)")
    parser.add_argument("--memory-of", help="ROS node name (e.g. move_base): sample its resident memory every 5 s into "
                        "<json name>_memory.csv and report it")
    parser.add_argument("--plan-clearance", type=float, default=0.1125,
                        help="m: a global plan with a pose nearer an occupied cell than this is invalid (default: the "
                        "car's inscribed radius + footprint padding)")
    parser.add_argument("--trace", help="write the car's true poses here (CSV: t,x,y,yaw) and the global plans beside it (<name>_plans.json)")
    parser.add_argument("--compare", nargs="+", metavar="[LABEL=]RECORDS.json[,RECORDS.json...]",
                        help="compare earlier runs' --json records goal by goal (the first is the reference; "
                        "comma-separated files are pooled) and exit")
    args = parser.parse_args()
    if args.compare:
        compare(args.compare)
        return
    goals = LAB_GOALS if not args.goals else [tuple(float(v) for v in g.split(",")) for g in args.goals.split(";")]

    rospy.init_node("drive_goals", anonymous=True)
    drive = Drive(OccupiedCells(args.map), args.plan_clearance)
    client = actionlib.SimpleActionClient("move_base", MoveBaseAction)
    if not client.wait_for_server(rospy.Duration(60)):
        sys.exit("drive_goals: no move_base action server within 60 s")
    while drive.pose is None and not rospy.is_shutdown():
        rospy.sleep(0.1)
    drive.watch_plans()
    records = []
    memory = []  # (s since the first goal, KiB)
    began = time.time()
    if args.memory_of:
        def sample(_event):
            kib = resident_kib(args.memory_of)
            if kib is not None:
                memory.append((round(time.time() - began, 1), kib))
        sample(None)
        rospy.Timer(rospy.Duration(5.0), sample)
    rounds = itertools.count() if args.duration else range(args.rounds)
    for round_index in rounds:
        if args.duration and time.time() - began >= args.duration:
            break
        for gx, gy in goals:
            if args.duration and time.time() - began >= args.duration:
                break
            x, y, _ = drive.pose
            yaw = math.atan2(gy - y, gx - x)
            drive.reset()
            start = time.time()
            client.send_goal(goal_message(gx, gy, yaw))
            finished = client.wait_for_result(rospy.Duration(args.timeout))
            seconds = time.time() - start
            if not finished:
                client.cancel_goal()
                client.wait_for_result(rospy.Duration(5))
            rospy.sleep(1.2)  # the last plan and poses arrive, and the costmap published after it
            state = STATES.get(client.get_state(), str(client.get_state())) if finished else "TIMEOUT"
            error = math.dist(drive.pose[:2], (gx, gy))
            record = dict(round=round_index + 1, goal=[gx, gy], state=state, seconds=round(seconds, 1),
                          final_error_m=round(error, 3), plans=drive.plans,
                          min_centre_clearance_m=round(drive.min_centre, 3),
                          min_footprint_clearance_m=round(drive.min_footprint, 3), contact_samples=drive.contacts,
                          invalid_plans=drive.invalid_plans,
                          min_plan_clearance_m=round(drive.min_plan_clearance, 3) if drive.plans else None,
                          plans_through_lethal=drive.costmap.lethal_plans - drive.lethal_plans_before)
            if drive.world_seen:
                record.update(min_world_clearance_m=round(drive.min_world, 3), world_contact_samples=drive.world_contacts)
            records.append(record)
            print("round %d goal (%.2f, %.2f): %s in %.1f s, %.3f m from the goal, %d plans, min clearance centre "
                  "%.3f m, footprint %.3f m, %d contact samples, %d invalid plans, %d through a lethal cell%s" % (
                      round_index + 1, gx, gy, state, record["seconds"], error, drive.plans, drive.min_centre,
                      drive.min_footprint, drive.contacts, drive.invalid_plans, record["plans_through_lethal"],
                      "; world (boxes too): footprint %.3f m, %d contact samples" % (drive.min_world, drive.world_contacts)
                      if drive.world_seen else ""), flush=True)
            drive.watch_plans()
    reached = sum(r["state"] == "SUCCEEDED" for r in records)
    print("reached %d of %d goals; min clearance centre %.3f m, footprint %.3f m; %d contact samples" % (
        reached, len(records), min(r["min_centre_clearance_m"] for r in records),
        min(r["min_footprint_clearance_m"] for r in records), sum(r["contact_samples"] for r in records)))
    plan_clearances = [r["min_plan_clearance_m"] for r in records if r["min_plan_clearance_m"] is not None]
    print("%d global plans, %d invalid (a pose nearer than %.3f m to an occupied cell); min plan clearance %s; "
          "%d of %d checked against the costmap through a lethal cell" % (
              sum(r["plans"] for r in records), sum(r["invalid_plans"] for r in records), args.plan_clearance,
              "%.3f m" % min(plan_clearances) if plan_clearances else "-", drive.costmap.lethal_plans, drive.costmap.checked))
    if drive.world_seen:
        print("world (boxes too): min footprint clearance %.3f m, %d contact samples" % (
            min(r["min_world_clearance_m"] for r in records), sum(r["world_contact_samples"] for r in records)))
    if memory:
        after_minute = [kib for t, kib in memory if t >= 60.0]
        print("%s resident memory: %.1f MiB at start, %s, %.1f MiB at the end (%d samples)" % (
            args.memory_of, memory[0][1] / 1024.0,
            "%.1f-%.1f MiB after the first minute" % (min(after_minute) / 1024.0, max(after_minute) / 1024.0)
            if after_minute else "no sample after the first minute", memory[-1][1] / 1024.0, len(memory)))
    if args.trace:
        with open(args.trace, "w") as out:
            out.write("t,x,y,yaw\n")
            out.writelines("%.3f,%.4f,%.4f,%.4f\n" % row for row in drive.trace)
        with open(os.path.splitext(args.trace)[0] + "_plans.json", "w") as out:
            json.dump(drive.plan_log, out)
    if args.json:
        with open(args.json, "w") as out:
            json.dump(records, out, indent=1)
        if memory:
            with open(os.path.splitext(args.json)[0] + "_memory.csv", "w") as out:
                out.write("seconds,vmrss_kib\n")
                out.writelines("%.1f,%d\n" % row for row in memory)


if __name__ == "__main__":
    main()
