#!/usr/bin/env python3
"""Writes a MovingAI benchmark map (.map) and scenario (.scen) from a map_server trinary PGM,
e.g. one written by `eaci_bench map`, for `eaci_bench scen`. Not an official MovingAI set: the
problems are random pairs of passable cells, and their optimal lengths come from this script's
own Dijkstra search (octile moves, diagonal sqrt(2), no corner cutting: a diagonal needs both
side cells passable), written independently of the planner's A*.

    eaci_bench map --kind rooms --size 256 --resolution 1 --out /tmp/gen/rooms256.yaml
    scripts/movingai_from_pgm.py /tmp/gen/rooms256.pgm /tmp/gen/rooms256 --problems 100 --seed 1

writes /tmp/gen/rooms256.map and /tmp/gen/rooms256.map.scen. Buckets as in MovingAI's sets:
floor(optimal length / 4).

--radii R1,R2,... spreads the route lengths (random pairs on a large map are mostly long):
problem k takes its goal within R(k mod n) cells of its start in x and y (0 = anywhere), e.g.
`--radii 8,32,128,0` for short, middling and long routes in equal numbers.
"""
import argparse
import heapq
import math
import os
import random

SQRT2 = math.sqrt(2.0)


def read_pgm(path):
    with open(path, "rb") as f:
        data = f.read()
    tokens, pos = [], 0
    while len(tokens) < 4:
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos)
            continue
        start = pos
        while not data[pos:pos + 1].isspace():
            pos += 1
        tokens.append(data[start:pos])
    if tokens[0] != b"P5" or int(tokens[3]) != 255:
        raise SystemExit(f"{path}: an 8-bit binary PGM (P5) is expected")
    width, height = int(tokens[1]), int(tokens[2])
    pixels = data[pos + 1:pos + 1 + width * height]
    return width, height, pixels


def dijkstra(passable, width, height, start, goal):
    """Octile distance without corner cutting from start to goal ((x, y) cells), or None."""
    dist = {start: 0.0}
    queue = [(0.0, start)]
    while queue:
        d, (x, y) = heapq.heappop(queue)
        if (x, y) == goal:
            return d
        if d > dist[(x, y)]:
            continue
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                if dx == 0 and dy == 0:
                    continue
                nx, ny = x + dx, y + dy
                if not (0 <= nx < width and 0 <= ny < height) or not passable[ny][nx]:
                    continue
                if dx and dy and not (passable[y][nx] and passable[ny][x]):
                    continue  # no corner cutting
                nd = d + (SQRT2 if dx and dy else 1.0)
                if nd < dist.get((nx, ny), math.inf):
                    dist[(nx, ny)] = nd
                    heapq.heappush(queue, (nd, (nx, ny)))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("pgm")
    parser.add_argument("out_base", help="writes OUT_BASE.map and OUT_BASE.map.scen")
    parser.add_argument("--problems", type=int, default=100)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--radii", default="0", help="goal within R cells of the start, cycled per problem (0 = anywhere)")
    args = parser.parse_args()

    width, height, pixels = read_pgm(args.pgm)
    passable = [[pixels[y * width + x] == 254 for x in range(width)] for y in range(height)]
    map_path = args.out_base + ".map"
    with open(map_path, "w") as f:
        f.write(f"type octile\nheight {height}\nwidth {width}\nmap\n")
        for row in passable:
            f.write("".join("." if p else "@" for p in row) + "\n")

    rng = random.Random(args.seed)
    free = [(x, y) for y in range(height) for x in range(width) if passable[y][x]]
    radii = [int(r) for r in args.radii.split(",")]
    problems = []
    while len(problems) < args.problems:
        radius = radii[len(problems) % len(radii)]
        start = rng.choice(free)
        if radius == 0:
            goal = rng.choice(free)
        else:
            gx, gy = start[0] + rng.randint(-radius, radius), start[1] + rng.randint(-radius, radius)
            if not (0 <= gx < width and 0 <= gy < height and passable[gy][gx]):
                continue
            goal = (gx, gy)
        if start == goal:
            continue
        length = dijkstra(passable, width, height, start, goal)
        if length is not None:
            problems.append((int(length // 4), start, goal, length))
    problems.sort(key=lambda p: p[0])
    name = os.path.basename(map_path)
    with open(map_path + ".scen", "w") as f:
        f.write("version 1\n")
        for bucket, (sx, sy), (gx, gy), length in problems:
            f.write(f"{bucket}\t{name}\t{width}\t{height}\t{sx}\t{sy}\t{gx}\t{gy}\t{length:.8f}\n")
    print(f"wrote {map_path} ({width} x {height}) and {map_path}.scen ({len(problems)} problems)")


if __name__ == "__main__":
    main()
