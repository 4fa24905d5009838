#!/usr/bin/env python3
"""docs/sizes.md's page of pictures: three chart bodies x three sizes of one catalogue style,
each drape in its fit map's colours, as one picture, and the verdicts as a Markdown table.

    python3 scripts/size-pictures.py [--view build/bin/figment-view] [--style pencil]
        [--bodies S M XL] [--sizes S M XL] [--map stretch] [--out docs/images/sizes-grid.png]

Each cell is figment-view on scenes/sizes/pencil-S-on-XL.iv with its body's chart dimensions
and its garment ("pencil:M") put in, --fit-map and --stats (the verdicts: "fit"."text"); the
cells are cropped to the garment's part of the picture and tiled, rows the bodies, columns the
sizes. Standard library only (the PNG files are 8-bit RGB or RGBA, as io/PngFile writes them).
Needs MakeHuman's data (scripts/setup.sh)."""

import argparse
import json
import os
import struct
import subprocess
import sys
import tempfile
import zlib

import pngrows

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEMPLATE = os.path.join(ROOT, "scenes", "sizes", "pencil-S-on-XL.iv")
TEMPLATE_BODY = "stature 1.68  bustGirth 0.96  waistGirth 0.80  hipGirth 1.04"
CELL = (300, 400)             # each render, pixels
CROP = (70, 120, 230, 280)    # the garment's part of it: left, top, right, bottom


def read_png(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB or RGBA PNG."""
    data = open(path, "rb").read()
    assert data[:8] == pngrows.SIGNATURE, path
    width, height, channels, rows = pngrows.unfiltered_rows(data)
    return width, height, [bytes(v for i, v in enumerate(line) if channels == 3 or i % 4 != 3) for line in rows]


def write_png(path, width, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\x00" + row for row in rows)
    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, len(rows), 8, 2, 0, 0, 0)) +
                  chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def chart_sizes(sex):
    sizes = {}
    for line in open(os.path.join(ROOT, "scenes", "sizes", "chart.txt")):
        words = line.split("#")[0].split()
        if len(words) == 7 and words[0] == sex:
            sizes[words[1]] = [float(w) for w in words[3:]]
    return sizes


def cell(view, folder, style, body, size, dims, kind):
    """The cropped fit map's rows and the verdict line of `style:size` on the `body` chart body."""
    text = open(TEMPLATE).read().replace(TEMPLATE_BODY, "stature %.2f  bustGirth %.2f  waistGirth %.2f  hipGirth %.2f"
                                         % tuple(dims)).replace('"pencil:S"', '"%s:%s"' % (style, size))
    scene, png, stats = (os.path.join(folder, "%s-on-%s.%s" % (size, body, ext)) for ext in ("iv", "png", "json"))
    open(scene, "w").write(text)
    subprocess.run([view, scene, "-o", png, "--size", "%dx%d" % CELL, "--view", "0,0", "--fit-map", kind,
                    "--stats", stats, "--no-cache"], check=True, stderr=subprocess.DEVNULL)
    fit = json.load(open(stats))["garments"][0].get("fit", {})
    _, _, rows = read_png(png)
    left, top, right, bottom = CROP
    return [row[3 * left:3 * right] for row in rows[top:bottom]], fit.get("text", "")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--view", default=os.path.join(ROOT, "build", "bin", "figment-view"))
    parser.add_argument("--style", default="pencil")
    parser.add_argument("--sex", default="female")
    parser.add_argument("--bodies", nargs="+", default=["S", "M", "XL"])
    parser.add_argument("--sizes", nargs="+", default=["S", "M", "XL"])
    parser.add_argument("--map", default="stretch", choices=["stretch", "ease", "pressure"])
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "images", "sizes-grid.png"))
    args = parser.parse_args()
    chart = chart_sizes(args.sex)
    grid, table = [], ["| body \\ size | " + " | ".join(args.sizes) + " |", "| --- |" + " --- |" * len(args.sizes)]
    with tempfile.TemporaryDirectory() as folder:
        for body in args.bodies:
            cells = [cell(args.view, folder, args.style, body, size, chart[body], args.map) for size in args.sizes]
            grid += [b"".join(c[0][y] for c in cells) for y in range(len(cells[0][0]))]
            table.append("| %s | " % body + " | ".join(c[1] for c in cells) + " |")
            print("body %s done" % body, file=sys.stderr)
    write_png(args.out, (CROP[2] - CROP[0]) * len(args.sizes), grid)
    print("\n".join(table))


if __name__ == "__main__":
    main()
