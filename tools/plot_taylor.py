#!/usr/bin/python3
"""Final shape of the Taylor bar (examples/taylor_bar -var out 1): the particles of the
bar seen from the side (x, r = sqrt(y^2 + z^2)), coloured by the equivalent plastic
strain, with the reference impact-face radius 7.11-7.22 mm and length 21.42-21.48 mm.
  plot_taylor.py out.png taylor_final.dump [more dumps ...] [--labels ...]"""
import argparse

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_final(path):
    with open(path) as fh:
        lines = fh.read().split("\n")
    cols = lines[8].split()[2:]
    data = np.array([[float(w) for w in line.split()] for line in lines[9:] if line.strip()])
    return {c: data[:, k] for k, c in enumerate(cols)}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("png")
    ap.add_argument("dumps", nargs="+")
    ap.add_argument("--labels", nargs="+")
    a = ap.parse_args()
    fig, axes = plt.subplots(len(a.dumps), 1, figsize=(7, 2.4 * len(a.dumps)), squeeze=False)
    for k, path in enumerate(a.dumps):
        d = read_final(path)
        ax = axes[k][0]
        x = -d["x"] * 1e3
        r = np.hypot(d["y"], d["z"]) * 1e3
        sc = ax.scatter(x, r, c=d["c_ep"], s=2, cmap="viridis", vmin=0, vmax=2.5, lw=0)
        ax.axhspan(7.11, 7.22, color="r", alpha=0.3, lw=0)
        ax.axvspan(21.42, 21.48, color="r", alpha=0.3, lw=0)
        ax.set_xlim(0, 34)
        ax.set_ylim(0, 10)
        ax.set_aspect("equal")
        ax.set_xlabel("distance from the wall [mm]")
        ax.set_ylabel("r [mm]")
        if a.labels:
            ax.set_title(a.labels[k], fontsize=9)
        fig.colorbar(sc, ax=ax, label="plastic strain")
    fig.tight_layout()
    fig.savefig(a.png, dpi=130)


if __name__ == "__main__":
    main()
