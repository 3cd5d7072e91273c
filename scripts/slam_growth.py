#!/usr/bin/python3
"""A map that grows as SLAM grows it, planned on by two move_base nodes, with every core loaded.

The deployment of the paper's car: gmapping publishes a map that holds unknown space and grows
while the robot drives, and move_base plans on it. This script stands in for gmapping: from a
world map (a map_server YAML) it publishes /map (latched nav_msgs/OccupancyGrid) every --period
seconds, each time larger -- the explored rectangle grows by --step metres on every side from
--explored metres round the world's centre -- with --margin metres of unknown cells (-1) beyond
the explored part and --holes blocks of --hole-size metres inside it that stay unknown (unseen
rooms). Meanwhile it calls /NODE/make_plan on every node of --nodes back to back, the same
request to each in turn (the order alternating), between free cells that are known, at least
--min-obstacle-distance from obstacles and at least --min-separation apart, chosen on the map
published one period before (the global costmap has had a period to take it in). --load N
starts N busy processes for the run, as other nodes (SLAM, the controller) would load the CPU.

Start the two move_base nodes first (launch/slam_growth.launch: EACI with one config line and
navfn, global costmaps keeping unknown space), then:
    /usr/bin/python3 scripts/slam_growth.py --world /tmp/mbmaps/building.yaml --load 4 --json out/slam.json
Per node it prints the calls, failures (an empty plan between known cells), mean and longest
make_plan time, the share of plan poses on unknown cells and the plans that touch unknown
space, and poses on occupied cells, for the calls while the map grows, those after it stopped
growing (held), and all. While it grows, a costmap that lags behind the published map plans
over cells it still holds unknown, and poses may land on walls published since; once the map is
held there must be none. Exit 0 when the run finished, 1 when a plan on the held map crossed an
occupied cell.
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import threading
import time

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from probe_make_plan import MapImage, pose, turn_and_length  # noqa: E402

UNKNOWN, FREE, OCCUPIED = -1, 0, 100


class World:
    """The whole map SLAM will have made at the end: values by cell, bottom row first (as an
    OccupancyGrid stores them), with the unseen holes already marked unknown."""

    def __init__(self, image, holes, hole_size, seed):
        self.image = image
        top_first = numpy.full((image.height, image.width), UNKNOWN, dtype=numpy.int8)
        top_first[image.free] = FREE
        top_first[image.occupied] = OCCUPIED
        rng = numpy.random.default_rng(seed)
        side = max(1, int(round(hole_size / image.resolution)))
        self.hole_cells = 0
        for _ in range(holes):
            r = int(rng.integers(0, max(1, image.height - side)))
            c = int(rng.integers(0, max(1, image.width - side)))
            top_first[r:r + side, c:c + side] = UNKNOWN
            self.hole_cells += side * side
        self.values = top_first[::-1].copy()  # row 0 = bottom
        self.height, self.width = self.values.shape
        self.resolution = image.resolution
        self.ox, self.oy = image.ox, image.oy
        # Distance to obstacles by the world (bottom-first), for choosing requests off the walls.
        self.clearance = image.distance[::-1]


class Snapshot:
    """One published map: the window [x0, x1) x [y0, y1) of the world's cells (bottom first),
    known only inside the explored window [ex0, ex1) x [ey0, ey1)."""

    def __init__(self, world, window, explored, version):
        self.world, self.version = world, version
        self.x0, self.y0, self.x1, self.y1 = window
        ex0, ey0, ex1, ey1 = explored
        grid = numpy.full((self.y1 - self.y0, self.x1 - self.x0), UNKNOWN, dtype=numpy.int8)
        grid[ey0 - self.y0:ey1 - self.y0, ex0 - self.x0:ex1 - self.x0] = world.values[ey0:ey1, ex0:ex1]
        self.grid = grid
        self.origin = (world.ox + self.x0 * world.resolution, world.oy + self.y0 * world.resolution)

    def message(self):
        from nav_msgs.msg import OccupancyGrid
        import rospy
        m = OccupancyGrid()
        m.header.frame_id = "map"
        m.header.stamp = rospy.Time.now()
        m.info.resolution = self.world.resolution
        m.info.height, m.info.width = self.grid.shape
        m.info.origin.position.x, m.info.origin.position.y = self.origin
        m.info.origin.orientation.w = 1.0
        m.data = self.grid.ravel().tolist()
        return m

    def value(self, x, y):
        """The published value at (x, y): unknown off the map."""
        col = int(math.floor((x - self.origin[0]) / self.world.resolution))
        row = int(math.floor((y - self.origin[1]) / self.world.resolution))
        if 0 <= row < self.grid.shape[0] and 0 <= col < self.grid.shape[1]:
            return int(self.grid[row, col])
        return UNKNOWN

    def known_free_cells(self, min_obstacle_distance):
        clear = self.world.clearance[self.y0:self.y1, self.x0:self.x1] >= min_obstacle_distance
        rows, cols = numpy.nonzero((self.grid == FREE) & clear)
        return rows, cols

    def centre(self, row, col):
        return (self.origin[0] + (col + 0.5) * self.world.resolution,
                self.origin[1] + (row + 0.5) * self.world.resolution)


def snapshots(world, explored_m, step_m, margin_m):
    """The published maps, smallest first: the explored window grows by step_m on every side
    from explored_m round the world's centre until it is the whole world."""
    res = world.resolution
    cx, cy = world.width // 2, world.height // 2
    half = max(1, int(round(explored_m / 2 / res)))
    step, margin = max(1, int(round(step_m / res))), int(round(margin_m / res))
    version = 0
    while True:
        ex0, ey0 = max(0, cx - half), max(0, cy - half)
        ex1, ey1 = min(world.width, cx + half), min(world.height, cy + half)
        window = (max(0, ex0 - margin), max(0, ey0 - margin), min(world.width, ex1 + margin), min(world.height, ey1 + margin))
        yield Snapshot(world, window, (ex0, ey0, ex1, ey1), version)
        if ex0 == 0 and ey0 == 0 and ex1 == world.width and ey1 == world.height:
            return
        half += step
        version += 1


class Load:
    """N busy processes (a shell loop each) for the run; ended on exit."""

    def __init__(self, count):
        self.procs = [subprocess.Popen(["sh", "-c", "while :; do :; done"]) for _ in range(count)]

    def stop(self):
        for p in self.procs:
            p.kill()
            p.wait()


def summarise(cs):
    """Calls, failures (an empty plan), times, and where the plans' poses lie."""
    ok = [c for c in cs if c["poses"] > 0]
    times = sorted(c["seconds"] for c in cs)
    poses = sum(c["poses"] for c in ok)
    return {"calls": len(cs), "failed": len(cs) - len(ok),
            "mean_ms": 1000 * statistics.fmean(times) if times else None,
            "p95_ms": 1000 * times[int(0.95 * (len(times) - 1))] if times else None,
            "max_ms": 1000 * times[-1] if times else None,
            "unknown_pose_share": sum(c["unknown_poses"] for c in ok) / poses if poses else 0.0,
            "plans_touching_unknown": sum(c["unknown_poses"] > 0 for c in ok),
            "occupied_poses": sum(c["occupied_poses"] for c in ok),
            "mean_length_m": statistics.fmean(c["length"] for c in ok) if ok else None,
            "mean_turn_deg": statistics.fmean(c["turn_deg"] for c in ok) if ok else None}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--world", required=True, help="map_server YAML of the whole map SLAM ends with")
    parser.add_argument("--nodes", default="move_base,move_base_other")
    parser.add_argument("--period", type=float, default=3.0, help="s between published maps")
    parser.add_argument("--explored", type=float, default=10.0, help="m, side of the first explored square")
    parser.add_argument("--step", type=float, default=1.5, help="m the explored part grows on every side per map")
    parser.add_argument("--margin", type=float, default=2.0, help="m of unknown cells round the explored part")
    parser.add_argument("--holes", type=int, default=12, help="unknown blocks inside the explored part")
    parser.add_argument("--hole-size", type=float, default=3.0, help="m, side of each unknown block")
    parser.add_argument("--hold", type=float, default=20.0, help="s of requests on the whole map after it stops growing")
    parser.add_argument("--load", type=int, default=0, help="busy processes for the run")
    parser.add_argument("--min-obstacle-distance", type=float, default=0.35)
    parser.add_argument("--min-separation", type=float, default=3.0)
    parser.add_argument("--tolerance", type=float, default=0.0)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--json", help="write every call and the summary here")
    args = parser.parse_args()

    import rospy
    from nav_msgs.msg import OccupancyGrid
    from nav_msgs.srv import GetPlan

    world = World(MapImage(args.world), args.holes, args.hole_size, args.seed)
    maps = list(snapshots(world, args.explored, args.step, args.margin))
    rospy.init_node("slam_growth", anonymous=True, disable_signals=True)
    publisher = rospy.Publisher("map", OccupancyGrid, queue_size=1, latch=True)
    nodes = [n for n in args.nodes.split(",") if n]
    current = {"map": maps[0], "previous": maps[0], "published_at": time.monotonic()}
    publisher.publish(maps[0].message())
    services = {}
    for n in nodes:
        rospy.wait_for_service("/%s/make_plan" % n, timeout=120)
        services[n] = rospy.ServiceProxy("/%s/make_plan" % n, GetPlan, persistent=True)
    time.sleep(args.period)  # the costmaps take the first map in

    done = threading.Event()
    held = threading.Event()  # the map has stopped growing

    def grow():
        for m in maps[1:]:
            if done.wait(args.period):
                return
            current["previous"] = current["map"]
            current["map"] = m
            publisher.publish(m.message())
            current["published_at"] = time.monotonic()
            print("published map %d: %d x %d cells" % (m.version, m.grid.shape[1], m.grid.shape[0]), flush=True)
        held.set()
        done.wait(args.hold)
        done.set()

    load = Load(args.load)
    grower = threading.Thread(target=grow, daemon=True)
    grower.start()
    rng = numpy.random.default_rng(args.seed)
    calls = {n: [] for n in nodes}
    request = 0
    try:
        while not done.is_set():
            chosen = current["previous"]  # taken in by the costmaps for a period already
            rows, cols = chosen.known_free_cells(args.min_obstacle_distance)
            if rows.size < 2:
                time.sleep(0.1)
                continue
            for _ in range(100):
                a, b = rng.integers(rows.size, size=2)
                start, goal = chosen.centre(rows[a], cols[a]), chosen.centre(rows[b], cols[b])
                if math.dist(start, goal) >= args.min_separation:
                    break
            order = nodes if request % 2 == 0 else nodes[::-1]
            for n in order:
                # Unknown poses are judged on the map published when the call is sent (the costmap
                # takes a new map in within a second, update_frequency 1 Hz; a period is 3 s).
                sent, published_at = current["map"], current["published_at"]
                t0 = time.monotonic()
                try:
                    reply = services[n](start=pose(*start), goal=pose(*goal), tolerance=args.tolerance)
                    points = [(p.pose.position.x, p.pose.position.y) for p in reply.plan.poses]
                    error = ""
                except Exception as e:  # noqa: BLE001 -- a dead service is a failed call, said in the record
                    points, error = [], str(e)
                seconds = time.monotonic() - t0
                values = [sent.value(x, y) for x, y in points]
                length, turn = turn_and_length(points) if len(points) > 1 else (0.0, 0.0)
                calls[n].append({"request": request, "phase": "held" if held.is_set() else "growing",
                                 "chosen_on_map": chosen.version, "map": sent.version,
                                 "map_cells": list(sent.grid.shape[::-1]), "since_publish": t0 - published_at,
                                 "start": start, "goal": goal, "seconds": seconds, "poses": len(points),
                                 "unknown_poses": sum(v == UNKNOWN for v in values),
                                 # a wall on the map the request was chosen on is in every costmap since
                                 "occupied_poses": sum(chosen.value(x, y) >= 65 for x, y in points),
                                 "occupied_points": [p for p in points if chosen.value(*p) >= 65][:20],
                                 "length": length, "turn_deg": turn, "error": error})
            request += 1
    finally:
        done.set()
        load.stop()

    summary = {}
    bad = False
    print("\n%-16s %-8s %6s %6s %9s %9s %9s %8s %8s %8s" % ("node", "phase", "calls", "failed", "mean ms", "p95 ms",
                                                            "max ms", "unk pose", "unk plan", "occupied"))
    for n in nodes:
        for phase in ("growing", "held", "all"):
            cs = [c for c in calls[n] if phase in ("all", c["phase"])]
            s = summarise(cs)
            summary.setdefault(n, {})[phase] = s
            # While the map grows a costmap under load may lag a map or two behind (its update
            # inflates the whole map), so a plan over cells it still held unknown can meet walls
            # published since; once the map is held, no pose may lie on an occupied cell.
            bad = bad or (phase == "held" and s["occupied_poses"] > 0)
            print("%-16s %-8s %6d %6d %9.1f %9.1f %9.1f %7.1f%% %8d %8d" % (
                n, phase, s["calls"], s["failed"], s["mean_ms"] or 0, s["p95_ms"] or 0, s["max_ms"] or 0,
                100 * s["unknown_pose_share"], s["plans_touching_unknown"], s["occupied_poses"]))
    print("maps published: %d, from %d x %d to %d x %d cells; load: %d busy processes" % (
        len(maps), maps[0].grid.shape[1], maps[0].grid.shape[0], maps[-1].grid.shape[1], maps[-1].grid.shape[0], args.load))
    if args.json:
        os.makedirs(os.path.dirname(os.path.abspath(args.json)), exist_ok=True)
        with open(args.json, "w") as f:
            json.dump({"args": vars(args), "summary": summary, "calls": calls}, f, indent=1)
    rospy.signal_shutdown("done")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
