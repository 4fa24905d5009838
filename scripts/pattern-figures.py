#!/usr/bin/env python3
"""docs/patterns.csv: every shipped sewing pattern (scenes/patterns/index.json) whose size the
size chart has (scenes/sizes/chart.txt), sewn and draped on that size's chart body, and what
each drape did (figment-sew --stats), one row a pattern.

    OMP_NUM_THREADS=1 python3 scripts/pattern-figures.py [--bin build/bin] [--out docs/patterns.csv]
        [--style tshirt ...] [--sex female|male] [--size M ...] [--repeat 5] [--index INDEX.json]

Each size's chart body is made once by figment-body (MakeHuman's, to the chart's stature and
girths) into a temporary folder; each pattern is sewn on it by figment-sew (cotton, backward
Euler from 1/20 s growing to figment-sew's --max-step or this one's, 2 cm spacing), --repeat times: the row is the run of median wall time (the
sewing and the drape, without reading the body). A pattern the reader refuses is a row with
its one-line reason. --index sews another index's patterns (its files named relative to it,
each entry's "style" or "name" the row's style): tests/io/data/designs/index.json, the other
designs (docs/patterns.md, "Other designs").
Standard library only. Needs MakeHuman's data (scripts/setup.sh)."""

import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIELDS = ["style", "sex", "size", "number", "panels", "nodes", "triangles", "sewing_steps", "drape_steps", "steps",
          "sewing_wall_s", "wall_s", "at_rest", "max_stretch", "inside_nodes", "open_seam_pairs", "seam_gap_max_m",
          "closed_gap_m", "clean", "problem"]


def chart_sizes(path):
    """(sex, number) -> dict of the chart's row."""
    sizes = {}
    with open(path) as chart:
        for line in chart:
            words = line.split("#")[0].split()
            if len(words) != 7:
                continue
            sex, letter, number, stature, bust, waist, hip = words
            sizes[(sex, int(number))] = {"size": letter, "stature": stature, "bust": bust, "waist": waist, "hip": hip}
    return sizes


def make_body(binary, folder, sex, row):
    path = os.path.join(folder, "%s-%s.obj" % (sex, row["size"]))
    if not os.path.exists(path):
        subprocess.run([os.path.join(binary, "figment-body"), "--sex", sex, "--stature", row["stature"],
                        "--bust-girth", row["bust"], "--waist-girth", row["waist"], "--hip-girth", row["hip"],
                        "-o", path], check=True, stdout=subprocess.DEVNULL)
    return path


def sew(binary, folder, patterns, entry, body, extra=()):
    """One figment-sew run of the pattern (its file under `patterns`) on the body, with the
    `extra` options: its row."""
    stats = os.path.join(folder, "stats.json")
    garment = os.path.join(folder, "garment.obj")
    run = subprocess.run([os.path.join(binary, "figment-sew"), os.path.join(patterns, entry["file"]),
                          "--body", body, "-o", garment, "--stats", stats, *extra], capture_output=True, text=True)
    row = {"style": entry.get("style", entry.get("name")), "sex": entry["sex"], "size": entry["size"],
           "number": entry["number"]}
    if run.returncode != 0:
        # The file as the repository names it, not this machine's path to it.
        row["problem"] = run.stderr.strip().replace(ROOT + os.sep, "")
        return row
    figures = json.load(open(stats))
    row.update({k: figures[k] for k in FIELDS if k in figures})
    row["max_stretch"] = figures["drape"]["verdict"]["max_edge_stretch"]  # the drape's report
    row["problem"] = "; ".join(line.split(": ", 2)[-1] for line in run.stderr.strip().splitlines())
    os.remove(stats)
    return row


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--bin", default=os.path.join(ROOT, "build", "bin"))
    parser.add_argument("--out", default=os.path.join(ROOT, "docs", "patterns.csv"))
    parser.add_argument("--style", action="append", help="only these styles (repeat)")
    parser.add_argument("--sex", choices=["female", "male"])
    parser.add_argument("--size", action="append", help="only these sizes, letter codes (repeat)")
    parser.add_argument("--repeat", type=int, default=1, help="runs per pattern; the median's row is kept")
    parser.add_argument("--max-step", type=float,
                        help="figment-sew --max-step: the drape's step grows to it (0: fixed; default figment-sew's)")
    parser.add_argument("--index", default=os.path.join(ROOT, "scenes", "patterns", "index.json"),
                        help="the patterns' index (default: the shipped ones')")
    args = parser.parse_args()

    index = json.load(open(args.index))
    patterns = os.path.dirname(os.path.abspath(args.index))
    entries = index.get("patterns", index.get("designs"))
    sizes = chart_sizes(os.path.join(ROOT, "scenes", "sizes", "chart.txt"))
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        for entry in entries:
            key = (entry["sex"], entry["number"])
            if key not in sizes or (args.style and entry.get("style", entry.get("name")) not in args.style) or (
                    args.sex and entry["sex"] != args.sex) or (args.size and entry["size"] not in args.size):
                continue
            body = make_body(args.bin, folder, entry["sex"], sizes[key])
            extra = ["--max-step", str(args.max_step)] if args.max_step is not None else []
            runs = [sew(args.bin, folder, patterns, entry, body, extra) for _ in range(max(1, args.repeat))]
            runs.sort(key=lambda r: float(r.get("wall_s", 0.0)))
            row = runs[len(runs) // 2]
            rows.append(row)
            print("%-8s %-6s %-4s %s" % (row["style"], row["sex"], row["size"],
                                         "clean" if row.get("clean") else row["problem"]), file=sys.stderr)
    with open(args.out, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=FIELDS)
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
