#!/usr/bin/env python3
"""Two iron cylinders side on (tests/physics/in.lattice_cylinders: R = 1 and 3 mm, 2 mm
long, axes along z, 25 m/s each, 0.2 mm: R/dx = 5 and 15) built on one cubic lattice
offset by (0.3, 0.2, 0.1) spacings: staircase sides, and rims where the sides meet the flat
caps. Exact frictionless contact: the force along the line of centres, no momentum in y or
z (issue 12: a touch test that holds on faces, edges and corners).
- the normals of the regions the cylinders were cut from (fix esph/boundary region): at the
  rims (a real particle within a spacing of the side and a cap) the generated normals are
  kept, refined by fit 8. Before that rule the rims' boundary particles took the caps'
  normal, and the cylinders interacted from the first step, across a gap of one spacing,
  and left with an axial (z) momentum of 4.5e-2 of the impact momentum (R/dx = 5);
- at R/dx = 15 the regions' normals against the generated ones (lateral momentum 2.0e-5
  against 2.9e-3; 5.5e-4 against 2.8e-3 with contact/gap projection) and np 2 against np 1;
- fit 8 alone (the surface fit of the generated normals) on a cylinder, reported: 1.3e-2;
- in 2d the region's z faces bound the plane, not the bodies: a disc (a cylinder region
  along z) takes the radial normals, only a block's corners keep their own (before, every
  boundary particle of a 2d body counted as at an edge and kept its own normal), and a z
  face never gives a normal;
- a region with side out (a spherical hole) named on its own gives the bore's normals
  pointing to the hole's centre, out of the body (they pointed into it).
About 1.5 minutes."""
import os
import re

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("lattice cylinders side on")
INP = et.source_input(a, "in.lattice_cylinders")
REG = "region s1 region s2"


def case(name, np=1, **var):
    s = et.summary(et.run(a, INP, var, np=np, log=f"log.{name}"), "CYLINDERS")
    print(f"INFO {name}: {s}")
    return s


# the regions' surfaces start one spacing (0.2 mm) apart and close at 50 m/s: they meet at
# 4.0 us. No pair may interact while they are more than 0.3 spacings apart: the lattice's
# staircase stands out of the region's surface by up to that at R/dx = 5 (its corners)
T_MEET = 0.2e-3 / 50.0 * 1e6
T_EARLIEST = 0.7 * T_MEET
# the regions' normals, and at the rims the generated ones refined by a surface fit (fit 8;
# without it the rims keep the staircase's first normals)
REGFIT = dict(bextra=REG, fit=8)

for R, tend in ((1.0, 10.0), (3.0, 14.0)):
    lab = f"R/dx = {R / 0.2:.0f}"
    reg = case(f"region_fit8_R{R:g}", R=R, tend=tend, **REGFIT)
    reg0 = case(f"region_R{R:g}", R=R, tend=tend, bextra=REG)
    gen = case(f"generated_R{R:g}", R=R, tend=tend)
    for name, s in (("regions' normals, fit 8", reg), ("regions' normals", reg0),
                    ("generated normals", gen)):
        c.less(f"{lab}, {name}: axial (z) momentum / impact momentum", abs(s["p1z_rel"]), 1e-10,
               "exact 0; the lattice offset in z is the same for both bodies, which span the "
               "same z: round-off (4.5e-2 when the rims took the caps' normals)")
        c.less(f"{lab}, {name}: y momenta cancel", abs(s["p1y_rel"] + s["p2y_rel"]), 1e-12,
               "pairwise forces")
        c.true(f"{lab}, {name}: one contact episode", s["episodes"] == 1, "hit and rebound")
        c.less(f"{lab}, {name}: first touch [us] not before the surfaces are 0.3 spacings "
               "apart", -s["t_first"], -T_EARLIEST,
               f"the regions' surfaces meet at {T_MEET:.2f} us; measured 3.93 us (2.9-3.7 with "
               "contact/gap projection); it was 0 (the first step) when the rims took the "
               "caps' normals")
    if R == 1.0:
        c.less(f"{lab}, regions' normals, fit 8: lateral (y) momentum / axial",
               abs(reg["p1y_rel"]), 1e-2, "exact 0; measured 5.7e-3 (regions without fit "
               "1.6e-2): a contact line a few particles wide. One lattice offset: over five "
               "(bench/contact_offsets, 2026-12-06) 2.4e-3 - 1.8e-2, mean 9.5e-3, against "
               "2.4e-3 - 3.4e-2, mean 1.5e-2 with contact/gap projection (2.6e-3 at this one)")
    else:
        c.less(f"{lab}, regions' normals, fit 8: lateral (y) momentum / axial",
               abs(reg["p1y_rel"]), 1e-3, "issue 12's bound for the spheres; exact 0, measured "
               "2.0e-5 (5.5e-4 with contact/gap projection)")
        c.less(f"{lab}, regions' normals, fit 8, against the generated ones: lateral momentum",
               abs(reg["p1y_rel"]), 0.5 * abs(gen["p1y_rel"]),
               f"generated {gen['p1y_rel']:.1e}: the staircase's normals")
        reg2 = case(f"region_fit8_R{R:g}_np2", np=2, R=R, tend=tend, **REGFIT)
        c.less(f"{lab}, regions' normals, fit 8: np 2 vs np 1 (lateral momentum / axial)",
               abs(reg2["p1y_rel"] - reg["p1y_rel"]), 1e-9 + 1e-6 * abs(reg["p1y_rel"]),
               "the same boundary particles, normals and edge decisions on any rank count; "
               "round-off")
        fit = case(f"fit8_R{R:g}", R=R, tend=tend, fit=8)
        c.less(f"{lab}, fit 8 alone: lateral momentum / axial (finding)", abs(fit["p1y_rel"]),
               0.03, "measured 1.3e-2, five times the generated normals': the fit tilts the "
               "normals of the contact line (doc/hard_cases.md 4)")

# --- 2d: a disc R = 1 mm and a block 1 x 1 mm beside it, 0.1 mm, the regions' z faces near
# the plane (the disc's 1e-6 m from it, the block's off centre); the lattice offset (0.3, 0.2)
D2 = """units si
dimension 2
atom_style atomic
atom_modify map array
boundary f f p
region box block -3e-3 3e-3 -3e-3 3e-3 -0.5e-4 0.5e-4
create_box 1 box
lattice sq 1e-4 origin 0.3 0.2 0
region d cylinder z 0 0 1e-3 -1e-6 1e-6 units box
region b block 1.2e-3 2.2e-3 -0.5e-3 0.5e-3 -0.5e-4 1.5e-4 units box
create_atoms 1 region d
create_atoms 1 region b
group d region d
group b region b
pair_style esph/solid 1e-4 dimension 2
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix int all esph/integrate
set group all mass 7.85e-5
set group d i_esph_body 1
set group b i_esph_body 2
fix bnd all esph/boundary spacing 1e-4 region d region b
neighbor 2e-5 bin
run 0
""" + et.boundary_dump("bnd2d.dump")
log = et.run(a, et.write_input(a, "in.disc2d", D2), log="log.disc2d")
m = re.search(r"(\d+) boundary particles took the normals of region\(s\) d b .* (\d+) at the "
              r"regions' edges kept their own", log)
c.true("2d: the regions' normals set (log line)", m is not None, "fix esph/boundary region")
bd = np.loadtxt(os.path.join(a.workdir, "bnd2d.dump"), skiprows=9)
disc = bd[bd[:, 1] == 1]
rr = np.hypot(disc[:, 2], disc[:, 3])
err = np.hypot(disc[:, 5] - disc[:, 2] / rr, disc[:, 6] - disc[:, 3] / rr).max()
c.less("2d disc: normals against the radial direction", err, 1e-12,
       "the region's normal at the nearest surface point: exact (kept first normals are off "
       "by up to 30 degrees)")
c.near("2d: boundary particles that kept their own normals (the block's corners)",
       int(m.group(2)) if m else -1, 4, 0, "one per corner of the block; none on the disc")
c.less("2d: largest normal component out of the plane", np.abs(bd[:, 7]).max(), 1e-15,
       "a region's z faces bound the plane, not the body (the nearest z face gave (0, 0, -1) "
       "where it was closer than the body's own faces)")

# --- a block with a spherical hole, the hole a region with side out named on its own
# (0.2 mm, lattice offset (0.3, 0.2, 0.1)): the body lies outside the sphere, so its
# outward normal on the bore points to the sphere's centre (it pointed into the material)
HOLE = """units si
atom_style atomic
atom_modify map array
boundary f f f
region box block -2e-3 2e-3 -2e-3 2e-3 -2e-3 2e-3
create_box 1 box
lattice sc 2e-4 origin 0.3 0.2 0.1
region blk block -1.2e-3 1.2e-3 -1.2e-3 1.2e-3 -1.2e-3 1.2e-3 units box
region hole sphere 0 0 0 0.6e-3 side out units box
region body intersect 2 blk hole
create_atoms 1 region body
pair_style esph/solid 2e-4
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix int all esph/integrate
set group all mass 6.28e-8
fix bnd all esph/boundary spacing 2e-4 region hole
neighbor 4e-5 bin
run 0
""" + et.boundary_dump("bndhole.dump")
et.run(a, et.write_input(a, "in.hole", HOLE), log="log.hole")
bh = np.loadtxt(os.path.join(a.workdir, "bndhole.dump"), skiprows=9)
rh = np.linalg.norm(bh[:, 2:5], axis=1)
bore = rh < 0.6e-3 + 0.2e-3
inward = -bh[bore, 2:5] / rh[bore, None]
err = np.linalg.norm(bh[bore, 5:8] - inward, axis=1).max()
c.true("hole: boundary particles in the bore", bore.sum() > 20, f"{bore.sum()} found")
c.less("hole (region with side out): bore normals against the direction to the centre", err,
       1e-12, "the region's surface normal, reversed for side out: exact")
outer = ~bore
c.less("hole: outer faces' normals pointing to the hole's centre", int(
    (np.einsum("ij,ij->i", bh[outer, 5:8], bh[outer, 2:5]) <= 0.0).sum()), 1,
       "the outer faces are 2-3 spacings from the sphere: not its surface, they keep their "
       "generated normals (they took the sphere's, pointing into the body; warned)")
c.done()
