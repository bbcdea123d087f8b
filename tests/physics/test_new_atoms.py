#!/usr/bin/env python3
"""Atoms created after a run (create_atoms, the way the package's own error message sends a
user who adds a body: create it, delete the old boundary particles, define fix esph/boundary
again) start with the ESPH state of a fresh box, on any number of ranks.

fix property/atom zeroes only newly grown memory: a slot reused after a sort, an exchange or
a ghost's use keeps the values of the atom that held it. Before the fix (found by a
user-scene sweep, 2026-12-06) the 64 new atoms of this scene had on 2 ranks 46 with the
density, energy, stress and normals of others (d_esph_e 200-560 J/kg, s_xx up to 7.35e8 Pa,
engaged), the total energy jumped by 5.4 % at the next run and the second impact differed
with the number of ranks (0.55 / 0.72 / 0.57 us on 1 / 2 / 4 ranks); on 1 rank the first
new atom took the mass and body ID of another (the sort's scratch slot).

Scene: two iron blocks (4 x 1 x 1 mm, 0.25 mm), the impactor at 50 m/s, 0.1 mm apart; after
300 steps (the first impact over) a third block is created at rest in the target's path.
  1. the new atoms' ESPH state is that of a fresh box (mass and body 0 until set, the rest
     0) on 1, 2 and 4 ranks
  2. the total energy (kinetic + the internal energy of fix esph/integrate, f_int[1]) does
     not change when they are added (they are at rest, unstrained)
  3. the second impact (target on the new block): the same on 2 and 4 ranks as on 1 to
     round-off, and the new block's momentum equals the impulse compute esph/contact gives
"""
import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("atoms created after a run: fresh ESPH state")

SCENE = """
variable h equal 2.5e-4
units si
atom_style atomic
atom_modify map array
boundary f f f
region box block -0.007 0.007 -0.001 0.001 -0.001 0.001
create_box 2 box
lattice sc ${h} origin 0.5 0.5 0.5
region a block -0.004 0.0 -0.0005 0.0005 -0.0005 0.0005 units box
region b block 0.0 0.004 -0.0005 0.0005 -0.0005 0.0005 units box
create_atoms 1 region a
create_atoms 2 region b
group a region a
group b region b
displace_atoms b move 1.0e-4 0 0 units box
pair_style esph/solid ${h}
pair_coeff * * rho0 7850 shear 80.0e9 eos mie/gruneisen 3574 1.92 1.69
variable m equal 7850*${h}^3
set group all mass ${m}
set group a i_esph_body 1
set group b i_esph_body 2
fix bnd all esph/boundary spacing ${h}
fix int all esph/integrate
variable massive atom mass>0.0
group real variable massive
group ra intersect a real
velocity ra set 50.0 0.0 0.0 units box
timestep 1.0e-8
neighbor $(0.2*v_h) bin
neigh_modify every 1 delay 0 check yes
compute cont all esph/contact
thermo_style custom step etotal
thermo_modify format float %.15g
thermo 100
variable etot equal ke+f_int[1]
run 300
variable e1 equal $(v_etot)
region c block 0.0046 0.0056 -0.0005 0.0005 -0.0005 0.0005 units box
create_atoms 1 region c
group c region c
write_dump c custom ${dump}.raw id mass i_esph_body modify sort id
set group c mass ${m}
set group c i_esph_body 3
write_dump c custom ${dump} id mass i_esph_body d_esph_rho d_esph_e d_esph_h &
  d2_esph_s[1] d2_esph_s[4] d2_esph_n[1] d_esph_depth d_esph_eng modify sort id
variable zm atom mass==0.0
group zm variable zm
delete_atoms group zm
unfix bnd
fix bnd all esph/boundary spacing ${h}
variable pb3 atom mass*vx*(i_esph_body==3)
compute p3 all reduce sum v_pb3
run 0 post no
variable e2 equal $(v_etot)
run 1000 post no
print "NEW_ATOMS e_before=$(v_e1:%.15g) e_after=$(v_e2:%.15g) rows=$(c_cont) b1=$(c_cont[2][1]) b2=$(c_cont[2][2]) dur_us=$(c_cont[2][9]*1e6:%.6f) episodes=$(c_cont[2][10]) J=$(c_cont[2][15]:%.15e) p3=$(c_p3:%.15e)"
"""
inp = et.write_input(a, "in.new_atoms", SCENE)

res = {}
for np_ in (1, 2, 4):
    dump = os.path.join(a.workdir, f"new_atoms.np{np_}.dump")
    s = et.summary(et.run(a, inp, {"dump": dump}, np=np_, log=f"log.new_atoms.np{np_}"),
                   "NEW_ATOMS")
    res[np_] = s
    d = np.loadtxt(dump, skiprows=9)
    print(f"INFO np {np_}: {s}")
    c.true(f"np {np_}: 64 new atoms", len(d) == 64, "4 x 4 x 4 lattice sites in region c")
    raw = np.loadtxt(dump + ".raw", skiprows=9)
    c.true(f"np {np_}: mass and body 0 as created", bool(np.all(raw[:, 1:3] == 0.0)),
           "a fresh box's atoms (before: on 1 rank the first new atom had another's mass and "
           "body, from the sort's scratch slot)")
    c.true(f"np {np_}: mass and body as set", bool(np.all(d[:, 1] == d[0, 1]) and
                                                     np.all(d[:, 2] == 3)),
           "set group c mass / i_esph_body 3")
    # the state of a fresh box: density, energy, h, stress, normal, depth, engagement all 0
    # (the pair style fills rho0 and h0 at the run's start)
    stale = int(np.count_nonzero(d[:, 3:]))
    c.true(f"np {np_}: ESPH state of the new atoms zero (non-zero values: {stale})", stale == 0,
           "fresh atoms (before: 46 of 64 atoms with others' values on 2 ranks)")
    c.less(f"np {np_}: total energy change on adding them (relative)",
           abs(s["e_after"] - s["e_before"]) / s["e_before"], 1.0e-9,
           "atoms at rest and unstrained add nothing (before: +5.4 % on 2 ranks)")
    c.true(f"np {np_}: second impact between bodies 2 and 3",
           s["b1"] == 2 and s["b2"] == 3 and s["episodes"] >= 1, "the target hits the new block")
    c.less(f"np {np_}: new block's momentum against the impulse on it (relative)",
           abs(s["p3"] + s["J"]) / abs(s["J"]), 1.0e-9,
           "momentum of body 3 = its impulse from body 2 (it started at rest)")
for np_ in (2, 4):
    c.less(f"np {np_} vs np 1: impulse of the second impact (relative)",
           abs(res[np_]["J"] - res[1]["J"]) / abs(res[1]["J"]), 1.0e-10, "round-off")
    c.true(f"np {np_} vs np 1: contact duration and episodes",
           abs(res[np_]["dur_us"] - res[1]["dur_us"]) < 1.0e-6 and
           res[np_]["episodes"] == res[1]["episodes"], "the same steps")
c.done()
