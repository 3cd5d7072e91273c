#!/usr/bin/python3
"""A map_server map at a finer resolution: each cell split into k x k cells of the same value.

    /usr/bin/python3 scripts/resample_map.py IN.yaml K OUT.yaml
writes OUT.yaml and OUT.pgm (a binary P5 image) with resolution / K and the same origin, mode and
thresholds; the walls are as thick in metres, the speckle of a SLAM map K times as many cells.
"""
import os
import sys

import numpy
import yaml


def main():
    if len(sys.argv) != 4:
        raise SystemExit(__doc__.strip().splitlines()[2].strip())
    source, factor, target = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    if factor < 1:
        raise SystemExit("resample_map: K must be a whole number >= 1 (got %d)" % factor)
    meta = yaml.safe_load(open(source))
    data = open(os.path.join(os.path.dirname(source), meta["image"]), "rb").read()
    header = [t for line in data.split(b"\n")[:4] if not line.startswith(b"#") for t in line.split()]
    if header[0] != b"P5" or int(header[3]) > 255:
        raise SystemExit("resample_map: %s is not an 8-bit binary PGM (P5)" % meta["image"])
    width, height = int(header[1]), int(header[2])
    pixels = numpy.frombuffer(data[-width * height:], dtype=numpy.uint8).reshape(height, width)
    finer = pixels.repeat(factor, axis=0).repeat(factor, axis=1)
    image = os.path.splitext(os.path.basename(target))[0] + ".pgm"
    with open(os.path.join(os.path.dirname(os.path.abspath(target)), image), "wb") as out:
        out.write(b"P5\n%d %d\n255\n" % (finer.shape[1], finer.shape[0]) + finer.tobytes())
    meta["image"] = image
    meta["resolution"] = float(meta["resolution"]) / factor
    with open(target, "w") as out:
        yaml.safe_dump(meta, out, default_flow_style=None, sort_keys=False)


if __name__ == "__main__":
    main()
