#!/usr/bin/python3
"""Generate the bundled lab map (maps/lab.pgm + maps/lab.yaml), a map_server map.

A 480 x 300 cm room at 5 cm per cell (96 columns x 60 rows) in the spirit of the
paper's lab (Figure 32): a 1-cell wall around the border, an L-shaped obstacle, a
U-shaped obstacle whose opening faces the start (its inside is a dead end for a
greedy walker) and three cubic boxes. Every obstacle keeps at least 12 free cells
(60 cm) from every other obstacle and from the walls, so a 265 x 205 mm robot
(radius ~17 cm, ~4 cells once inflated) passes everywhere.

The script checks those clearances and that start and goal are connected for the
inflated robot, then writes the files. Standard library only:

    /usr/bin/python3 scripts/make_lab_map.py            # writes maps/lab.pgm, maps/lab.yaml
    /usr/bin/python3 scripts/make_lab_map.py --ascii    # also prints the map ('#' obstacle)
    /usr/bin/python3 scripts/make_lab_map.py --output-dir /tmp/x
"""

import argparse
import collections
import math
import pathlib
import sys

WIDTH = 96            # columns (x), 480 cm
HEIGHT = 60           # rows (y), 300 cm
RESOLUTION = 0.05     # metres per cell
FREE_PIXEL = 254      # as written by map_server's map_saver
OCCUPIED_PIXEL = 0

MIN_GAP_CELLS = 12    # free cells required between any two obstacles (60 cm)
ROBOT_RADIUS_CELLS = 4  # 265 x 205 mm robot: circumscribed radius ~17 cm, ~4 cells inflated

# Suggested start and goal, in metres in the map frame (origin = bottom-left corner).
START_M = (0.4, 0.4)
GOAL_M = (4.4, 2.6)

# Obstacles as rectangles (x0, x1, y0, y1), in cells, inclusive; x = column from the
# left, y = row counted from the BOTTOM (as in the map frame).
OBSTACLES = collections.OrderedDict([
    ("L", [
        (14, 15, 34, 46),   # vertical leg
        (14, 27, 34, 35),   # horizontal leg (foot, pointing right)
    ]),
    ("U", [
        (42, 57, 36, 37),   # upper arm
        (42, 57, 22, 23),   # lower arm
        (56, 57, 22, 37),   # back wall; the opening faces west, towards the start
    ]),
    ("cube A", [(22, 28, 13, 19)]),
    ("cube B", [(70, 76, 34, 40)]),
    ("cube C", [(70, 76, 13, 19)]),
])


def border_cells():
    cells = set()
    for x in range(WIDTH):
        cells.add((x, 0))
        cells.add((x, HEIGHT - 1))
    for y in range(HEIGHT):
        cells.add((0, y))
        cells.add((WIDTH - 1, y))
    return cells


def rectangle_cells(rectangles):
    return {(x, y)
            for x0, x1, y0, y1 in rectangles
            for x in range(x0, x1 + 1)
            for y in range(y0, y1 + 1)}


def obstacle_groups():
    """Name -> set of (x, y) cells, the border wall included."""
    groups = collections.OrderedDict([("wall", border_cells())])
    for name, rectangles in OBSTACLES.items():
        groups[name] = rectangle_cells(rectangles)
    return groups


def metres_to_cell(point):
    """(x, y) in metres -> (x, y) cell indices (y from the bottom)."""
    return (int(math.floor(point[0] / RESOLUTION)), int(math.floor(point[1] / RESOLUTION)))


def free_cells_between(a, b):
    """Smallest number of free cells between two cell sets (centre distance minus one)."""
    return min(math.hypot(ax - bx, ay - by) for ax, ay in a for bx, by in b) - 1.0


def check_gaps(groups):
    names = list(groups)
    for i, first in enumerate(names):
        for second in names[i + 1:]:
            gap = free_cells_between(groups[first], groups[second])
            if gap < MIN_GAP_CELLS - 1e-9:
                raise SystemExit("gap between %s and %s is %.1f cells, need %d"
                                 % (first, second, gap, MIN_GAP_CELLS))


def inflate(occupied, radius):
    reach = int(math.ceil(radius))
    offsets = [(dx, dy) for dx in range(-reach, reach + 1) for dy in range(-reach, reach + 1)
               if math.hypot(dx, dy) <= radius]
    return {(x + dx, y + dy) for x, y in occupied for dx, dy in offsets}


def reachable_from(start, blocked):
    """4-connected flood fill over the cells of the map that are not blocked."""
    seen = {start}
    queue = collections.deque([start])
    while queue:
        x, y = queue.popleft()
        for nx, ny in ((x + 1, y), (x - 1, y), (x, y + 1), (x, y - 1)):
            if 0 <= nx < WIDTH and 0 <= ny < HEIGHT and (nx, ny) not in blocked and (nx, ny) not in seen:
                seen.add((nx, ny))
                queue.append((nx, ny))
    return seen


def check_connectivity(occupied):
    """Start and goal connected for the inflated robot, and no free pocket left unreachable."""
    blocked = inflate(occupied, ROBOT_RADIUS_CELLS)
    start, goal = metres_to_cell(START_M), metres_to_cell(GOAL_M)
    for name, cell in (("start", start), ("goal", goal)):
        if cell in blocked:
            raise SystemExit("%s cell %s is inside an inflated obstacle" % (name, cell))
    reached = reachable_from(start, blocked)
    if goal not in reached:
        raise SystemExit("goal is not reachable from start for the inflated robot")
    all_free = {(x, y) for x in range(WIDTH) for y in range(HEIGHT)} - blocked
    if reached != all_free:
        raise SystemExit("%d free cells are unreachable for the inflated robot" % len(all_free - reached))


def pixel_rows(occupied):
    """Image rows, top row first (image row r holds map y = HEIGHT - 1 - r)."""
    return [bytes(OCCUPIED_PIXEL if (x, HEIGHT - 1 - r) in occupied else FREE_PIXEL for x in range(WIDTH))
            for r in range(HEIGHT)]


def write_pgm(path, occupied):
    header = ("P5\n# eaci_planner lab map, generated by scripts/make_lab_map.py\n%d %d\n255\n"
              % (WIDTH, HEIGHT)).encode("ascii")
    path.write_bytes(header + b"".join(pixel_rows(occupied)))


def write_yaml(path, image_name):
    path.write_text(
        "# eaci_planner lab map (480 x 300 cm, 5 cm cells), generated by scripts/make_lab_map.py\n"
        "image: %s\n"
        "resolution: %.2f\n"
        "origin: [0.0, 0.0, 0.0]\n"
        "negate: 0\n"
        "occupied_thresh: 0.65\n"
        "free_thresh: 0.196\n"
        "mode: trinary\n" % (image_name, RESOLUTION))


def ascii_art(occupied):
    start, goal = metres_to_cell(START_M), metres_to_cell(GOAL_M)
    lines = []
    for r in range(HEIGHT):
        y = HEIGHT - 1 - r
        line = []
        for x in range(WIDTH):
            if (x, y) == start:
                line.append("S")
            elif (x, y) == goal:
                line.append("G")
            else:
                line.append("#" if (x, y) in occupied else ".")
        lines.append("".join(line))
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    default_dir = pathlib.Path(__file__).resolve().parent.parent / "maps"
    parser.add_argument("--output-dir", type=pathlib.Path, default=default_dir)
    parser.add_argument("--ascii", action="store_true", help="print the map ('#' obstacle, S start, G goal)")
    args = parser.parse_args()

    groups = obstacle_groups()
    check_gaps(groups)
    occupied = set().union(*groups.values())
    check_connectivity(occupied)

    args.output_dir.mkdir(parents=True, exist_ok=True)
    write_pgm(args.output_dir / "lab.pgm", occupied)
    write_yaml(args.output_dir / "lab.yaml", "lab.pgm")
    if args.ascii:
        print(ascii_art(occupied))
    print("wrote %s and %s" % (args.output_dir / "lab.pgm", args.output_dir / "lab.yaml"), file=sys.stderr)


if __name__ == "__main__":
    main()
