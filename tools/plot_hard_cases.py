#!/usr/bin/python3
"""Pictures of the hard cases (doc/hard_cases.md): runs the examples in a scratch copy
of examples/ with the given lmp and draws
  hard_1d.png : mean rod velocities against time (unequal rods, dissimilar rods both
                ways, 500 m/s, initial gap, 1D, 0.1 mm), the plasticity two-wave
                profile (0.05 mm) and the free bar's energies over 10^5 steps
  hard_3d.png : before/after snapshots (v_x colour) of the off-axis rods, the oblique
                rod on a block and the spinning block (coarse 3D)
  plot_hard_cases.py --lmp build/lmp --out doc/figures   (about 6 minutes on 1 core)"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from plot_rod_impact import read_profiles  # noqa: E402


def run(lmp, work, infile, var):
    cwd = os.path.join(work, os.path.dirname(infile))
    cmd = [lmp, "-in", os.path.basename(infile), "-log", "log.lammps", "-screen", "none"]
    for k, v in var.items():
        cmd += ["-var", k, str(v)]
    subprocess.run(cmd, cwd=cwd, check=True)
    return cwd


def history(path):
    """fix ave/time file of rod_impact: columns step, t [us], v_imp, v_tgt, pairs"""
    return np.loadtxt(path, comments="#")


def thermo(logpath):
    cols, rows = None, []
    for line in open(logpath):
        w = line.split()
        if w[:1] == ["Step"]:
            cols, rows = w, []
        elif cols and len(w) == len(cols):
            try:
                rows.append([float(x) for x in w])
            except ValueError:
                pass
    return cols, np.array(rows)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--lmp", required=True)
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    lmp = os.path.abspath(a.lmp)
    os.makedirs(a.out, exist_ok=True)
    work = tempfile.mkdtemp(prefix="esph_hard_")
    shutil.copytree(os.path.join(os.path.dirname(HERE), "examples"), work, dirs_exist_ok=True,
                    ignore=shutil.ignore_patterns("log.*"))

    fig, ax = plt.subplots(2, 3, figsize=(13, 7))
    # velocity histories of the 1D rod cases
    panels = [
        (ax[0][0], "unequal_rods/in.unequal_rods", {"mat_imp": "iron"},
         "unequal rods: 10 mm on 20 mm\nbar theory: striker 0, target 25 m/s", [0.0, 25.0]),
        (ax[0][1], "dissimilar_rods/in.dissimilar_rods", {"mat_imp": "aluminum", "mat_tgt": "iron"},
         "aluminum on iron\ninterface velocity 15.03 m/s (theory)", [15.03]),
        (ax[0][2], "dissimilar_rods/in.dissimilar_rods", {"mat_imp": "iron", "mat_tgt": "aluminum"},
         "iron on aluminum\ninterface velocity 34.97 m/s (theory)", [34.97]),
        (ax[1][0], "fast_impact/in.fast_impact", {"V": 500},
         "500 m/s (elastic model)", []),
    ]
    for axis, infile, var, title, refs in panels:
        cwd = run(lmp, work, infile, dict(var, dim=1, dx=0.1, tend=14, out=1))
        h = history(os.path.join(cwd, "velocity.solid.1d.txt"))
        axis.plot(h[:, 1], h[:, 2], label="impactor")
        axis.plot(h[:, 1], h[:, 3], label="target")
        for r in refs:
            axis.axhline(r, color="k", lw=0.6, ls=":")
        axis.set_title(title, fontsize=9)
        axis.set_xlabel("t [us]")
        axis.set_ylabel("mean v_x [m/s]")
        axis.legend(fontsize=8)
    # initial gaps: the same history shifted by gap / V
    for gap in (0.0, 0.5, 2.0):
        cwd = run(lmp, work, "rod_impact/in.rod_impact",
                  {"dim": 1, "dx": 0.1, "gap": gap, "tend": 14, "out": 1})
        h = history(os.path.join(cwd, "velocity.solid.1d.txt"))
        shift = gap * 0.1e-3 / 50.0 * 1e6
        ax[1][1].plot(h[:, 1] - shift, h[:, 3], label=f"gap {gap} dx (shifted by gap/V)")
    ax[1][1].set_title("initial gaps: target velocity, 1D", fontsize=9)
    ax[1][1].set_xlabel("t - gap/V [us]")
    ax[1][1].legend(fontsize=8)
    # plasticity: velocity profile at 3 us, two waves
    cwd = run(lmp, work, "rod_impact/in.rod_impact",
              {"dim": 1, "dx": 0.05, "yield": 0.5e9, "tend": 3, "out": 1})
    blocks = read_profiles(os.path.join(cwd, "profile.solid.1d.txt"))
    prof = blocks[sorted(blocks)[-1]]
    ax[1][2].plot(prof[:, 0], prof[:, 1], label="Y = 0.5 GPa, 3 us")
    ax[1][2].axhline(16.05, color="k", lw=0.6, ls=":", label="HEL c_p Y / 2G = 16.05 m/s")
    ax[1][2].axhline(25.0, color="k", lw=0.6, ls="--", label="V/2")
    ax[1][2].set_title("plasticity, 1D: elastic precursor + plastic wave", fontsize=9)
    ax[1][2].set_xlabel("x [mm]")
    ax[1][2].set_ylabel("v_x [m/s]")
    ax[1][2].set_xlim(-2, 22)
    ax[1][2].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "hard_1d.png"), dpi=110)

    # free bar: energies over 10^5 steps
    cwd = run(lmp, work, "free_bar/in.free_bar", {"nsteps": 100000})
    cols, d = thermo(os.path.join(cwd, "log.lammps"))
    f2, b = plt.subplots(figsize=(6, 3.2))
    for c in ("KinEng", "PotEng", "TotEng"):
        b.plot(d[:, cols.index("v_tus")], d[:, cols.index(c)], label=c)
    b.set_xlabel("t [us]")
    b.set_ylabel("energy [J per m^2]")
    b.set_title("free bar, 10^5 steps: vibration -> heat, total conserved", fontsize=9)
    b.legend(fontsize=8)
    f2.tight_layout()
    f2.savefig(os.path.join(a.out, "hard_free_bar.png"), dpi=110)

    # 3D snapshots
    cases = [("offaxis_rods/in.offaxis_rods", {"dx": 0.25, "tend": 12, "out": 0, "images": 1},
              ("before.solid.png", "after.solid.png"), "off-axis rods (R/2 offset), 0.25 mm"),
             ("oblique_rod/in.oblique_rod", {"dx": 0.25, "images": 1},
              ("before.png", "after.png"), "rod on a block at 30 degrees, 0.25 mm"),
             ("spinning_block/in.spinning_block", {"dx": 0.2, "images": 1},
              ("before.png", "after.png"), "spinning block into a block, 0.2 mm")]
    f3, c3 = plt.subplots(len(cases), 2, figsize=(10, 3.2 * len(cases)))
    for k, (infile, var, pngs, title) in enumerate(cases):
        cwd = run(lmp, work, infile, var)
        for j, png in enumerate(pngs):
            c3[k][j].imshow(plt.imread(os.path.join(cwd, png)))
            c3[k][j].set_axis_off()
            c3[k][j].set_title(f"{title}: {'before' if j == 0 else 'after'} (colour v_x)",
                               fontsize=8)
    f3.tight_layout()
    f3.savefig(os.path.join(a.out, "hard_3d.png"), dpi=110)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
