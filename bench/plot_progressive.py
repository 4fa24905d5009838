#!/usr/bin/python3
"""Charts figment-bench progressive's CSV: for each method, the progressive drapes' median
wall time to rest (as a share of the full garment's) against their at-rest mean deviation
from it, one point per schedule (begin level, split rate), failures marked; a dotted
line per method at its floor (the full garment's drapes' deviation from each other).
Usage: plot_progressive.py progressive.csv progressive.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.lines
import matplotlib.pyplot as plt


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    fig, ax = plt.subplots(figsize=(8, 5))
    colors = ["tab:blue", "tab:orange", "tab:green", "tab:red"]
    for m, color in zip(methods, colors):
        # The floor: how far the full garment's own drapes at the nearby time steps differ.
        floor = float(next(r for r in rows if r["method"] == m)["floor_mean_dev_pct_height"])
        ax.axvline(floor, color=color, linewidth=0.8, linestyle=":")
        ax.annotate(f"floor {floor:.3f} %", (floor, 0.05), xycoords=("data", "axes fraction"), rotation=90,
                    fontsize=7, color=color, xytext=(2, 0), textcoords="offset points")
        for r in (r for r in rows if r["method"] == m):
            label = f"begin {r['begin_level']}, {float(r['split_rate_per_s']):g}/s"
            if r["failure"]:
                ax.annotate(f"{m} {label}: failed ({r['failure'][:60]}...)", (0.02, 0.95 - 0.05 * methods.index(m)),
                            xycoords="axes fraction", color=color, fontsize=7)
                continue
            share = float(r["median_wall_s"]) / float(r["full_median_wall_s"])
            dev = float(r["mean_dev_pct_height"])
            rested, runs = int(r["rested"]), int(r["time_steps"])
            marker = "o" if rested == runs else "^" if rested else "x"
            ax.scatter(dev, share, c=color, marker=marker, s=45)
            ax.annotate(label, (dev, share), textcoords="offset points", xytext=(4, 4), fontsize=7, color=color)
    ax.axhline(1.0, color="grey", linewidth=0.8)
    ax.axhline(0.5, color="grey", linewidth=0.8, linestyle="--")
    ax.axvline(0.03, color="grey", linewidth=0.8, linestyle="--")
    ax.text(0.031, 0.52, "target: 2x at 0.03 %", fontsize=7, color="grey")
    ax.set_xscale("log")
    ax.set_xlabel("at-rest mean deviation from the full garment's drape, % of its height")
    ax.set_ylabel("wall time to rest / the full garment's")
    handles = [matplotlib.lines.Line2D([], [], color=c, marker="o", linestyle="") for c in colors[: len(methods)]]
    ax.legend(handles, methods, fontsize=8, title="o all rested, ^ some, x none", title_fontsize=7, loc="center right")
    ax.set_title(f"Progressive drapes of {rows[0]['scene']} (figment-bench progressive)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
