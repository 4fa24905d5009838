#!/usr/bin/env python3
"""docs/patterns.md's pictures: shipped sewing patterns sewn and draped on their size's chart
body, one picture each (front, and 30 degrees round), and the pencil skirt's stages; and the
other designs (tests/io/data/designs/, docs/patterns.md "Other designs"), 30 degrees round.

    python3 scripts/pattern-pictures.py [--view build/bin/figment-view] [--out docs/images] [--designs-only]

Each picture is figment-view on scenes/examples/SewingPattern.iv with the pattern, its body's
chart dimensions and a colour put in; the stages are the same scene drawn placed (the
SewingPattern node itself, no engine), sewn (--stop-at 1: the first drape step after
sewing) and at rest. Standard library only. Needs MakeHuman's data (scripts/setup.sh)."""

import argparse
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
TEMPLATE = os.path.join(ROOT, "scenes", "examples", "SewingPattern.iv")
TEMPLATE_FILE = "../patterns/pencil/pencil-f-38_specification.json"
TEMPLATE_BODY = "gender 0  stature 1.68  bustGirth 0.88  waistGirth 0.72  hipGirth 0.96"
TEMPLATE_COLOUR = "diffuseColor 0.15 0.18 0.22"
TEMPLATE_STATURE = "madeForStature 1.68"

# (picture name, pattern file under scenes/patterns, HumanBody fields, garment colour)
FEMALE_M = "gender 0  stature 1.68  bustGirth 0.88  waistGirth 0.72  hipGirth 0.96"
MALE_M = "gender 1  stature 1.74  bustGirth 0.96  waistGirth 0.84  hipGirth 1.00"
FEMALE_3XL = "gender 0  stature 1.68  bustGirth 1.04  waistGirth 0.88  hipGirth 1.12"
GALLERY = [
    ("pattern-tshirt-f-38", "tshirt/tshirt-f-38", FEMALE_M, "0.85 0.85 0.80"),
    ("pattern-shirt-f-38", "shirt/shirt-f-38", FEMALE_M, "0.55 0.70 0.85"),
    ("pattern-dress-f-38", "dress/dress-f-38", FEMALE_M, "0.55 0.12 0.20"),
    ("pattern-circle-f-38", "circle/circle-f-38", FEMALE_M, "0.18 0.49 0.20"),
    ("pattern-pencil-f-38", "pencil/pencil-f-38", FEMALE_M, "0.15 0.18 0.22"),
    ("pattern-trousers-f-38", "trousers/trousers-f-38", FEMALE_M, "0.25 0.30 0.45"),
    ("pattern-tshirt-m-48", "tshirt/tshirt-m-48", MALE_M, "0.12 0.25 0.70"),
    ("pattern-trousers-m-48", "trousers/trousers-m-48", MALE_M, "0.35 0.30 0.25"),
    ("pattern-shirt-m-48", "shirt/shirt-m-48", MALE_M, "0.85 0.88 0.92"),
    ("pattern-dress-f-46", "dress/dress-f-46", FEMALE_3XL, "0.12 0.30 0.45"),
]
# The other designs: (picture name, file under tests/io/data/designs, HumanBody fields, colour).
DESIGNS = [
    ("design-tank-f-38", "tank-f-38", FEMALE_M, "0.80 0.35 0.30"),
    ("design-tank-m-48", "tank-m-48", MALE_M, "0.30 0.32 0.35"),
    ("design-dress-f-38", "dress-f-38", FEMALE_M, "0.20 0.40 0.55"),
    ("design-gores-f-38", "gores-f-38", FEMALE_M, "0.45 0.20 0.35"),
    ("design-yoke-f-38", "yoke-f-38", FEMALE_M, "0.85 0.75 0.45"),
    ("design-shorts-f-38", "shorts-f-38", FEMALE_M, "0.30 0.45 0.30"),
    ("design-shorts-m-48", "shorts-m-48", MALE_M, "0.60 0.55 0.45"),
]


def scene(text, pattern, body, colour, made_for_body=False):
    """The template with `pattern` (its path relative to scenes/examples/, no suffix), `body`
    (HumanBody's fields) and `colour` put in; made_for_body: the pattern made for the body's
    stature (the template's is 1.68 m, which the shipped gallery keeps)."""
    text = (text.replace(TEMPLATE_FILE, "%s_specification.json" % pattern)
            .replace(TEMPLATE_BODY, body).replace(TEMPLATE_COLOUR, "diffuseColor " + colour))
    if made_for_body:
        text = text.replace(TEMPLATE_STATURE, "madeForStature " + body.split("stature ")[1].split()[0])
    return text


def render(view, scene_path, out, extra):
    subprocess.run([view, scene_path, "-o", out, "--size", "300x420", "--no-cache"] + extra, check=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--view", default=os.path.join(ROOT, "build", "bin", "figment-view"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "images"))
    parser.add_argument("--designs-only", action="store_true", help="only the other designs' pictures")
    args = parser.parse_args()
    text = open(TEMPLATE).read()
    for name in (TEMPLATE_FILE, TEMPLATE_BODY, TEMPLATE_COLOUR, TEMPLATE_STATURE):
        assert name in text, "%s no longer holds %r" % (TEMPLATE, name)
    # The scene names its pattern relative to itself: the temporary scenes sit beside it.
    folder = os.path.dirname(TEMPLATE)
    with tempfile.NamedTemporaryFile("w", suffix=".iv", dir=folder, delete=False) as handle:
        path = handle.name
    try:
        for picture, design, body, colour in DESIGNS:
            with open(path, "w") as handle:
                handle.write(scene(text, "../../tests/io/data/designs/" + design, body, colour, made_for_body=True))
            render(args.view, path, os.path.join(args.out, picture + ".png"), ["--view", "30,10"])
        if args.designs_only:
            return
        for picture, pattern, body, colour in GALLERY:
            with open(path, "w") as handle:
                handle.write(scene(text, "../patterns/" + pattern, body, colour))
            render(args.view, path, os.path.join(args.out, picture + ".png"), ["--view", "front", "--view", "30,10"])
        # The pencil skirt's stages: placed (the pattern node drawn, no engine), sewn, at rest.
        placed = text.replace("whichChild -1", "whichChild 0")
        placed = placed[:placed.index("    Coordinate3 {")] + placed[placed.index("    ClothingLayer"):].split("\n", 1)[1]
        with open(path, "w") as handle:
            handle.write(placed)
        render(args.view, path, os.path.join(args.out, "pattern-stage-placed.png"), ["--view", "30,10"])
        with open(path, "w") as handle:
            handle.write(text)
        render(args.view, path, os.path.join(args.out, "pattern-stage-sewn.png"), ["--view", "30,10", "--stop-at", "1"])
        render(args.view, path, os.path.join(args.out, "pattern-stage-draped.png"), ["--view", "30,10"])
    finally:
        os.remove(path)


if __name__ == "__main__":
    main()
