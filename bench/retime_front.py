#!/usr/bin/python3
"""Times the Pareto points of two tradeoff runs again, side by side on one machine: each
configuration on either run's front, draped by the old build in the old tree and by the new
build in the new tree, one after the other, --repeat times each (median wall). A tradeoff
study's walls are only as good as the machine was quiet while it ran; this puts the points
that decide the front on one footing. Deviations are the runs' own (a drape's shape does not
depend on the machine).

    python3 bench/retime_front.py OLD_TREE OLD.csv NEW_TREE NEW.csv [--repeat 5]

OLD_TREE and NEW_TREE are source trees with build/bin/figment-bench built; each run of the
bench drapes with a cheap reference (implicit:0.05, unchecked), whose deviation is not used.
Prints Markdown: per configuration, the runs' deviations and both walls. Standard library
only."""
import argparse
import csv
import re
import subprocess
import tempfile

KEY = ("scene", "method", "body", "progressive", "resolution")
ROW = re.compile(r"^\s+(\S+)\s+(\S+)\s+(\S+)\s+x(\S+)\s+\d+ sections:\s+(\d+) steps\s+([\d.]+) s wall")


def front(path):
    with open(path, newline="") as f:
        return {tuple(r[k] for k in KEY): r for r in csv.DictReader(f) if r["pareto"] == "1"}


def rows(path):
    with open(path, newline="") as f:
        return {tuple(r[k] for k in KEY): r for r in csv.DictReader(f)}


def wall(tree, key, repeat):
    """Median wall of `key` draped by the tree's build, or None where the build does not know
    its method or the drape failed."""
    scene, method, body, progressive, resolution = key
    with tempfile.TemporaryDirectory() as out:
        run = subprocess.run([tree + "/build/bin/figment-bench", "tradeoff", "--scene", scene, "--method", method,
                              "--body", body, "--schedule", progressive, "--resolution", resolution, "--reference",
                              "implicit:0.05", "--no-reference-check", "--repeat", str(repeat), "--out", out],
                             cwd=tree, capture_output=True, text=True, env={"OMP_NUM_THREADS": "1", "PATH": "/usr/bin:/bin"})
    for line in run.stdout.splitlines():
        match = ROW.match(line)
        if match and match.group(1) == method:
            return float(match.group(6)), int(match.group(5))
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("old_tree")
    parser.add_argument("old_csv")
    parser.add_argument("new_tree")
    parser.add_argument("new_csv")
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    old, new = rows(args.old_csv), rows(args.new_csv)
    keys = sorted(set(front(args.old_csv)) | set(front(args.new_csv)))
    print("| garment | configuration | front | deviation old → new (%) | wall old → new (s), one machine | ratio |")
    print("| --- | --- | --- | --- | --- | --- |")
    for key in keys:
        o, n = old.get(key), new.get(key)
        fronts = "/".join(name for name, r in (("old", o), ("new", n)) if r and r["pareto"] == "1")
        t_old = wall(args.old_tree, key, args.repeat) if o else None
        t_new = wall(args.new_tree, key, args.repeat)
        dev = lambda r: ("%.3f" % float(r["mean_dev_pct_height"])) if r and not r["failure"] else (
            "failed" if r else "–")
        walls = "%s → %s" % ("%.3f" % t_old[0] if t_old else "–", "%.3f" % t_new[0] if t_new else "–")
        ratio = "%.2f" % (t_new[0] / t_old[0]) if t_old and t_new else ""
        print("| %s | %s %s %s x%s | %s | %s → %s | %s | %s |" % (key[0].split("/")[-1], key[1], key[2], key[3], key[4],
                                                              fronts, dev(o), dev(n), walls, ratio), flush=True)


if __name__ == "__main__":
    main()
