#!/usr/bin/env python3
"""The real particles' surface sums (normal, depth, gap) only while some body touches another
(doc/pair_esph_solid.rst, the normals; issue 15): two small iron blocks half a spacing
apart, block 1 closing at 50 m/s (the faces meet after 200 steps of 5 ns). Before the
touch every real particle has normal 0 and depth 0 (the sums are skipped: the contact rule
would use them only across a gap below the cap, which a particle takes only while its body
touches); in contact the particles of the facing surfaces have their outward normals; after
the blocks have parted, 0 again. On 1 and 2 ranks the same. A few seconds."""

import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("surface sums only while bodies touch")


def real_dump(tag):
    return (f"write_dump real custom real.{tag}.txt id i_esph_body x y z d2_esph_n[1] "
            "d2_esph_n[2] d2_esph_n[3] d_esph_depth modify sort id format float %.17g")


# block 1's face half a spacing (0.05 mm) from block 2's
text = et.small_blocks("-0.00045 -0.00005 0 0.0006 -0.0002 0.0002") + f"""
displace_atoms b0 move -0.00005 0 0 units box
velocity rb0 set 50 0 0 units box
neighbor 2e-5 bin
thermo_style custom step f_int[2] f_int[4] f_int[5]
thermo 20
run 100
{real_dump("apart")}
run 115
{real_dump("touch")}
print "SURF_TOUCH pairs=$(f_int[2]) first_us=$(f_int[4]*1e6:%.6f)"
run 585
{real_dump("parted")}
print "SURF pairs=$(f_int[2]) first_us=$(f_int[4]*1e6:%.6f) end_us=$(f_int[5]*1e6:%.6f)"
"""
inp = et.write_input(a, "in.surface_sums", text)


def load(tag):
    return np.loadtxt(os.path.join(a.workdir, f"real.{tag}.txt"), skiprows=9, ndmin=2)


ref = None
for nprocs in (1, 2):
    out = et.run(a, inp, np=nprocs, log=f"log.surface_sums.np{nprocs}")
    t = et.summary(out, "SURF_TOUCH")
    s = et.summary(out, "SURF")
    print(f"INFO np {nprocs}: in contact {t}; at the end {s}")
    apart, touch, parted = load("apart"), load("touch"), load("parted")
    c.less(f"np {nprocs}: before the touch, largest |normal|, |depth| of a real particle",
           float(np.max(np.abs(apart[:, 5:9]))), 1e-300,
           "no body touches: the sums are skipped, normal and depth exactly 0")
    c.true(f"np {nprocs}: the blocks are in contact at step 215", t["pairs"] > 0,
           f"{t['pairs']:.0f} interacting pairs; the faces meet at 1 us (step 200), first "
           f"touch {t['first_us']:.3f} us")
    # the facing layers: block 1's particles at x = -0.05 mm, block 2's at x = 0.05 mm
    b, x = touch[:, 1], touch[:, 2]
    face1 = (b == 1) & (x > x[b == 1].max() - 0.5e-4)
    face2 = (b == 2) & (x < x[b == 2].min() + 0.5e-4)
    nx1, nx2 = touch[face1, 5], touch[face2, 5]
    c.true(f"np {nprocs}: in contact, the facing layers have outward normals",
           bool(nx1.size and nx2.size and np.all(nx1 > 0.3) and np.all(nx2 < -0.3)),
           f"x components {nx1.min():.3f}..{nx1.max():.3f} (block 1, +x) and "
           f"{nx2.min():.3f}..{nx2.max():.3f} (block 2, -x)")
    c.true(f"np {nprocs}: the blocks have parted by step 800", s["end_us"] > 0.0,
           f"contact ended at {s['end_us']:.3f} us")
    c.less(f"np {nprocs}: after they part, largest |normal|, |depth| of a real particle",
           float(np.max(np.abs(parted[:, 5:9]))), 1e-300, "no body touches: 0 again")
    if ref is None:
        ref = touch
    else:
        c.less("np 2 vs np 1: normals and depths in contact",
               float(np.max(np.abs(touch[:, 5:9] - ref[:, 5:9]))), 1e-12,
               "the same computation on two ranks: round-off")
c.done()
