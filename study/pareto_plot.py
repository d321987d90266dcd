#!/usr/bin/python3
"""Draws the Pareto plots of a `quadshade study`: for each POINTS/CASE.csv (mode, group, ms,
rms_vs_truth, front), PLOTS/CASE.png, the RMS error against the truth over the time per frame,
log-log, one point per mode, the Pareto front (which `quadshade study` marks) drawn through its
points. Exits 3, saying why, where matplotlib (Debian's python3-matplotlib) is not installed.

usage: pareto_plot.py POINTS PLOTS
"""
import csv
import glob
import os
import sys

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
except ImportError:
    print("matplotlib is not installed (Debian: python3-matplotlib)")
    sys.exit(3)

GROUP_MARKERS = {"derivatives": "o", "anti-aliasing": "s", "precision": "^"}
FLOOR = 1e-6  # an exact mode, drawn on the log axis


LABEL_POINTS = 7


def label(ax, rows):
    """Names each point beside it; a name that would cover one already placed (modes of the same
    cost and error, e.g. two derivative rules) moves down below it instead."""
    placed = []  # (x0, x1, y0, y1) in pixels
    height = LABEL_POINTS * ax.figure.dpi / 72 * 1.25
    for r in sorted(rows, key=lambda r: -max(float(r["rms_vs_truth"]), FLOOR)):
        x, y = float(r["ms"]), max(float(r["rms_vs_truth"]), FLOOR)
        px, py = ax.transData.transform((x, y))
        width = 0.62 * len(r["mode"]) * height
        dy = 3
        while any(px < b[1] and px + width > b[0] and py + dy < b[3] and py + dy + height > b[2] for b in placed):
            dy -= height
        placed.append((px, px + width, py + dy, py + dy + height))
        ax.annotate(r["mode"], (x, y), textcoords="offset pixels", xytext=(4, dy), fontsize=LABEL_POINTS)


def plot(title, rows, path):
    fig, ax = plt.subplots(figsize=(7.5, 4.8), dpi=100)
    for r in rows:
        on_front = r["front"] == "1"
        x, y = float(r["ms"]), max(float(r["rms_vs_truth"]), FLOOR)
        ax.scatter(x, y, marker=GROUP_MARKERS.get(r["group"], "o"), s=60 if on_front else 30,
                   facecolors="tab:red" if on_front else "none", edgecolors="tab:red" if on_front else "tab:blue")
    front = sorted((r for r in rows if r["front"] == "1"), key=lambda r: float(r["ms"]))
    ax.plot([float(r["ms"]) for r in front], [max(float(r["rms_vs_truth"]), FLOOR) for r in front], color="tab:red",
            lw=1, label="Pareto front")
    for group, marker in GROUP_MARKERS.items():
        ax.scatter([], [], marker=marker, facecolors="none", edgecolors="k", label=group)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("time per frame (ms, median)")
    ax.set_ylabel("RMS error against the truth")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    label(ax, rows)  # placed in pixels, once the axes have their final size
    fig.savefig(path)
    plt.close(fig)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    for path in sorted(glob.glob(os.path.join(sys.argv[1], "*.csv"))):
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
        if rows:
            name = os.path.splitext(os.path.basename(path))[0]
            plot(rows[0]["case"], rows, os.path.join(sys.argv[2], name + ".png"))


if __name__ == "__main__":
    main()
