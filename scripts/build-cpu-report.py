#!/usr/bin/env python3
"""Sums a measurement build's CPU time (scripts/cpu-time-launcher.sh's log: "output user sys"
per compile and link) by part of the tree, by target and by kind of step, lists the heaviest
steps, and, given the build folder, counts the translation units that parse each heavy header
(ninja's recorded dependencies). CPU seconds, not wall time: the machine may be shared.

    python3 scripts/build-cpu-report.py CPU_LOG [BUILD_DIR] [--top N]
"""
import argparse
import collections
import re
import subprocess
import sys

HEAVY = {
    "Coin (Inventor/)": "/Inventor/",
    "Eigen": "/eigen3/",
    "GoogleTest": "/gtest/",
    "nlohmann/json": "/nlohmann/",
    "cpp-httplib": "httplib.h",
    "assimp": "/assimp/",
    "CLI11": "/CLI/",
}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("log")
    parser.add_argument("build", nargs="?")
    parser.add_argument("--top", type=int, default=25)
    args = parser.parse_args()
    steps = {}
    for line in open(args.log):
        parts = line.split()
        if len(parts) != 3:
            continue
        try:
            steps[parts[0]] = float(parts[1]) + float(parts[2])  # the last build of an output
        except ValueError:
            continue
    if args.build:  # only what the build makes now (a batch regrouped since leaves a stale line)
        outputs = subprocess.run(["ninja", "-C", args.build, "-t", "targets", "all"], capture_output=True,
                                 text=True).stdout
        current = {line.split(":")[0] for line in outputs.splitlines()}
        steps = {out: cpu for out, cpu in steps.items() if out in current or args.build + "/" + out in current}
    by_target = collections.Counter()
    by_kind = collections.Counter()
    by_part = collections.Counter()
    for out, cpu in steps.items():
        m = re.search(r"CMakeFiles/([^/]+)\.dir/", out)
        target = m.group(1) if m else out.split("/")[-1]
        kind = "pch" if out.endswith(".gch") else "compile" if out.endswith(".o") else "link"
        by_target[target] += cpu
        by_kind[kind] += cpu
        part = "tests" if target.startswith("test_") else out.split("/")[0] if m else "programs"
        if "/bin/" in out or out.startswith("bin/"):
            part = "links of programs and tests"
        by_part[part] += cpu
    total = sum(steps.values())
    print(f"{len(steps)} steps, {total:.0f} CPU-s (user+sys)")
    print("by kind: " + ", ".join(f"{k} {v:.0f}" for k, v in by_kind.most_common()))
    print("by part: " + ", ".join(f"{k} {v:.0f}" for k, v in by_part.most_common()))
    print("by target:")
    for target, cpu in by_target.most_common(30):
        count = sum(1 for o in steps if f"/{target}.dir/" in o)
        print(f"  {cpu:8.1f}  {target} ({count} steps)")
    print(f"the {args.top} heaviest steps:")
    for out, cpu in sorted(steps.items(), key=lambda kv: -kv[1])[: args.top]:
        print(f"  {cpu:7.1f}  {out}")
    if args.build:
        deps = subprocess.run(["ninja", "-C", args.build, "-t", "deps"], capture_output=True, text=True).stdout
        parsed = collections.Counter()
        units = 0
        for block in deps.split("\n\n"):
            lines = block.strip().splitlines()
            if not lines or ": #deps" not in lines[0]:
                continue
            units += 1
            headers = "\n".join(lines[1:])
            for name, needle in HEAVY.items():
                if needle in headers:
                    parsed[name] += 1
        print(f"translation units (and precompiled headers) that parse each heavy header, of {units}:")
        for name in HEAVY:
            print(f"  {parsed[name]:4d}  {name}")


if __name__ == "__main__":
    sys.exit(main())
