#!/usr/bin/env python3
"""Fig. 4/5-style plots of the rod impact (examples/rod_impact) with and without contact,
against bar theory (and the 3D elastic reference of shared/REFERENCES.md 1(d)).

usage: plot_rod_impact.py --contact DIR_WITH_CONTACT --nocontact DIR_WITHOUT --out DOCDIR
       [--dim 3]
Each DIR holds the profile.<rule>.<dim>d.txt and velocity.<rule>.<dim>d.txt files that
in.rod_impact writes. Writes rod_profiles.png (Fig. 4) and rod_velocity.png (Fig. 5)."""
import argparse
import glob
import os

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

L, V = 20.0, 50.0                 # mm, m/s
C_BAR = 4914.6                     # m/s, sqrt(E/rho0)
C_P = 5134.4                       # m/s, uniaxial strain


def read_profiles(path):
    """blocks of a fix ave/chunk profile file: {timestep: array of (x [mm], v_x)}"""
    blocks, cur = {}, None
    for line in open(path):
        if line.startswith("#"):
            continue
        p = line.split()
        if len(p) == 3:
            cur = int(p[0])
            blocks[cur] = []
        elif len(p) == 4 and float(p[2]) > 0:
            blocks[cur].append((float(p[1]) * 1e3, float(p[3])))
    return {k: np.array(v) for k, v in blocks.items()}


def theory_profile(t_us, c):
    """piecewise bar-theory particle velocity along X in [-L, L] (mm) at time t"""
    x = np.linspace(-L, L, 2001)
    ct = c * t_us * 1e-3           # mm
    T = L / ct * t_us if ct > 0 else np.inf
    v = np.where(x < 0, V, 0.0)
    tc = 2 * L / (c * 1e-3)
    if t_us <= 0:
        return x, v
    if t_us >= tc:
        return x, np.where(x < 0, 0.0, V)
    if ct <= L:
        v = np.where(np.abs(x) < ct, V / 2, v)
    else:
        d = ct - L
        v = np.where(x < 0, np.where(x < -L + d, 0.0, V / 2), np.where(x < L - d, V / 2, V))
    return x, v


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--contact", required=True)
    p.add_argument("--nocontact", required=True)
    p.add_argument("--out", required=True)
    p.add_argument("--dim", default="3")
    a = p.parse_args()
    os.makedirs(a.out, exist_ok=True)
    c_theory = C_BAR if a.dim == "3" else C_P
    label_theory = "bar theory" if a.dim == "3" else "uniaxial strain theory"

    pc = read_profiles(glob.glob(os.path.join(a.contact, f"profile.*.{a.dim}d.txt"))[0])
    pn = read_profiles(glob.glob(os.path.join(a.nocontact, f"profile.off.{a.dim}d.txt"))[0])
    pc = [pc[k] for k in sorted(pc)]
    pn = [pn[k] for k in sorted(pn)]
    times = [0, 3, 6, 9, 12]
    fig, axes = plt.subplots(len(times), 1, figsize=(8, 11), sharex=True)
    for k, (ax, t) in enumerate(zip(axes, times)):
        if k < len(pn):
            ax.plot(pn[k][:, 0], pn[k][:, 1], "-", color="tab:red", lw=1.2, label="without contact")
        if k < len(pc):
            ax.plot(pc[k][:, 0], pc[k][:, 1], ".", color="tab:blue", ms=3, label="with contact")
        x, v = theory_profile(t, c_theory)
        ax.plot(x, v, "k--", lw=0.8, label=label_theory)
        ax.set_ylabel("v [m/s]")
        ax.set_ylim(-15, 65)
        ax.text(0.01, 0.85, f"({'abcde'[k]}) {t} us", transform=ax.transAxes)
    axes[0].legend(loc="upper right", fontsize=8)
    axes[-1].set_xlabel("x [mm] (contact surface at 0)")
    fig.suptitle("Particle velocity along the rods (cf. Min et al. 2000, Fig. 4)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, f"rod_profiles_{a.dim}d.png"), dpi=110)

    fig, ax = plt.subplots(figsize=(8, 5))
    for d, style, name in ((a.contact, "-", "with contact"), (a.nocontact, "--", "without contact")):
        f = glob.glob(os.path.join(d, f"velocity.*.{a.dim}d.txt"))
        if "without" in name:
            f = glob.glob(os.path.join(d, f"velocity.off.{a.dim}d.txt"))
        data = np.loadtxt(f[0], comments="#")
        ax.plot(data[:, 1], data[:, 2], style, color="tab:blue", label=f"impactor, {name}")
        ax.plot(data[:, 1], data[:, 3], style, color="tab:orange", label=f"target, {name}")
    tc = 2 * L / (c_theory * 1e-3)
    t = np.linspace(0, 16, 400)
    vimp = np.where(t < tc, V * (1 - t / tc), 0.0)
    ax.plot(t, vimp, "k:", lw=1, label=f"{label_theory} (t_c = {tc:.3f} us)")
    ax.plot(t, V - vimp, "k:", lw=1)
    if a.dim == "3":
        ax.plot([8.23, 16], [0.63, 0.63], "g-", lw=3, alpha=0.4, label="3D elastic: 0.63 / 49.37 m/s after 8.23 us")
        ax.plot([8.23, 16], [49.37, 49.37], "g-", lw=3, alpha=0.4)
    ax.set_xlabel("t [us]")
    ax.set_ylabel("mean rod velocity [m/s]")
    ax.legend(fontsize=8)
    ax.set_title("Mean velocities of the rods (cf. Min et al. 2000, Fig. 5)")
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, f"rod_velocity_{a.dim}d.png"), dpi=110)


if __name__ == "__main__":
    main()
