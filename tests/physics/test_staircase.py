#!/usr/bin/env python3
"""Staircase faces (issue 12): bodies built on a lattice whose faces are not lattice
planes (a face cut at 30 degrees, a sphere) with the surface fit of the boundary normals
(fix esph/boundary ... fit 8).

  normals  a lattice sphere (R 1 mm, lattice offset (0.3, 0.2, 0.1) dx): the boundary
           normals against the exact radial direction, first normals and fitted; the fit
           in a scene rotated as a whole by 40 degrees about (1,2,3) is the rotated fit
           (round-off), and 1, 2 and 4 ranks give the same boundary particles
  oblique  examples/oblique_rod with and without the fit: the lattice friction
           |J_t|/|J_n| of the staircase, reported (0.2 mm)
  cone     the common normal from the cones of both surfaces (pair_style ...
           contact/normal cone) with the face fitted over 16 spacings: the staircase's
           lattice friction below 0.01 at 0.25 and 0.2 mm (the mean normal: 0.05 as the
           contrast), the same scene without any staircase (examples/oblique_rod/
           in.oblique_edge: the rod's rim on a lattice-aligned face), 2 ranks = 1 rank
"""
import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("staircase faces: surface fit of the boundary normals")

SPHERE = """
variable        dx index 0.2
variable        fit index 8
variable        rot index 0
variable        h equal ${dx}*1.0e-3
units           si
atom_style      atomic
atom_modify     map array
boundary        f f f
region          box block -2e-3 2e-3 -2e-3 2e-3 -2e-3 2e-3
create_box      1 box
lattice         sc ${h} origin 0.3 0.2 0.1
region          s sphere 0 0 0 1.0e-3 units box
create_atoms    1 region s
pair_style      esph/solid ${h}
pair_coeff      * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
set             group all mass $(7850*v_h^3)
if "${rot} == 1" then "displace_atoms all rotate 0 0 0 1 2 3 40 units box"
fix             bnd all esph/boundary spacing ${h} fit ${fit}
variable        b atom mass==0.0
group           b variable b
write_dump      b custom ${out} id x y z d2_esph_n[1] d2_esph_n[2] d2_esph_n[3] modify format float %.17g
"""
sphere_in = et.write_input(a, "in.sphere", SPHERE)


def load(path):
    lines = open(path).read().splitlines()
    k = [i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")][0]
    d = np.array([[float(v) for v in l.split()] for l in lines[k + 1:] if l.strip()])
    return d[np.argsort(d[:, 0])]


def sphere(np_=1, **var):
    out = os.path.join(a.workdir, "sphere_{}.dump".format("_".join(
        f"{k}{v}" for k, v in sorted(var.items())) + f"_np{np_}"))
    et.run(a, sphere_in, dict(var, out=out), np=np_, log="log.sphere")
    return load(out)


def radial_rms(d):
    x, n = d[:, 1:4], d[:, 4:7]
    r = x / np.linalg.norm(x, axis=1)[:, None]
    ang = np.degrees(np.arccos(np.clip((n * r).sum(1), -1.0, 1.0)))
    return np.sqrt((ang ** 2).mean()), ang.max()


# ---------- 1. normals of a lattice sphere ----------
for dx, bound in ((0.2, 7.0), (0.1, 3.0)):
    rms0, max0 = radial_rms(sphere(dx=dx, fit=0))
    d8 = sphere(dx=dx, fit=8)
    rms8, max8 = radial_rms(d8)
    print(f"INFO sphere dx {dx}: {len(d8)} boundary particles; angle to radial rms "
          f"{rms0:.2f} (max {max0:.1f}) degrees first, {rms8:.2f} (max {max8:.1f}) fitted")
    c.less(f"sphere dx {dx}: fitted normals, rms angle to radial [deg]", rms8, bound,
           f"measured 5.7 at R/dx 5 and 2.0 at 10 (first normals 12.6 and 13.5): the fit "
           "sees the sphere, not the steps; bound 1.2-1.5x measured")
    c.less(f"sphere dx {dx}: fit better than first normals by 2x", rms8, 0.5 * rms0,
           "the point of the fit")

d = sphere(dx=0.2, fit=8)
dr = sphere(dx=0.2, fit=8, rot=1)
ax = np.array([1.0, 2.0, 3.0]) / np.sqrt(14.0)
th = np.radians(40.0)
K = np.array([[0, -ax[2], ax[1]], [ax[2], 0, -ax[0]], [-ax[1], ax[0], 0]])
R = np.eye(3) + np.sin(th) * K + (1 - np.cos(th)) * K @ K
c.true("rotated scene: same boundary particles", len(d) == len(dr), "one per surface particle")
if len(d) == len(dr):
    dn = np.abs(d[:, 4:7] @ R.T - dr[:, 4:7]).max()
    c.less("rotated scene: |R n - n_rotated|", dn, 1e-12,
           "the fit is a continuous function of the particles (inverse iteration, no "
           "eigenvector choice): round-off, measured 2.5e-15")


def by_position(d):
    return d[np.lexsort(np.round(d[:, 1:4] * 1e7).T)]


for np_ in (2, 4):
    dp = sphere(np_=np_, dx=0.2, fit=8)
    same = len(dp) == len(d)
    c.true(f"np {np_}: same number of boundary particles", same, "distributed generation")
    if same:
        diff = np.abs(by_position(d)[:, 1:7] - by_position(dp)[:, 1:7]).max()
        c.less(f"np {np_}: positions and fitted normals against np 1", diff, 1e-13,
               "sums in the fixed order of the integer cell grid and of atom IDs; the halo "
               "of fit spacings brings every rank the same neighbours (measured 0 / 1.3e-15)")

# ---------- 2. oblique rod on a 30 degree staircase face (reported) ----------
# The lattice friction |J_t|/|J_n| with fit 8 is reported, not asserted: with the common
# normal's weight |n|^8 the rod's rim still tilts it (doc/hard_cases.md 4: 0.05 at 0.2 mm;
# 0.003 with |n|^64, not shipped)
OBL = "oblique_rod/in.oblique_rod"
for fit, smooth in ((8, 1.0), (0, 1.5)):
    s = et.summary(et.run(a, OBL, {"dx": 0.2, "fit": fit, "smooth": smooth},
                          log=f"log.oblique_fit{fit}"), "OBLIQUE_ROD")
    print(f"INFO oblique rod dx 0.2, fit {fit}, smooth {smooth}: {s}")
    c.less(f"oblique rod fit {fit}: momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")

# ---------- 3. the cone rule of the common normal ----------
# The mean normal lets the rod's rim (an edge) tilt the contact force; the cone rule takes
# the direction both surfaces admit (doc/pair_esph_solid.rst, "Normal cones"). The bound
# 0.01 is issue 12's; measured on this machine (fit 16, smooth 1): 0.0030 / 0.0047 at
# 0.25 / 0.2 mm (0.0025 at 0.15 mm, not run here), with the mean normal 0.049 / 0.047.
FIT = {"fit": 16, "smooth": 1.0}
cone = {}
for dx in (0.25, 0.2):
    for normal in ("cone", "mean"):
        s = et.summary(et.run(a, OBL, dict(FIT, dx=dx, normal=normal),
                              log=f"log.oblique_{normal}_{dx}"), "OBLIQUE_ROD")
        print(f"INFO oblique rod dx {dx}, fit 16, contact/normal {normal}: {s}")
        if normal == "cone":
            cone[dx] = s
            c.less(f"staircase dx {dx}, cone: lattice friction |J_t|/|J_n|", s["mu_eff"], 0.01,
                   "issue 12: frictionless on a staircase face (exact 0); measured "
                   "0.0030 / 0.0047 at 0.25 / 0.2 mm (2026-12-05)")
            c.less(f"staircase dx {dx}, cone: momentum drift", s["momentum_drift_rel"], 1e-12,
                   "pairwise forces")
            c.less(f"staircase dx {dx}, cone: energy drift [%]", abs(s["energy_drift_pct"]), 0.5,
                   "REFERENCES 7")
            c.true(f"staircase dx {dx}, cone: at most 2 contact episodes", s["episodes"] <= 2,
                   "hit and rebound, plus the precursor touch of the rim's lattice step")
        else:
            c.less(f"staircase dx {dx}, mean normal (contrast): lattice friction > 0.03", -s["mu_eff"],
                   -0.03, "measured 0.049 / 0.047: the rim tilts the mean normal")

# the rod's rim on a face without any staircase (each body on a lattice of its own): the
# edge against a face alone; 0.2 mm (at 0.25 mm, four particles per rod radius, 0.016)
EDGE = "oblique_rod/in.oblique_edge"
for normal, bound, why in (("cone", 0.01, "measured 0.0035"),
                           ("mean", None, "measured 0.052")):
    s = et.summary(et.run(a, EDGE, {"dx": 0.2, "normal": normal}, log=f"log.edge_{normal}"),
                   "OBLIQUE_ROD")
    print(f"INFO rim on an aligned face dx 0.2, contact/normal {normal}: {s}")
    if bound:
        c.less("rim on an aligned face, cone: |J_t|/|J_n|", s["mu_eff"], bound,
               f"frictionless: exact 0; {why}")
        c.less("rim on an aligned face, cone: momentum drift", s["momentum_drift_rel"], 1e-12,
               "pairwise forces")
    else:
        c.less("rim on an aligned face, mean normal (contrast): |J_t|/|J_n| > 0.03", -s["mu_eff"],
               -0.03, why + ": the rim tilts the mean normal")

# 2 ranks: the cones are sums over boundary particles (reverse communicated) and a
# continuous function of them: the same run to round-off (thermo every 50 steps, 15 digits)
logs = {}
for np_ in (1, 2):
    logs[np_] = et.production_thermo(et.run(a, OBL, dict(FIT, dx=0.25, normal="cone"), np=np_,
                                            log=f"log.oblique_cone_np{np_}"))
worst, col = et.worst_difference(logs[1], logs[2])
c.less(f"staircase dx 0.25, cone: np 2 vs np 1 thermo (worst column {col})", worst, 1e-10,
       "summation order only")
c.done()
