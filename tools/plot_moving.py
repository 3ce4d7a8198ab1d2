#!/usr/bin/python3
"""Plots `bench --moving`'s frame times (docs/benchmarks.md, "Moving views").

usage: tools/plot_moving.py OUT.png MOVING.csv [MOVING.csv ...]

One panel per motion and size: each moving frame's wall time drawn whole and with adaptive
resolution (the same views, drawn in turn in one run), the 16.7 ms budget, and the scale the
adaptive frame was drawn at (right axis)."""
import csv
import sys
from collections import OrderedDict

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def read_cases(paths):
    cases = OrderedDict()
    for path in paths:
        with open(path, newline="") as f:
            for row in csv.DictReader(f):
                case = cases.setdefault((row["motion"], row["size"]), {"full": [], "adaptive": [], "scale": []})
                case["full"].append(float(row["full_ms"]))
                case["adaptive"].append(float(row["adaptive_ms"]))
                case["scale"].append(float(row["scale"]))
    return cases


def main(out_path, paths):
    cases = read_cases(paths)
    fig, axes = plt.subplots(len(cases), 1, figsize=(9, 2.2 * len(cases)), constrained_layout=True, squeeze=False)
    for ax, ((motion, size), c) in zip(axes[:, 0], cases.items()):
        frames = range(len(c["full"]))
        ax.plot(frames, c["full"], label="whole", color="tab:red")
        ax.plot(frames, c["adaptive"], label="adaptive", color="tab:blue")
        ax.axhline(16.7, color="gray", linestyle="--", linewidth=0.8, label="16.7 ms budget")
        ax.set_ylabel("frame ms")
        ax.set_ylim(bottom=0)
        ax.set_title(f"{motion}, {size}", fontsize=9)
        scale = ax.twinx()
        scale.step(frames, c["scale"], where="post", color="tab:green", linewidth=0.8)
        scale.set_ylim(0, 1.05)
        scale.set_ylabel("scale", color="tab:green")
    axes[0, 0].legend(loc="upper right", fontsize=8)
    axes[-1, 0].set_xlabel("moving frame")
    fig.savefig(out_path, dpi=90)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2:])
