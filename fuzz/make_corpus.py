#!/usr/bin/env python3
"""Writes the seed corpus of the fuzz targets (fuzz/corpus/<target>/), a few small valid and
nearly valid inputs per parser. The files are committed; run this again only to change them:
    python3 fuzz/make_corpus.py
"""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write(target, name, data):
    directory = os.path.join(HERE, "corpus", target)
    os.makedirs(directory, exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(directory, name), "wb") as f:
        f.write(data)


def png(width, height, color_type, bit_depth, rows, extra_chunks=()):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    raw = b"".join(b"\x00" + row for row in rows)
    header = struct.pack(">IIBBBBB", width, height, bit_depth, color_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + b"".join(chunk(k, v) for k, v in extra_chunks) +
            chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def bmp24(width, height, pixels):
    """pixels: rows top first, each a list of (b, g, r)."""
    stride = (width * 3 + 3) & ~3
    data = b""
    for row in reversed(pixels):  # BMP stores the bottom row first
        line = b"".join(bytes(p) for p in row)
        data += line + b"\x00" * (stride - len(line))
    header = struct.pack("<2sIHHI", b"BM", 14 + 40 + len(data), 0, 0, 14 + 40)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 24, 0, len(data), 2835, 2835, 0, 0)
    return header + info + data


def bmp8(width, height, rows):
    """8-bit palettised (grey palette), rows top first."""
    stride = (width + 3) & ~3
    data = b"".join(bytes(r) + b"\x00" * (stride - width) for r in reversed(rows))
    palette = b"".join(bytes((i, i, i, 0)) for i in range(256))
    offset = 14 + 40 + len(palette)
    header = struct.pack("<2sIHHI", b"BM", offset + len(data), 0, 0, offset)
    info = struct.pack("<IiiHHIIiiII", 40, width, height, 1, 8, 0, len(data), 2835, 2835, 256, 0)
    return header + info + palette + data


# A 2 x 2 GIF89a with a 4-colour global palette (black, white, grey, red), LZW min code size 2.
GIF_2X2 = (b"GIF89a\x02\x00\x02\x00\x91\x00\x00"
           b"\x00\x00\x00\xff\xff\xff\x80\x80\x80\xff\x00\x00"
           b"!\xf9\x04\x00\x00\x00\x00\x00"
           b",\x00\x00\x00\x00\x02\x00\x02\x00\x00\x02\x03\x44\x34\x05\x00;")
# The classic 1 x 1 transparent GIF.
GIF_1X1 = (b"GIF89a\x01\x00\x01\x00\x80\x00\x00\x00\x00\x00\xff\xff\xff"
           b"!\xf9\x04\x01\x00\x00\x00\x00,\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02D\x01\x00;")

PGM_P5_8 = b"P5\n3 2\n255\n" + bytes([0, 128, 254, 255, 205, 16])
PGM_P5_16 = b"P5\n# 16-bit\n2 2\n65535\n" + struct.pack(">4H", 0, 1000, 40000, 65535)
PGM_P2_8 = b"P2\n# map\n4 3\n255\n0 0 255 255\n254 205 0 255\n255 255 255 0\n"
PGM_P2_16 = b"P2 2 2 1023\n0 1023\n512 7\n"
PGM_P2_MAXVAL1 = b"P2\r\n3\t1 #c\n1\n0 1 0"

PNG_GRAY = png(3, 2, 0, 8, [bytes([0, 128, 255]), bytes([254, 205, 16])])
PNG_RGBA = png(2, 2, 6, 8, [bytes([255, 0, 0, 255, 0, 255, 0, 128]), bytes([0, 0, 255, 0, 255, 255, 255, 255])])
PNG_GRAY16 = png(2, 1, 0, 16, [struct.pack(">2H", 0, 65535)])
PNG_PALETTE = png(4, 1, 3, 2, [bytes([0b00011011])],
                  extra_chunks=[(b"PLTE", bytes([0, 0, 0, 255, 255, 255, 128, 128, 128, 255, 0, 0])),
                                (b"tRNS", bytes([255, 0]))])
PNG_GRAY1 = png(9, 2, 0, 1, [bytes([0b10101010, 0b10000000]), bytes([0b01010101, 0])])

BMP_24 = bmp24(2, 2, [[(0, 0, 0), (255, 255, 255)], [(128, 128, 128), (0, 0, 255)]])
BMP_8 = bmp8(3, 2, [[0, 128, 255], [254, 205, 16]])

# ---------------------------------------------------------------- fuzz_pgm
write("pgm", "p5_8bit.pgm", PGM_P5_8)
write("pgm", "p5_16bit.pgm", PGM_P5_16)
write("pgm", "p2_8bit.pgm", PGM_P2_8)
write("pgm", "p2_16bit.pgm", PGM_P2_16)
write("pgm", "p2_maxval1.pgm", PGM_P2_MAXVAL1)
write("pgm", "p5_truncated.pgm", b"P5 4 4 255\n\x00\x01")

# ---------------------------------------------------------------- fuzz_image
write("image", "gray.png", PNG_GRAY)
write("image", "rgba.png", PNG_RGBA)
write("image", "gray16.png", PNG_GRAY16)
write("image", "palette.png", PNG_PALETTE)
write("image", "gray1.png", PNG_GRAY1)
write("image", "rgb24.bmp", BMP_24)
write("image", "gray8.bmp", BMP_8)
write("image", "2x2.gif", GIF_2X2)
write("image", "1x1.gif", GIF_1X1)
write("image", "p5_8bit.pgm", PGM_P5_8)
write("image", "p2_16bit.pgm", PGM_P2_16)

# ---------------------------------------------------------------- fuzz_matrix
write("matrix", "spaces.txt", "0 1 0\n0 0 1\n1 0 0\n")
write("matrix", "commas.txt", "0,1,0,0\n1,1,0,0\n")
write("matrix", "packed.txt", "0110\n0000\r\n1001\n")
write("matrix", "comments.txt", "# a map\n\n0\t1 # row 1\n1, 0\n# end\n")
write("matrix", "bom.txt", "\ufeff01\n10")
write("matrix", "ragged.txt", "0 1\n0 1 1\n")

# ---------------------------------------------------------------- fuzz_movingai_map
write("movingai_map", "small.map", "type octile\nheight 3\nwidth 4\nmap\n..@.\n.TG.\nWS.O\n")
write("movingai_map", "crlf.map", "type octile\r\nheight 2\r\nwidth 2\r\nmap\r\n.@\r\n@.\r\n")
write("movingai_map", "order.map", "width 3\nheight 1\ntype octile\nmap\n.G.")
write("movingai_map", "short.map", "type octile\nheight 3\nwidth 2\nmap\n..\n..\n")
write("movingai_map", "wide.map", "type octile\nheight 1\nwidth 2\nmap\n...\n")

# ---------------------------------------------------------------- fuzz_map_yaml (YAML [NUL image])
MAP_YAML = ("image: map.pgm\nresolution: 0.05\norigin: [-10.0, -10.0, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n")
write("map_yaml", "map.yaml", MAP_YAML)
write("map_yaml", "flow.yaml", "{image: /maps/lab.png, resolution: 1e-2, origin: [0, 0, 1.57], mode: trinary, "
                               "negate: true}")
write("map_yaml", "with_png.yaml", MAP_YAML.encode() + b"\x00" + PNG_GRAY)
write("map_yaml", "with_p2.yaml", b"image: m.pgm\nresolution: 1\norigin: [0,0,0]\nmode: scale\n\x00" + PGM_P2_8)
# mode: raw, each pixel a costmap_2d cost: a P5 of costs, and an RGBA PNG (channels averaged, alpha not counted).
write("map_yaml", "raw_costs.yaml", MAP_YAML.encode() + b"mode: raw\n\x00P5\n4 2\n255\n" + bytes([0, 1, 128, 252, 253, 254, 255, 50]))
write("map_yaml", "raw_rgba.yaml", b"image: c.png\nmode: raw\nresolution: 1\norigin: [0,0,0]\nnegate: 1\n\x00" +
      png(2, 1, 6, 8, [bytes([10, 20, 31, 0, 200, 201, 202, 255])]))
write("map_yaml", "anchors.yaml", "r: &r 0.5\nimage: \"x.pgm\"\nresolution: *r\norigin: !!seq [1, 2, 3]\n"
                                  "free_thresh: 0.7\n")

# ---------------------------------------------------------------- fuzz_parameters (key=value lines)
write("parameters", "ants.txt", "ants=50")
write("parameters", "alpha_nan.txt", "alpha=nan")
write("parameters", "seed_max.txt", "seed=18446744073709551615")
write("parameters", "several.txt", "beta=7.5\nkappa=0.9\nislands=9\nisland_strategy=paper\n"
                                   "allow_corner_cutting=yes\nthreads=0\n")
write("parameters", "edges.txt", "q=1e308\nlambda=0x1p-3\nepsilon=-0\nmax_iterations=2147483648\n"
                                 "early_stop_iterations=-1\naco_rho=inf\naco_tau0=1e-320\n"
                                 "island_spacing_max= 3\nunknown=1\n=5")

# ---------------------------------------------------------------- fuzz_params_yaml (--params file)
write("params_yaml", "flat.yaml", "ants: 20\nmax_iterations: 30\nalpha: 1.1\nbeta: 7\nseed: 42\n"
                                  "island_strategy: geodesic\nallow_corner_cutting: True\n")
write("params_yaml", "flow.yaml", "{q: 100, kappa: .9, lambda: 3.0, epsilon: 0.5, threads: 2}")
write("params_yaml", "nested.yaml", "ants: [1, 2]\nalpha: {a: 1}\n")
write("params_yaml", "empty_value.yaml", "ants:\nbeta: ~\n")
write("params_yaml", "list.yaml", "- ants: 5\n- beta: 2\n")
write("params_yaml", "anchors.yaml", "a: &x 12\nants: *x\n? [k]\n: v\n")

# ---------------------------------------------------------------- fuzz_cli_args
for name, text in [("rowcol.txt", "0,5"), ("rowcol_spaces.txt", " 12 , -3 "), ("xy.txt", "0.4,1.5"),
                   ("xy_exp.txt", "-1e-3,2E+2"), ("serial.txt", "42"), ("serial_big.txt", "9223372036854775808"),
                   ("assign.txt", "ants = 50"), ("assign_eq.txt", "key==value=x"), ("nan.txt", "nan,inf"),
                   ("hex.txt", "0x10,0x1p3")]:
    write("cli_args", name, text)
