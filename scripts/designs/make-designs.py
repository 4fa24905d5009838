#!/usr/bin/env python3
"""GarmentCode designs the shipped catalogue does not have, made with GarmentCode's own library
(pygarment 2.0.2, MIT) by FIGMENT's design programs (scripts/designs/*.py), each for the
GarmentCode body of a chart size (scenes/patterns/bodies/): tests/io/data/designs/.

    python3 -m venv build/designs-venv
    build/designs-venv/bin/pip install --no-deps --require-hashes -r scripts/designs/requirements.txt
    build/designs-venv/bin/python scripts/designs/make-designs.py [--out DIR] [--check | --every-size]

--check writes into a temporary folder and compares with the committed files byte for byte
(exit 1 and one line a file that differs or is missing). --every-size makes each design for
every chart size of its sex instead (not committed: scripts/pattern-figures.py --index
DIR/index.json sews them all)."""

import argparse
import filecmp
import json
import os
import sys
import tempfile

from assemble import assemble, write
from body import ROOT, Body, chart_sizes
import shorts
import skirts
import tops

# name, program, sex, size number (the chart's), what it is
DESIGNS = [
    ("tank-f-38", lambda b: tops.tank_top(b, front_neck=12.0, back_neck=4.0), "female", 38,
     "tank top, scoop neck, to the hips"),
    ("tank-m-48", lambda b: tops.tank_top(b, front_neck=9.0, back_neck=3.0), "male", 48,
     "tank top, to the hips"),
    ("dress-f-38", lambda b: tops.aline_dress(b, front_neck=10.0, back_neck=4.0, dart_width=3.0), "female", 38,
     "sleeveless A-line dress above the knee, bust darts"),
    ("gores-f-38", lambda b: skirts.six_gore_skirt(b, length=58.0, flare=10.0), "female", 38,
     "six-gore flared skirt to the knee, straight waistband"),
    ("yoke-f-38", lambda b: skirts.yoke_skirt(b, yoke_depth=16.0, length=55.0, gather=1.6), "female", 38,
     "hip yoke with a gathered tier"),
    ("shorts-f-38", lambda b: shorts.shorts(b, inseam=12.0), "female", 38, "shorts, 12 cm inside leg, waistband"),
    ("shorts-m-48", lambda b: shorts.shorts(b, inseam=20.0), "male", 48, "shorts, 20 cm inside leg, waistband"),
]


def made(every_size):
    """(name, program, sex, number, what) of each pattern to make: the designs as listed, or each
    for every chart size of its sex (named NAME-NUMBER with the size's number)."""
    for name, program, sex, number, what in DESIGNS:
        for n in sorted(chart_sizes(sex)) if every_size else [number]:
            yield "%s-%d" % (name.rsplit("-", 1)[0], n), program, sex, n, what


def make(folder, every_size=False):
    """Writes the designs and index.json into folder; returns the files' names."""
    entries, names = [], []
    for name, program, sex, number, what in made(every_size):
        panels, stitches = program(Body(sex, number))
        pattern = assemble(name, panels, stitches)
        names.append(os.path.basename(write(pattern, folder)))
        entries.append({"name": name, "what": what, "sex": sex, "size": chart_sizes(sex)[number], "number": number,
                        "body": "scenes/patterns/bodies/%s-%d.yaml" % (sex, number), "file": names[-1],
                        "panels": len(pattern.pattern["panels"]), "stitches": len(pattern.pattern["stitches"])})
    with open(os.path.join(folder, "index.json"), "w") as f:
        json.dump({"source": "made by scripts/designs/make-designs.py with pygarment 2.0.2 (MIT)",
                   "designs": entries}, f, indent=1)
        f.write("\n")
    return names + ["index.json"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--out", default=os.path.join(ROOT, "tests", "io", "data", "designs"))
    parser.add_argument("--check", action="store_true", help="compare with the files in --out, write nothing")
    parser.add_argument("--every-size", action="store_true", help="each design in every chart size of its sex")
    args = parser.parse_args()
    if not args.check:
        os.makedirs(args.out, exist_ok=True)
        make(args.out, args.every_size)
        return 0
    with tempfile.TemporaryDirectory() as folder:
        differ = [n for n in make(folder) if not os.path.exists(os.path.join(args.out, n))
                  or not filecmp.cmp(os.path.join(folder, n), os.path.join(args.out, n), shallow=False)]
    for n in differ:
        print("%s: differs from what make-designs.py makes" % os.path.join(args.out, n), file=sys.stderr)
    return 1 if differ else 0


if __name__ == "__main__":
    sys.exit(main())
