#!/usr/bin/python3
"""Snapshots of the colliding-rings example (examples/colliding_rings): one row per
dump file, one column per chosen frame.
  plot_rings.py out.png rings_off_0.dump rings_off_0.3.dump ... [--frames 0 3 6 9]"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read_dump(path):
    """list of (timestep, [(x, y), ...]) frames of a LAMMPS text dump with x y columns"""
    frames = []
    with open(path) as fh:
        lines = fh.read().split("\n")
    i = 0
    while i < len(lines):
        if lines[i].startswith("ITEM: TIMESTEP"):
            step = int(lines[i + 1])
            n = int(lines[i + 3])
            cols = lines[i + 8].split()[2:]
            ix, iy = cols.index("x"), cols.index("y")
            pts = []
            for line in lines[i + 9:i + 9 + n]:
                w = line.split()
                pts.append((float(w[ix]), float(w[iy])))
            frames.append((step, pts))
            i += 9 + n
        else:
            i += 1
    return frames


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("dumps", nargs="+")
    ap.add_argument("--frames", type=int, nargs="+", default=[0, 2, 4, 6, 8])
    ap.add_argument("--labels", nargs="+")
    ap.add_argument("--dt-us", type=float, default=None, help="time per dump step [us]")
    a = ap.parse_args()
    data = [read_dump(p) for p in a.dumps]
    nr, nc = len(data), len(a.frames)
    fig, axes = plt.subplots(nr, nc, figsize=(2.6 * nc, 1.5 * nr + 0.3), squeeze=False)
    for r, frames in enumerate(data):
        for c, k in enumerate(a.frames):
            ax = axes[r][c]
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_xlim(-0.11, 0.11)
            ax.set_ylim(-0.055, 0.055)
            if k >= len(frames):
                ax.text(0.5, 0.5, "(stopped)", ha="center", transform=ax.transAxes)
                continue
            step, pts = frames[k]
            ax.scatter([p[0] for p in pts], [p[1] for p in pts], s=0.05, c="k", lw=0)
            if r == 0:
                ax.set_title(f"step {step}", fontsize=8)
        if a.labels:
            axes[r][0].set_ylabel(a.labels[r], fontsize=7)
    fig.tight_layout()
    fig.savefig(a.png, dpi=150)


if __name__ == "__main__":
    main()
