#!/usr/bin/python3
"""The README's wind figures (paper §2, Figure 2.2) from a figment-view wind run.

    build/bin/figment-view scenes/wind.iv -o build/wind/wind.png --size 240x280 \\
        --frames 0.5:4.4:40 --wind-force docs/wind-force.csv
    /usr/bin/python3 scripts/wind-figures.py --frames 'build/wind/wind-*.png' \\
        --csv docs/wind-force.csv --gif docs/images/wind.gif --chart docs/images/wind-force.png

The GIF plays the frames in name order (figment-view numbers them so they sort) at
--fps, looping; the chart shows the wind pressure p(t) with the moments its phase jumped,
and the total wind force on the garment (its magnitude, and its component along the
wind, which carries the sign of p). Pillow and matplotlib (Debian: python3-matplotlib);
each output is written to a temporary name and renamed, so it exists only when whole.
"""

import argparse
import csv
import glob
import os
import sys
import tempfile


def write_atomically(path, write):
    """Calls write(temporary_path) and renames the result to path."""
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, prefix=".", suffix=os.path.splitext(path)[1])
    os.close(handle)
    umask = os.umask(0)
    os.umask(umask)
    os.chmod(temporary, 0o666 & ~umask)  # as a plain open() would make it, not mkstemp's 0600
    try:
        write(temporary)
        os.replace(temporary, path)
    except BaseException:
        os.unlink(temporary)
        raise


def make_gif(frame_pattern, gif, fps, colours):
    from PIL import Image

    names = sorted(glob.glob(frame_pattern))
    if not names:
        sys.exit(f"wind-figures: {frame_pattern}: no frames")
    # One palette for all frames (the first's), so the background does not flicker.
    first = Image.open(names[0]).convert("RGB").quantize(colors=colours, method=Image.Quantize.MEDIANCUT)
    frames = [first] + [Image.open(n).convert("RGB").quantize(palette=first, dither=Image.Dither.NONE)
                        for n in names[1:]]
    write_atomically(gif, lambda path: first.save(
        path, format="GIF", save_all=True, append_images=frames[1:], duration=round(1000 / fps), loop=0,
        optimize=True))
    print(f"{gif}: {len(frames)} frames, {os.path.getsize(gif) / 1024:.0f} KiB")


def read_wind(path):
    rows = list(csv.DictReader(open(path)))
    if not rows:
        sys.exit(f"wind-figures: {path}: no wind samples (does the scene's wind blow?)")
    engine = rows[0]["engine"]  # the first garment's
    rows = [r for r in rows if r["engine"] == engine]
    column = lambda name: [float(r[name]) for r in rows]
    return engine, column


def make_chart(csv_path, chart, direction_label):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    engine, column = read_wind(csv_path)
    t, p, phase, force = column("time_s"), column("pressure_Pa"), column("phase_rad"), column("force_N")
    fx, fy, fz = column("force_x_N"), column("force_y_N"), column("force_z_N")
    # The component along the wind (the force is parallel to it, signed as p).
    along = [f if pv >= 0 else -f for f, pv in zip(force, p)]
    jumps = [t[i] for i in range(1, len(t)) if phase[i] != phase[i - 1]]

    fig, (top, bottom) = plt.subplots(2, 1, figsize=(7.0, 4.6), sharex=True, dpi=100)
    top.plot(t, p, color="#1f5f8b", linewidth=1.4)
    for j in jumps:
        top.axvline(j, color="#c0392b", linestyle=":", linewidth=1.0)
    top.axhline(0.0, color="0.6", linewidth=0.6)
    top.set_ylabel("pressure p(t), Pa")
    top.set_title(f"Wind on the skirt ({engine}): p(t) = a sin(2\u03c0ft + \u03c6(t)), "
                  "\u03c6 jumping at random moments (dotted)", fontsize=9)
    bottom.plot(t, force, color="#1f5f8b", linewidth=1.4, label="|F|, total wind force")
    bottom.plot(t, along, color="#7f8c8d", linewidth=0.9, linestyle="--", label=f"F along the wind ({direction_label})")
    bottom.axhline(0.0, color="0.6", linewidth=0.6)
    bottom.set_xlabel("simulated time, s")
    bottom.set_ylabel("force, N")
    bottom.legend(loc="lower right", fontsize=8, framealpha=0.9)
    fig.tight_layout()
    write_atomically(chart, lambda path: fig.savefig(path, format="png"))
    print(f"{chart}: {len(t)} samples, {len(jumps)} phase changes, |F| up to {max(force):.2f} N")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--frames", help="the frames' PNG files, a glob pattern (quoted)")
    parser.add_argument("--gif", help="animated GIF to write from the frames")
    parser.add_argument("--fps", type=float, default=10.0, help="frames a second in the GIF (default 10)")
    parser.add_argument("--colours", type=int, default=64, help="the GIF's palette size (default 64)")
    parser.add_argument("--csv", help="figment-view --wind-force output")
    parser.add_argument("--chart", help="PNG chart to write from the CSV")
    parser.add_argument("--direction", default="+x", help="how the chart names the wind's direction")
    args = parser.parse_args()
    if bool(args.frames) != bool(args.gif) or bool(args.csv) != bool(args.chart) or not (args.gif or args.chart):
        parser.error("give --frames with --gif, --csv with --chart, or both pairs")
    if args.gif:
        make_gif(args.frames, args.gif, args.fps, args.colours)
    if args.chart:
        make_chart(args.csv, args.chart, args.direction)


if __name__ == "__main__":
    main()
