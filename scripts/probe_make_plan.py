#!/usr/bin/python3
"""Asks a running move_base for plans and measures them.

For each request: /move_base/make_plan, then the plan's pose count, length, total heading
change (sum of |turn| between consecutive segments), minimum clearance (distance from a pose
to the nearest occupied cell centre of the map image) and the call's wall time.
Start move_base first (launch/move_base_demo.launch; see docs/ros.md), then:
    /usr/bin/python3 scripts/probe_make_plan.py [--map maps/lab.yaml] [--start 0.4,0.4]
        the lab's five goals from --start (the default);
    ... --map M.yaml --pairs "sx,sy:gx,gy;sx,sy:gx,gy"
        the given start/goal pairs;
    ... --map M.yaml --random 12 --seed 1
        random pairs of free cell centres at least --min-obstacle-distance (0.35 m) from every
        occupied cell and at least --min-separation (half the map's shorter side) apart.
Several move_base nodes at once (launch/compare_planners.launch starts two on one map):
    ... --nodes move_base,move_base_other --repeat 3 --save out/compare-{node}.json
        each request goes to every node in turn, --repeat times (the time kept is the median),
        so both planners see the same machine; one saved file per node.
--save F.json keeps the requests, measurements and plans; comparing two saved runs of the same
requests (no ROS needed):
    /usr/bin/python3 scripts/probe_make_plan.py --compare navfn.json eaci.json
"""
import argparse
import json
import math
import os
import statistics
import time

import numpy
import yaml

LAB_GOALS = [(4.4, 2.6), (2.45, 1.5), (1.1, 2.2), (4.2, 0.5), (0.5, 2.6)]  # across the L, into the U, past the cubes


class MapImage:
    """A map_server map's occupied cells (pixels < 128 of its P5 PGM image) and their distances."""

    def __init__(self, yaml_path):
        meta = yaml.safe_load(open(yaml_path))
        data = open(os.path.join(os.path.dirname(yaml_path), meta["image"]), "rb").read()
        header = [t for line in data.split(b"\n")[:4] if not line.startswith(b"#") for t in line.split()]
        self.width, self.height = int(header[1]), int(header[2])
        pixels = numpy.frombuffer(data[-self.width * self.height:], dtype=numpy.uint8)
        self.occupied = pixels.reshape(self.height, self.width) < 128  # row 0 = top
        self.free = pixels.reshape(self.height, self.width) >= 250
        self.resolution = float(meta["resolution"])
        self.ox, self.oy = (float(v) for v in meta["origin"][:2])
        self.distance = self._cell_distances()

    def _cell_distances(self):
        """Distance (m) from each cell centre to the nearest occupied cell centre."""
        if not self.occupied.any():
            return numpy.full(self.occupied.shape, math.inf)
        try:
            from scipy.ndimage import distance_transform_edt
            return distance_transform_edt(~self.occupied) * self.resolution
        except ImportError:  # exact but slow: row by row against every occupied cell
            rows, cols = numpy.nonzero(self.occupied)
            out = numpy.empty(self.occupied.shape)
            for r in range(self.height):
                cc = numpy.arange(self.width)[:, None]
                out[r] = numpy.sqrt(((cc - cols) ** 2 + (r - rows) ** 2).min(axis=1))
            return out * self.resolution

    def cell(self, x, y):
        col = int(math.floor((x - self.ox) / self.resolution))
        row = self.height - 1 - int(math.floor((y - self.oy) / self.resolution))
        return min(max(row, 0), self.height - 1), min(max(col, 0), self.width - 1)

    def centre(self, row, col):
        return self.ox + (col + 0.5) * self.resolution, self.oy + (self.height - 1 - row + 0.5) * self.resolution

    def clearance(self, x, y):
        """Exact distance (m) from (x, y) to the nearest occupied cell centre: the obstacles in a
        window around the point's cell, wide enough to hold the nearest one (its cell's distance
        plus the point's offset from the cell centre)."""
        row, col = self.cell(x, y)
        reach = int(math.ceil(self.distance[row, col] / self.resolution)) + 2
        r0, r1 = max(row - reach, 0), min(row + reach + 1, self.height)
        c0, c1 = max(col - reach, 0), min(col + reach + 1, self.width)
        rows, cols = numpy.nonzero(self.occupied[r0:r1, c0:c1])
        if rows.size == 0:
            return math.inf
        xs = self.ox + (cols + c0 + 0.5) * self.resolution
        ys = self.oy + (self.height - 1 - (rows + r0) + 0.5) * self.resolution
        return float(numpy.sqrt((xs - x) ** 2 + (ys - y) ** 2).min())

    def min_clearance(self, points):
        """The smallest clearance along the points; exact, checking points in order of their cells'
        distance until no other can come closer."""
        order = sorted(points, key=lambda p: self.distance[self.cell(*p)])
        best = math.inf
        for p in order:
            if self.distance[self.cell(*p)] - self.resolution > best:  # a point is within res/sqrt(2) of its centre
                break
            best = min(best, self.clearance(*p))
        return best


def random_pairs(image, count, seed, min_obstacle_distance, min_separation):
    """`count` start/goal pairs of free cell centres, both at least min_obstacle_distance from
    every occupied cell, at least min_separation apart."""
    rng = numpy.random.default_rng(seed)
    rows, cols = numpy.nonzero(image.free & (image.distance >= min_obstacle_distance))
    if rows.size == 0:
        raise SystemExit("probe_make_plan: no free cell %.2f m from every occupied cell (--min-obstacle-distance)"
                         % min_obstacle_distance)
    pairs, tries = [], 0
    while len(pairs) < count:
        tries += 1
        if tries > 1000 * count:
            raise SystemExit("probe_make_plan: found %d of %d pairs %.2f m apart in %d tries: the free space is "
                             "smaller; lower --min-separation" % (len(pairs), count, min_separation, tries - 1))
        a, b = rng.integers(rows.size, size=2)
        start, goal = image.centre(rows[a], cols[a]), image.centre(rows[b], cols[b])
        if math.dist(start, goal) >= min_separation:
            pairs.append((start, goal))
    return pairs


def parse_pairs(text):
    return [tuple(tuple(float(v) for v in end.split(",")) for end in pair.split(":"))
            for pair in text.split(";") if pair.strip()]


def turn_and_length(points):
    length = sum(math.dist(points[i], points[i + 1]) for i in range(len(points) - 1))
    headings = [math.atan2(b[1] - a[1], b[0] - a[0]) for a, b in zip(points, points[1:]) if a != b]
    turn = sum(abs(math.remainder(h2 - h1, 2 * math.pi)) for h1, h2 in zip(headings, headings[1:]))
    return length, math.degrees(turn)


def pose(x, y):
    from geometry_msgs.msg import PoseStamped
    p = PoseStamped()
    p.header.frame_id = "map"
    p.pose.position.x, p.pose.position.y, p.pose.orientation.w = x, y, 1.0
    return p


def describe(r):
    where = "(%.2f, %.2f) -> (%.2f, %.2f)" % (*r["start"], *r["goal"])
    if r["poses"] < 2:
        return "%s: no plan, %.0f ms" % (where, r["ms"])
    return "%s: %d poses, length %.2f m, turn %.0f deg, min clearance %.3f m, %.0f ms" % (
        where, r["poses"], r["length"], r["turn"], r["clearance"], r["ms"])


def probe(args, image):
    import rospy
    from nav_msgs.srv import GetPlan
    if args.pairs:
        pairs = parse_pairs(args.pairs)
    elif args.random:
        side = min(image.width, image.height) * image.resolution
        separation = args.min_separation if args.min_separation is not None else side / 2
        pairs = random_pairs(image, args.random, args.seed, args.min_obstacle_distance, separation)
    else:
        start = tuple(float(v) for v in args.start.split(","))
        pairs = [(start, goal) for goal in LAB_GOALS]
    rospy.init_node("probe_make_plan", anonymous=True)
    nodes = [n.strip().strip("/") for n in args.nodes.split(",") if n.strip()]
    if len(nodes) > 1 and args.save and "{node}" not in args.save:
        raise SystemExit("--save needs {node} in its name with several --nodes")
    services, planners, results = {}, {}, {}
    for node in nodes:
        rospy.wait_for_service("/%s/make_plan" % node, args.wait)
        # One connection per node for all its requests (as a client that plans often keeps it):
        # the time is the planner's and the message's, not a new TCP connection's per call.
        services[node] = rospy.ServiceProxy("/%s/make_plan" % node, GetPlan, persistent=True)
        planners[node] = rospy.get_param("/%s/base_global_planner" % node, "?")
        results[node] = []
    for start, goal in pairs:
        times, plans = {node: [] for node in nodes}, {}
        for _ in range(args.repeat):
            for node in nodes:
                t0 = time.perf_counter()
                plans[node] = services[node](start=pose(*start), goal=pose(*goal), tolerance=0.0).plan
                times[node].append((time.perf_counter() - t0) * 1000)
        for node in nodes:
            results[node].append({"start": list(start), "goal": list(goal), "ms": statistics.median(times[node]),
                                  "ms_all": times[node],
                                  "points": [(p.pose.position.x, p.pose.position.y) for p in plans[node].poses]})
        for node in nodes:
            r = results[node][-1]
            r["poses"] = len(r["points"])
            if r["poses"] >= 2:
                r["length"], r["turn"] = turn_and_length(r["points"])
                r["clearance"] = image.min_clearance(r["points"])
            print(("%s: " % node if len(nodes) > 1 else "") + describe(r), flush=True)
    for node in nodes:
        planned = [r for r in results[node] if r["poses"] >= 2]
        if planned:
            print("%s: %d/%d planned; turn median %.0f deg, total %.0f deg; min clearance %.3f m; time median %.0f ms"
                  % (planners[node], len(planned), len(results[node]), statistics.median(r["turn"] for r in planned),
                     sum(r["turn"] for r in planned), min(r["clearance"] for r in planned),
                     statistics.median(r["ms"] for r in results[node])))
        if args.save:
            json.dump({"map": args.map, "planner": planners[node], "node": node, "repeat": args.repeat,
                       "results": results[node]}, open(args.save.replace("{node}", node), "w"))


def compare(base_path, other_path):
    """Per request and in sum: the other run's turn and time over the base run's, both clearances."""
    base, other = json.load(open(base_path)), json.load(open(other_path))
    b_name, o_name = base["planner"].split("/")[-1], other["planner"].split("/")[-1]
    print("| start -> goal | %s: length, turn, clearance, ms | %s: length, turn, clearance, ms | turn ratio | time ratio |"
          % (b_name, o_name))
    print("|---|---|---|---|---|")
    turn_ratios, time_ratios, b_turn, o_turn, b_ms, o_ms = [], [], 0.0, 0.0, 0.0, 0.0
    b_clear, o_clear, less_clear, shortfall = math.inf, math.inf, 0, 0.0
    cell = lambda r: ("%.2f m, %.0f°, %.3f m, %.0f" % (r["length"], r["turn"], r["clearance"], r["ms"])
                      if r["poses"] >= 2 else "no plan, %.0f ms" % r["ms"])
    for b, o in zip(base["results"], other["results"]):
        assert b["start"] == o["start"] and b["goal"] == o["goal"], "the runs asked for different requests"
        both = b["poses"] >= 2 and o["poses"] >= 2
        turn_ratio = o["turn"] / b["turn"] if both and b["turn"] > 0 else math.nan
        time_ratio = o["ms"] / b["ms"]
        if both:
            turn_ratios.append(turn_ratio)
            time_ratios.append(time_ratio)
            b_turn, o_turn, b_ms, o_ms = b_turn + b["turn"], o_turn + o["turn"], b_ms + b["ms"], o_ms + o["ms"]
            b_clear, o_clear = min(b_clear, b["clearance"]), min(o_clear, o["clearance"])
            less_clear += o["clearance"] < b["clearance"] - 1e-9
            shortfall = max(shortfall, b["clearance"] - o["clearance"])
        print("| (%.2f, %.2f) -> (%.2f, %.2f) | %s | %s | %.2f | %.2f |"
              % (*b["start"], *b["goal"], cell(b), cell(o), turn_ratio, time_ratio))
    if turn_ratios:
        print("\n%d requests planned by both. turn %s/%s: median %.2f, max %.2f, total %.2f (%.0f° / %.0f°); "
              "min clearance %s %.3f m, %s %.3f m (%s below %s's on %d requests, by up to %.3f m); "
              "make_plan time %s/%s: median %.2f, total %.2f"
              % (len(turn_ratios), o_name, b_name, statistics.median(turn_ratios), max(turn_ratios), o_turn / b_turn,
                 o_turn, b_turn, b_name, b_clear, o_name, o_clear, o_name, b_name, less_clear, shortfall, o_name, b_name,
                 statistics.median(time_ratios), o_ms / b_ms))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--map", default=os.path.join(os.path.dirname(__file__), "..", "maps", "lab.yaml"))
    parser.add_argument("--start", default="0.4,0.4", help="start of the lab goals (without --pairs / --random)")
    parser.add_argument("--pairs", help='"sx,sy:gx,gy;..." in metres')
    parser.add_argument("--random", type=int, default=0, help="this many random start/goal pairs")
    parser.add_argument("--seed", type=int, default=1, help="seed of the random pairs")
    parser.add_argument("--min-obstacle-distance", type=float, default=0.35, help="m, random starts and goals")
    parser.add_argument("--min-separation", type=float, help="m between a random start and goal (half the map)")
    parser.add_argument("--wait", type=float, default=30, help="s to wait for each node's make_plan service")
    parser.add_argument("--nodes", default="move_base", help="move_base nodes to ask, comma-separated, in turn")
    parser.add_argument("--repeat", type=int, default=1, help="ask each node this many times per request (median kept)")
    parser.add_argument("--save", help="write the requests, measurements and plans to this JSON file")
    parser.add_argument("--compare", nargs=2, metavar=("BASE.json", "OTHER.json"),
                        help="compare two saved runs (OTHER over BASE) instead of probing")
    args = parser.parse_args()
    if args.compare:
        compare(*args.compare)
    else:
        probe(args, MapImage(args.map))


if __name__ == "__main__":
    main()
