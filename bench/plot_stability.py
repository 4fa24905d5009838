#!/usr/bin/python3
"""Charts figment-bench stability's CSV: a stability map (time step against
configuration) and the at-rest deviation from the small-step reference against dt.
Usage: plot_stability.py stability.csv stability.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main(csv_path, png_path):
    rows = list(csv.DictReader(open(csv_path)))
    configs = []
    for r in rows:
        key = (r["integrator"], r["strain_clamp"], r["limiter"])
        if key not in configs:
            configs.append(key)
    label = {k: f"{k[0]}{' +strain' if k[1] == '1' else ''}{' +' + k[2] if k[2] != 'none' else ''}" for k in configs}
    fig, (stab, dev) = plt.subplots(1, 2, figsize=(13, 0.35 * len(configs) + 3))
    for y, k in enumerate(configs):
        for r in (r for r in rows if (r["integrator"], r["strain_clamp"], r["limiter"]) == k):
            dt = float(r["dt"])
            color = "tab:green" if r["stable"] == "1" else "tab:red"
            marker = "o" if r["at_rest"] == "1" else "s"
            stab.scatter(dt, y, c=color, marker=marker, s=40)
    stab.set_xscale("log")
    stab.set_yticks(range(len(configs)), [label[k] for k in configs])
    stab.set_xlabel("time step dt (s)")
    stab.set_title("stable (green) / failed (red); circle = came to rest")
    # Colour: the stability measures; line and marker: the integrator.
    measures = sorted({(k[1], k[2]) for k in configs})
    colours = dict(zip(measures, plt.cm.tab10.colors))
    styles = {"euler": ("-", "s"), "symplectic": ("--", "^"), "heun": (":", "o")}
    for k in configs:
        # (the reference run itself deviates by 0: not drawn on a log axis)
        points = [(float(r["dt"]), 100 * float(r["mean_dev_m"]) / float(r["garment_height_m"]))
                  for r in rows if (r["integrator"], r["strain_clamp"], r["limiter"]) == k and r["stable"] == "1"
                  and float(r["mean_dev_m"]) > 0]
        if points:
            xs, ys = zip(*points)
            line, marker = styles.get(k[0], ("-", "o"))
            dev.plot(xs, ys, linestyle=line, marker=marker,
                     color=colours[(k[1], k[2])], label=label[k])
    dev.axhline(0.5, color="grey", linestyle="--", linewidth=1)
    dev.set_xscale("log")
    dev.set_yscale("log")
    dev.set_xlabel("time step dt (s)")
    dev.set_ylabel("mean deviation from reference (% of garment height)")
    dev.set_title("accuracy of stable runs (0.5 % dashed)")
    dev.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(png_path, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
