#!/usr/bin/python3
"""Charts figment-bench sizes' CSV: median wall time to rest against the garment's
sections, whole and progressive, log-log; o: every drape rested, ^: some, x: none;
each size's speed-up, deviation and floor beside it; failures listed.
Usage: plot_sizes.py sizes.csv sizes.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    done = [r for r in rows if not r["failure"]]
    fig, ax = plt.subplots(figsize=(8, 5))
    for prefix, label, color in (("full_", "whole garment", "tab:blue"), ("", "progressive", "tab:orange")):
        x = [int(r["sections"]) for r in done]
        y = [float(r[prefix + "median_wall_s"]) for r in done]
        ax.plot(x, y, color=color, label=label, linewidth=1.2)
        for xi, yi, r in zip(x, y, done):
            rested, runs = int(r[prefix + "rested"]), int(r["time_steps"])
            ax.scatter(xi, yi, c=color, marker="o" if rested == runs else "^" if rested else "x", s=40)
    for r in done:
        ax.annotate(f"{float(r['speed_up']):.2f}x\n{float(r['mean_dev_pct_height']):.2f} % "
                    f"(floor {float(r['floor_mean_dev_pct_height']):.2f})",
                    (int(r["sections"]), float(r["median_wall_s"])), textcoords="offset points", xytext=(4, -22),
                    fontsize=7, color="tab:orange")
    for i, r in enumerate(r for r in rows if r["failure"]):
        ax.annotate(f"{r['sections']} sections failed: {r['failure'][:70]}", (0.02, 0.95 - 0.05 * i),
                    xycoords="axes fraction", fontsize=7, color="tab:red")
    method = rows[0]["method"] if rows else ""
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("garment sections (triangles)")
    ax.set_ylabel("wall time to rest, s (one core)")
    ax.legend(fontsize=8, title="o all rested, ^ some, x none; speed-up,\nmean deviation (floor)", title_fontsize=7)
    ax.set_title(f"Time to rest against garment size ({method}; figment-bench sizes)")
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
