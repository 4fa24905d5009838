#!/usr/bin/python3
"""Compares two runs of figment-bench tradeoff (their tradeoff.csv): what moved.

    python3 bench/compare_tradeoff.py OLD.csv NEW.csv

Prints Markdown: per garment, every configuration on either run's Pareto front with its
wall and deviation in both runs (a point that moved right, slower, or up, less accurate,
is marked); then per garment and method the median ratio of wall (new / old) and the
median change of deviation over the configurations that rested whole in both runs; then
the configurations that failed in one run and not the other. Configurations only one run
has (a method added) are listed apart. Standard library only."""
import csv
import statistics
import sys

KEY = ("scene", "method", "body", "progressive", "resolution")
# Within these a point has not moved: the walls of a repeated run on an idle machine agree
# to a few per cent (docs/results.md), and deviations to the reference's own noise.
WALL_SLACK = 1.10
DEV_SLACK = 0.02  # percentage points of the garment's height


def rows(path):
    with open(path, newline="") as f:
        return {tuple(r[k] for k in KEY): r for r in csv.DictReader(f)}


def ok(r):
    return r is not None and r["failure"] == ""


def moved(old, new):
    marks = []
    if float(new["median_wall_s"]) > WALL_SLACK * float(old["median_wall_s"]):
        marks.append("slower")
    if float(new["mean_dev_pct_height"]) > float(old["mean_dev_pct_height"]) + DEV_SLACK:
        marks.append("less accurate")
    return ", ".join(marks)


def point(r):
    if r is None:
        return "–"
    if not ok(r):
        return "failed: " + r["failure"]
    return "%.3f s, %.3f %%" % (float(r["median_wall_s"]), float(r["mean_dev_pct_height"]))


def main(old_path, new_path):
    old, new = rows(old_path), rows(new_path)
    scenes = sorted({k[0] for k in new})
    print("## Pareto points, old run against new\n")
    print("| garment | method | body | progressive | resolution | old | new | moved |")
    print("| --- | --- | --- | --- | --- | --- | --- | --- |")
    for scene in scenes:
        keys = sorted(k for k in set(old) | set(new) if k[0] == scene and
                      ((k in old and old[k]["pareto"] == "1") or (k in new and new[k]["pareto"] == "1")))
        for k in keys:
            o, n = old.get(k), new.get(k)
            front = "old front" if o and o["pareto"] == "1" else ""
            front += (" and " if front else "") + "new front" if n and n["pareto"] == "1" else ""
            mark = moved(o, n) if ok(o) and ok(n) else ""
            print("| %s | %s | %s | %s | %s | %s | %s | %s (%s) |" % (scene.split("/")[-1], k[1], k[2], k[3], k[4],
                                                                point(o), point(n), mark or "no", front))
    print("\n## Per method, configurations that rested whole in both runs\n")
    print("| garment | method | configurations | wall new / old, median (range) | deviation change, median (range), points |")
    print("| --- | --- | --- | --- | --- |")
    for scene in scenes:
        for method in sorted({k[1] for k in new if k[0] == scene}):
            both = [k for k in new if k[0] == scene and k[1] == method and ok(new[k]) and ok(old.get(k))]
            if not both:
                continue
            walls = [float(new[k]["median_wall_s"]) / float(old[k]["median_wall_s"]) for k in both]
            devs = [float(new[k]["mean_dev_pct_height"]) - float(old[k]["mean_dev_pct_height"]) for k in both]
            print("| %s | %s | %d | %.2f (%.2f–%.2f) | %+.3f (%+.3f to %+.3f) |" % (
                scene.split("/")[-1], method, len(both), statistics.median(walls), min(walls), max(walls),
                statistics.median(devs), min(devs), max(devs)))
    print("\n## Failed in one run only\n")
    for k in sorted(set(old) & set(new)):
        if ok(old[k]) != ok(new[k]):
            print("- %s: old %s; new %s" % (" ".join(k), point(old[k]), point(new[k])))
    added = sorted(set(new) - set(old))
    if added:
        print("\n## Only in the new run: %d configurations (%s)" % (
            len(added), ", ".join(sorted({k[1] for k in added}))))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
