#!/usr/bin/python3
"""Renders a wash CSV state (a --dump file or a CSV frame) of a 2D run as a PNG.

usage: render.py STATE.csv OUT.png [--color FIELD] [--box WIDTH HEIGHT] [--title TEXT]

Particles are drawn at x,y (or at the vector force given by --at, e.g. position),
coloured by FIELD (a scalar column, or a vector column name for its magnitude;
default: speed from vx,vy). Needs Debian's python3-matplotlib and python3-numpy.
"""
import argparse
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def column(data, name):
    names = data.dtype.names
    if name in names:
        return data[name]
    parts = [f"{name}_{a}" for a in "xyz" if f"{name}_{a}" in names]
    if name == "speed":
        parts = [p for p in ("vx", "vy", "vz") if p in names]
    if not parts:
        sys.exit(f"render.py: error: no column '{name}' (have: {', '.join(names)})")
    return np.sqrt(sum(data[p] ** 2 for p in parts))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("state")
    parser.add_argument("png")
    parser.add_argument("--color", default="speed")
    parser.add_argument("--at", default="", help="vector force to use as position")
    parser.add_argument("--box", nargs=2, type=float, metavar=("WIDTH", "HEIGHT"))
    parser.add_argument("--title", default="")
    args = parser.parse_args()

    data = np.genfromtxt(args.state, delimiter=",", names=True)
    xs, ys = ("x", "y") if not args.at else (f"{args.at}_x", f"{args.at}_y")
    values = column(data, args.color)

    fig, ax = plt.subplots(figsize=(9, 5.2), dpi=110)
    points = ax.scatter(data[xs], data[ys], c=values, s=6, cmap="viridis", linewidths=0)
    fig.colorbar(points, ax=ax, label=args.color, shrink=0.85)
    if args.box:
        w, h = args.box
        ax.add_patch(plt.Rectangle((-w / 2, -h / 2), w, h, fill=False, color="0.3", lw=1.2))
        ax.set_xlim(-w / 2 - 0.3, w / 2 + 0.3)
        ax.set_ylim(-h / 2 - 0.3, h / 2 + 0.3)
    ax.set_aspect("equal")
    ax.set_title(args.title or f"{args.state}: {len(data)} particles")
    fig.tight_layout()
    fig.savefig(args.png)


if __name__ == "__main__":
    main()
