#!/usr/bin/python3
"""Charts figment-bench collision's CSV: per body part, the mean gap (bars) and the
largest gap (ticks) of each volume, and the time of one point query.
Usage: plot_collision.py collision.csv collision.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    parts = list(dict.fromkeys(r["part"] for r in rows))
    methods = ["capsule", "radial", "exact"]
    colours = {"capsule": "tab:orange", "radial": "tab:blue", "exact": "tab:grey"}
    value = {(r["part"], r["method"]): r for r in rows}
    fig, (gap, cost) = plt.subplots(2, 1, figsize=(12, 8))
    width = 0.4
    for k, method in enumerate(methods[:2]):
        xs = [i + (k - 0.5) * width for i in range(len(parts))]
        gap.bar(xs, [float(value[(p, method)]["mean_gap_mm"]) for p in parts], width, color=colours[method],
                label=f"{method}: mean gap")
        gap.scatter(xs, [float(value[(p, method)]["max_gap_mm"]) for p in parts], color=colours[method], marker="_",
                    s=120, label=f"{method}: largest gap")
    gap.set_xticks(range(len(parts)), parts, rotation=45, ha="right")
    gap.set_ylabel("gap from the body (mm)")
    gap.set_yscale("log")
    gap.legend(fontsize=8)
    gap.set_title("how far each volume stands off the body's vertices (all enclosed)")
    for k, method in enumerate(methods):
        xs = [i + (k - 1) * 0.27 for i in range(len(parts))]
        cost.bar(xs, [float(value[(p, method)]["query_ns"]) for p in parts], 0.27, color=colours[method], label=method)
    cost.set_xticks(range(len(parts)), parts, rotation=45, ha="right")
    cost.set_ylabel("one point query (ns)")
    cost.set_yscale("log")
    cost.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png_path, dpi=100)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
