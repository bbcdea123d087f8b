#!/usr/bin/env python3
"""Boundary particles and normals (fix esph/boundary): generated on a box and a cylinder
they sit on the surface and carry the analytic outward normals; on a freely spinning
block the normals turn with the body."""
import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("boundary particles and normals")

HEAD = """units si
atom_style atomic
atom_modify map array
boundary f f f
region box block -3e-3 3e-3 -3e-3 3e-3 -3e-3 3e-3
create_box 1 box
lattice sc 1e-4 origin 0.5 0.5 0.5
"""
TAIL = """pair_style esph/solid 1e-4
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix int all esph/integrate
set group all mass 7.85e-9
fix bnd all esph/boundary spacing 1e-4
neighbor 2e-5 bin
variable b atom mass==0
group bnd variable b
"""
DUMP = ("write_dump bnd custom {f} id x y z d2_esph_n[1] d2_esph_n[2] d2_esph_n[3] "
        "modify sort id format float %.17g\n")


def load(name):
    return np.loadtxt(f"{a.workdir}/{name}", skiprows=9)


# --- box 1.0 x 0.8 x 0.6 mm ---
et.write_input(a, "in.box", HEAD + "region b block 0 1e-3 0 0.8e-3 0 0.6e-3 units box\n"
               "create_atoms 1 region b\n" + TAIL + "run 0\n" + DUMP.format(f="box.dump"))
et.run(a, f"{a.workdir}/in.box", log="log.box")
d = load("box.dump")
x, n = d[:, 1:4], d[:, 4:7]
hi = np.array([1e-3, 0.8e-3, 0.6e-3])
# distance of each boundary particle to the box surface
dist = np.minimum(np.abs(x), np.abs(x - hi)).min(axis=1)
c.less("box: boundary particles on the surface [m]", dist.max(), 1e-15, "placed exactly")
# expected normal: sum of the outward face normals of the faces the point lies on
on_lo, on_hi = np.abs(x) < 1e-12, np.abs(x - hi) < 1e-12
nexp = on_hi.astype(float) - on_lo.astype(float)
nexp /= np.linalg.norm(nexp, axis=1)[:, None]
ang = np.degrees(np.arccos(np.clip((n * nexp).sum(axis=1), -1, 1)))
faces = (on_lo | on_hi).sum(axis=1) == 1
c.less("box faces: max normal error [deg]", ang[faces].max(), 1e-6, "exact by lattice symmetry")
c.less("box edges and corners: max normal error [deg]", ang[~faces].max(), 1e-4,
       "bisector of the faces")
c.near("box: number of boundary particles", len(d), 10 * 8 * 6 - 8 * 6 * 4, 0,
       "one per surface particle: all 480 minus the 8 x 6 x 4 interior")

# --- cylinder R = 1 mm, axis z, length 1 mm ---
et.write_input(a, "in.cyl", HEAD + "region b cylinder z 0 0 1e-3 0 1e-3 units box\n"
               "create_atoms 1 region b\n" +
               TAIL.replace("spacing 1e-4", "spacing 1e-4 smooth 1.5") + "run 0\n" +
               DUMP.format(f="cyl.dump"))
et.run(a, f"{a.workdir}/in.cyl", log="log.cyl")
d = load("cyl.dump")
x, n = d[:, 1:4], d[:, 4:7]
lateral = (x[:, 2] > 0.25e-3) & (x[:, 2] < 0.75e-3)
r = np.hypot(x[lateral, 0], x[lateral, 1])
nr = np.column_stack([x[lateral, 0] / r, x[lateral, 1] / r, np.zeros(lateral.sum())])
ang = np.degrees(np.arccos(np.clip((n[lateral] * nr).sum(axis=1), -1, 1)))
print(f"INFO cylinder lateral normals: mean {ang.mean():.2f} deg, max {ang.max():.2f} deg, "
      f"radius {r.mean()*1e3:.4f} +- {r.std()*1e3:.4f} mm")
# a cubic lattice approximates the cylinder by a staircase; with smooth 1.5 the normal
# kernel averages over 3 spacings: measured mean 5.8, max 12.6 deg at R = 10 dx (with the
# default smooth 1: mean 12, max 27 deg)
c.less("cylinder: mean lateral normal error [deg]", ang.mean(), 8.0, "staircase surface")
c.less("cylinder: max lateral normal error [deg]", ang.max(), 20.0, "staircase surface")
c.near("cylinder: boundary particles at the radius [mm]", r.mean() * 1e3, 1.0, 0.05,
       "surface at R within half a spacing")

# --- spinning block: normals rotate with the body ---
# A free block set spinning at w = 2e4 rad/s for 11.5 degrees. With the kernel-gradient
# corrected velocity gradient the rotation is reproduced exactly (no spurious strain rate
# at free surfaces) and the boundary particles (linear-exact interpolation, corrected spin)
# move and turn with the body: tolerance 0.05 deg for the centrifugal deformation. With
# the paper's plain SPH gradient the one-sided kernel at the free surfaces sees a spurious
# shear rate ~ w/4 (REFERENCES 4), the shear stress it builds brakes the rotation: reported.
w = 2.0e4
theta = w * 2000 * 5e-9
R = np.array([[np.cos(theta), -np.sin(theta), 0], [np.sin(theta), np.cos(theta), 0], [0, 0, 1]])
for grad in ("corrected", "plain"):
    et.write_input(a, f"in.spin.{grad}", HEAD + "region b block -0.5e-3 0.5e-3 -0.3e-3 0.3e-3 "
                   "-0.2e-3 0.2e-3 units box\ncreate_atoms 1 region b\n" +
                   TAIL.replace("esph/solid 1e-4", f"esph/solid 1e-4 gradient {grad}") +
                   DUMP.format(f="spin0.dump") +
                   f"variable vx atom -{w}*y\nvariable vy atom {w}*x\n"
                   "velocity all set v_vx v_vy 0.0 units box\n"
                   "timestep 5e-9\nrun 2000\n" + DUMP.format(f=f"spin1.{grad}.dump"))
    log = et.run(a, f"{a.workdir}/in.spin.{grad}", log=f"log.spin.{grad}")
    d0, d1 = load("spin0.dump"), load(f"spin1.{grad}.dump")
    ang = np.degrees(np.arccos(np.clip((d1[:, 4:7] * (d0[:, 4:7] @ R.T)).sum(axis=1), -1, 1)))
    pos = np.degrees(np.arctan2(d1[:, 2], d1[:, 1]) - np.arctan2(d0[:, 2], d0[:, 1]))
    pos = (pos + 180) % 360 - 180
    ke = et.thermo(log)[-1]["TotEng"]
    print(f"INFO spin {grad}: normal error mean {ang.mean():.3f} max {ang.max():.3f} deg; "
          f"boundary particles turned {pos.mean():.3f} of {np.degrees(theta):.3f} deg")
    if grad == "corrected":
        c.less("spinning block (corrected gradient): max normal error [deg]", ang.max(), 0.05,
               "normals rotate with W at the boundary particles")
        c.near("spinning block (corrected gradient): boundary particles turned [deg]",
               pos.mean(), np.degrees(theta), 0.05, "they move with the body")
c.done()
