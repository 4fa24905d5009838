#!/usr/bin/python3
"""Charts figment-bench tradeoff's CSV: per garment, each configuration's median wall time
to rest against its mean deviation from the converged reference, log-log; colour by
method, marker by collision body, hollow for a progressive drape; failed configurations
as grey crosses (those that blew up have no shape to place and are only counted); the
Pareto front drawn and its points labelled.
Usage: plot_tradeoff.py tradeoff.csv tradeoff.png"""
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.lines
import matplotlib.pyplot as plt

MARKERS = {"volumes": "o", "capsules": "s", "triangles": "^", "mix": "D"}


def number(text):
    try:
        value = float(text)
    except ValueError:
        return math.nan
    return value


def label(r):
    parts = [r["method"], r["body"]]
    if r["progressive"] != "off":
        parts.append("prog " + r["progressive"])
    if number(r["resolution"]) != 1.0:
        parts.append(f"x{number(r['resolution']):g} sections")
    return ", ".join(parts)


def chart(ax, rows, methods, colors):
    done = [r for r in rows if not r["failure"]]
    failed = [r for r in rows if r["failure"]]
    for r in done:
        color = colors[r["method"]]
        hollow = r["progressive"] != "off"
        ax.scatter(number(r["mean_dev_pct_height"]), number(r["median_wall_s"]), marker=MARKERS.get(r["body"], "o"),
                   s=34, facecolors="none" if hollow else color, edgecolors=color, linewidths=1.2, zorder=3)
    for r in failed:
        dev, wall = number(r["mean_dev_pct_height"]), number(r["median_wall_s"])
        if math.isnan(dev) or math.isnan(wall) or wall == 0.0:
            continue  # blew up or refused: no point to put (listed in the CSV)
        ax.scatter(dev, wall, marker="x", c="grey", s=30, zorder=2)
    front = sorted((r for r in done if r["pareto"] == "1"), key=lambda r: number(r["median_wall_s"]))
    if front:
        ax.plot([number(r["mean_dev_pct_height"]) for r in front], [number(r["median_wall_s"]) for r in front],
                color="black", linewidth=0.9, zorder=1)
        for i, r in enumerate(front):  # alternate sides so neighbours' labels do not overlap
            ax.annotate(label(r), (number(r["mean_dev_pct_height"]), number(r["median_wall_s"])),
                        textcoords="offset points", xytext=(6, 4 if i % 2 else -10), fontsize=6.5)
    blew = sum(1 for r in failed if math.isnan(number(r["mean_dev_pct_height"])))
    ax.text(0.01, 0.01, f"{len(done)} rested whole, {len(failed)} failed ({blew} without a shape: blew up)",
            transform=ax.transAxes, fontsize=7, color="grey")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("mean deviation at rest from the reference, % of the garment's height")
    ax.set_ylabel("wall time to rest, s (one core)")
    ax.set_title(f"{rows[0]['scene']}", fontsize=9)
    ax.grid(True, which="both", linewidth=0.3, alpha=0.5)


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    methods = list(dict.fromkeys(r["method"] for r in rows))
    palette = plt.get_cmap("tab10")
    colors = {m: palette(i % 10) for i, m in enumerate(methods)}
    fig, axes = plt.subplots(len(scenes), 1, figsize=(9, 5.2 * len(scenes)), squeeze=False)
    for ax, scene in zip(axes[:, 0], scenes):
        chart(ax, [r for r in rows if r["scene"] == scene], methods, colors)
    handles = [matplotlib.lines.Line2D([], [], color=colors[m], marker="o", linestyle="") for m in methods]
    handles += [matplotlib.lines.Line2D([], [], color="black", marker=MARKERS[b], linestyle="", markerfacecolor="none")
                for b in MARKERS]
    handles += [matplotlib.lines.Line2D([], [], color="grey", marker="x", linestyle=""),
                matplotlib.lines.Line2D([], [], color="black", linewidth=0.9)]
    names = methods + list(MARKERS) + ["failed (tore or never rested)", "Pareto front"]
    fig.legend(handles, names, fontsize=7, loc="upper right", title="hollow: progressive", title_fontsize=7)
    fig.suptitle("Speed against accuracy (figment-bench tradeoff)", fontsize=10)
    fig.tight_layout(rect=(0, 0, 0.8, 0.97))
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
