#!/usr/bin/python3
"""Hammers a running move_base that plans with EACI, to show that nothing of ours hangs or breaks.

While move_base replans (start launch/move_base_demo.launch with planner_frequency:=10 and let
scripts/drive_goals.py --duration ... drive the car to goals), this script calls both make_plan
services at once -- move_base's own /move_base/make_plan (which holds the costmap's lock while
our plugin plans) and the plugin's /move_base/EaciGlobalPlanner/make_plan -- from one thread
each, with random start/goal pairs of free cells, and cancels the plan in progress now and
then (/move_base/EaciGlobalPlanner/cancel). A watchdog fails the run (exit 2) as soon as any
call has been waiting for longer than --watchdog seconds, or move_base's own plans stop coming
while a goal is being driven. Every plan must be valid: no pose on an occupied cell of the map
image, no jump longer than --max-step between poses. move_base's resident memory is sampled
every 10 s.

With --costmap-check the plans are checked against the global costmap too, as move_base
publishes it (/move_base/global_costmap/costmap and its updates; publish it as often as it
updates): no segment between two poses of a plan may cross a cell that every costmap held from
before the plan was asked for until it came back showed lethal (so lethal while it was made: a
cell at a moving obstacle's edge that one scan marks and the next clears is not),
for the two services' plans and move_base's own (its plans published on the plugin's ~plan).
For a costmap whose obstacles move (config/moving_obstacle_costmap.yaml, scripts/moving_obstacle.py).
    /usr/bin/python3 scripts/stress_make_plan.py --duration 600 --json stress.json
Exit 0: no hang, every plan valid; 1: an invalid plan; 2: a hang.
"""
import argparse
import json
import math
import os
import random
import sys
import threading
import time

import numpy
import rospy
from actionlib_msgs.msg import GoalStatusArray
from map_msgs.msg import OccupancyGridUpdate
from nav_msgs.msg import OccupancyGrid
from nav_msgs.msg import Path
from nav_msgs.srv import GetPlan
from std_srvs.srv import Trigger

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from drive_goals import resident_kib  # noqa: E402
from probe_make_plan import MapImage, pose  # noqa: E402


class CostmapHistory:
    """The global costmap as move_base publishes it (costmap_2d's 0..100 scale: 100 lethal), its
    last few seconds kept: lethal(t0, t1) is the cells lethal in the costmap held at t0 and in
    the one held at t1."""

    def __init__(self):
        self.lock = threading.Lock()
        self.info = None
        self.grid = None
        self.history = []  # (monotonic time, lethal mask), newest last

    def _keep(self):
        now = time.monotonic()
        self.history.append((now, self.grid == 100))
        while self.history and now - self.history[0][0] > 5.0:
            self.history.pop(0)

    def on_full(self, message):
        with self.lock:
            self.info = message.info
            self.grid = numpy.array(message.data, dtype=numpy.int8).reshape(message.info.height, message.info.width)
            self._keep()

    def on_update(self, message):
        with self.lock:
            if self.grid is None:
                return
            block = numpy.array(message.data, dtype=numpy.int8).reshape(message.height, message.width)
            self.grid[message.y:message.y + message.height, message.x:message.x + message.width] = block
            self._keep()

    def held_at(self, t):
        """The lethal mask held at monotonic time t (the newest received before it), or None."""
        with self.lock:
            held = None
            for received, mask in self.history:
                if received <= t:
                    held = mask
            return held

    def lethal_throughout(self, before, after):
        """The cells lethal in every costmap held from `before` to `after`, or None."""
        with self.lock:
            masks = [mask for received, mask in self.history if received <= after]
            first = max((k for k, (received, _) in enumerate(self.history[:len(masks)]) if received <= before),
                        default=None)
            if first is None:
                return None
            masks = masks[first:]
            if any(m.shape != masks[0].shape for m in masks):
                return None
            lethal = masks[0].copy()
            for m in masks[1:]:
                lethal &= m
            return lethal

    def crossing(self, poses, before, after):
        """A sentence when a segment between two poses crosses a cell lethal throughout, else None."""
        lethal = self.lethal_throughout(before, after)
        if lethal is None:
            return None
        info = self.info
        res, ox, oy = info.resolution, info.origin.position.x, info.origin.position.y
        points = [(p.pose.position.x, p.pose.position.y) for p in poses]
        for k, ((x0, y0), (x1, y1)) in enumerate(zip(points, points[1:])):
            samples = max(1, int(math.ceil(math.hypot(x1 - x0, y1 - y0) / res * 20)))
            for i in range(samples + 1):
                x, y = x0 + (x1 - x0) * i / samples, y0 + (y1 - y0) * i / samples
                col, row = int(math.floor((x - ox) / res)), int(math.floor((y - oy) / res))  # row from the bottom
                if 0 <= row < lethal.shape[0] and 0 <= col < lethal.shape[1] and lethal[row, col]:
                    return "segment %d crosses the lethal cell (%d, %d) at (%.3f, %.3f)" % (k + 1, col, row, x, y)
        return None


class Stress:
    def __init__(self, args, image):
        self.args, self.image = args, image
        self.lock = threading.Lock()
        self.in_flight = {}  # thread name -> (service, start time)
        self.stats = {}      # service -> counts and times
        self.invalid = []
        self.move_base_plans = []  # times of the plugin's published plans (move_base's and ours)
        self.costmap = CostmapHistory() if args.costmap_check else None
        self.costmap_checked = {}  # service -> plans checked against the costmap
        self.goal_active_since = None
        self.memory = []
        free_rows, free_cols = (self.image.distance >= args.min_obstacle_distance).nonzero()
        self.free = list(zip(free_rows.tolist(), free_cols.tolist()))
        self.stop = threading.Event()

    def on_plan(self, message):
        now = time.monotonic()
        with self.lock:
            self.move_base_plans.append(now)
        if self.costmap is not None and message.poses:
            # Published when made: the costmap a tenth of a second before and when it arrives.
            self.costmap_check("~plan", message.poses, now - 0.1 - self.args.plan_age, now)

    def costmap_check(self, service, poses, before, after):
        crossing = self.costmap.crossing(poses, before, after)
        checked = self.costmap.held_at(before) is not None
        with self.lock:
            self.costmap_checked[service] = self.costmap_checked.get(service, 0) + (1 if checked else 0)
            if crossing:
                self.invalid.append({"service": service, "defect": crossing})
        if crossing:
            rospy.logerr("plan from %s through the costmap: %s", service, crossing)

    def on_status(self, message):
        active = any(s.status == 1 for s in message.status_list)  # ACTIVE
        with self.lock:
            if active and self.goal_active_since is None:
                self.goal_active_since = time.monotonic()
            elif not active:
                self.goal_active_since = None

    def check(self, poses):
        points = [(p.pose.position.x, p.pose.position.y) for p in poses]
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            if math.hypot(x1 - x0, y1 - y0) > self.args.max_step:
                return "a jump of %.3f m" % math.hypot(x1 - x0, y1 - y0)
        for x, y in points:
            row, col = self.image.cell(x, y)
            if self.image.occupied[row, col]:
                return "a pose on an occupied cell at (%.3f, %.3f)" % (x, y)
        return None

    def caller(self, service, rng):
        call = rospy.ServiceProxy(service, GetPlan, persistent=True)
        name = threading.current_thread().name
        stats = self.stats.setdefault(service, {"calls": 0, "plans": 0, "empty": 0, "errors": 0, "seconds": []})
        while not self.stop.is_set():
            (sr, sc), (gr, gc) = rng.choice(self.free), rng.choice(self.free)
            start, goal = self.image.centre(sr, sc), self.image.centre(gr, gc)
            with self.lock:
                self.in_flight[name] = (service, time.monotonic())
            begin = time.monotonic()
            try:
                response = call(start=pose(*start), goal=pose(*goal), tolerance=0.0)
                poses = response.plan.poses
            except (rospy.ServiceException, rospy.ROSException) as e:
                stats["errors"] += 1
                poses = None
                rospy.logwarn("%s: %s", service, e)
                call = rospy.ServiceProxy(service, GetPlan, persistent=True)
            with self.lock:
                del self.in_flight[name]
            stats["calls"] += 1
            stats["seconds"].append(time.monotonic() - begin)
            if poses:
                stats["plans"] += 1
                if self.costmap is not None:
                    self.costmap_check(service, poses, begin, time.monotonic())
                defect = self.check(poses)
                if defect:
                    self.invalid.append({"service": service, "start": start, "goal": goal, "defect": defect})
                    rospy.logerr("invalid plan from %s: %s", service, defect)
            elif poses is not None:
                stats["empty"] += 1

    def canceller(self, rng):
        cancel = rospy.ServiceProxy("/move_base/EaciGlobalPlanner/cancel", Trigger)
        count = 0
        while not self.stop.wait(rng.uniform(0.5, 3.0)):
            with self.lock:
                self.in_flight["cancel"] = ("cancel", time.monotonic())
            try:
                cancel()
                count += 1
            except (rospy.ServiceException, rospy.ROSException):
                pass
            with self.lock:
                del self.in_flight["cancel"]
        self.stats["cancel"] = {"calls": count}

    def watchdog(self, started):
        """None while all is well, else what hangs."""
        now = time.monotonic()
        with self.lock:
            for name, (service, since) in self.in_flight.items():
                if now - since > self.args.watchdog:
                    return "%s has waited %.1f s for %s" % (name, now - since, service)
            if self.goal_active_since is not None and now - self.goal_active_since > self.args.watchdog:
                last = self.move_base_plans[-1] if self.move_base_plans else started
                if now - last > self.args.watchdog:
                    return "no plan for %.1f s while a goal is driven" % (now - last)
        return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", default=os.path.join(os.path.dirname(__file__), "..", "maps", "lab.yaml"))
    parser.add_argument("--duration", type=float, default=600.0, help="s")
    parser.add_argument("--watchdog", type=float, default=20.0, help="s a call may wait before the run fails")
    parser.add_argument("--max-step", type=float, default=0.5, help="m between two poses of a plan")
    parser.add_argument("--min-obstacle-distance", type=float, default=0.12, help="m, random starts and goals")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", help="write the counts, times and memory samples here")
    parser.add_argument("--costmap-check", action="store_true",
                        help="check every plan against the global costmap as published (see above)")
    parser.add_argument("--plan-age", type=float, default=0.1,
                        help="s: how long before its ~plan message a plan of move_base's may have started")
    args = parser.parse_args()
    rospy.init_node("stress_make_plan", anonymous=True, disable_signals=True)
    image = MapImage(args.map)
    stress = Stress(args, image)
    for service in ("/move_base/make_plan", "/move_base/EaciGlobalPlanner/make_plan"):
        rospy.wait_for_service(service, timeout=60)
    rospy.Subscriber("/move_base/EaciGlobalPlanner/plan", Path, stress.on_plan, queue_size=100)
    rospy.Subscriber("/move_base/status", GoalStatusArray, stress.on_status, queue_size=10)
    if stress.costmap is not None:
        rospy.Subscriber("/move_base/global_costmap/costmap", OccupancyGrid, stress.costmap.on_full, queue_size=5)
        rospy.Subscriber("/move_base/global_costmap/costmap_updates", OccupancyGridUpdate, stress.costmap.on_update,
                         queue_size=50)
    rng = random.Random(args.seed)
    threads = [threading.Thread(target=stress.caller, args=(s, random.Random(rng.random())), name=s, daemon=True)
               for s in ("/move_base/make_plan", "/move_base/EaciGlobalPlanner/make_plan")]
    threads.append(threading.Thread(target=stress.canceller, args=(random.Random(rng.random()),), daemon=True))
    started = time.monotonic()
    for t in threads:
        t.start()
    hang = None
    next_memory = started
    while time.monotonic() - started < args.duration:
        time.sleep(0.5)
        hang = stress.watchdog(started)
        if hang:
            break
        if time.monotonic() >= next_memory:
            stress.memory.append((round(time.monotonic() - started, 1), resident_kib("move_base")))
            next_memory += 10.0
    stress.stop.set()
    for t in threads:
        t.join(timeout=args.watchdog)
    elapsed = time.monotonic() - started
    plans = stress.move_base_plans
    summary = {
        "seconds": round(elapsed, 1),
        "hang": hang,
        "invalid": stress.invalid,
        "published_plans": len(plans),
        "published_per_second": round(len(plans) / elapsed, 2) if elapsed > 0 else 0,
        "services": {s: {k: (v if k != "seconds" else {"median": sorted(v)[len(v) // 2] if v else None,
                                                        "max": max(v) if v else None})
                         for k, v in st.items()} for s, st in stress.stats.items()},
        "memory_kib": stress.memory,
        "costmap_checked": stress.costmap_checked,
    }
    print(json.dumps(summary, indent=1))
    if args.json:
        with open(args.json, "w") as out:
            json.dump(summary, out, indent=1)
    if hang:
        print("HANG: " + hang, file=sys.stderr)
        os._exit(2)
    os._exit(1 if stress.invalid else 0)


if __name__ == "__main__":
    main()
