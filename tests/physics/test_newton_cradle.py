#!/usr/bin/env python3
"""Three bodies in a row (examples/newton_cradle, 3D, 0.25 mm): compute esph/contact
reports each interface apart. Its impulse is the momentum handed across the interface,
its first touch is when the gap has closed, each interface touches once, momentum is
conserved to round-off, and the same on 1 and 2 ranks and in a split run."""
import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("three bodies: contact per interface")
CR = "newton_cradle/in.newton_cradle"
DX, V, L = 0.25, 50.0, 10.0
RHO = 7850.0


def cradle(name, np_=1, **v):
    var = {"dx": DX, "thermo_every": 50}
    var.update(v)
    log = et.run(a, CR, var, np=np_, log=f"log.{name}")
    return log, et.summary(log, "NEWTON_CRADLE")


log, s = cradle("np1")
print("INFO", s)
# fix ave/time mode vector of the compute's whole array (the example writes interfaces.txt):
# its last block holds both interfaces with the impulses the final print reports
with open(os.path.join(a.lastdir, "interfaces.txt")) as f:
    blocks = [l.split() for l in f if l.strip() and not l.startswith("#")]
k = max(i for i, b in enumerate(blocks) if len(b) == 2)
last = blocks[k + 1:]
c.near("fix ave/time mode vector: rows of the last block", len(last), 2, 0,
       "one row per touching pair of bodies")
c.near("fix ave/time mode vector: impulse of interface 1-2", float(last[0][6]), s["J12"],
       1e-5 * s["J12"], "the compute's column 6 (printed to 6 digits)")
c.near("fix ave/time mode vector: impulse of interface 2-3", float(last[1][6]), s["J23"],
       1e-5 * s["J23"], "the compute's column 6 (printed to 6 digits)")
# the two-rod impact of the same rods for the contact duration
ref = et.summary(et.run(a, "rod_impact/in.rod_impact",
                        {"dx": DX, "Limp": L, "Ltgt": L, "tend": 8, "out": 0},
                        log="log.pair"))
print("INFO two rods:", ref)
p0 = s["p0"]
c.true("rows: bodies 1-2, then 2-3",
       (s["row1_I"], s["row1_J"], s["row2_I"], s["row2_J"]) == (1, 2, 2, 3),
       "one row per touching pair of bodies, sorted")
dt = 0.5 / 35    # time step [us] at 0.25 mm
c.near("interface 1-2: first touch [us]", s["first12_us"], 0.5 * DX * 1e-3 / V * 1e6, 2 * dt,
       "gap / V within 2 steps")
c.near("interface 1-2: episodes", s["ep12"], 1, 0, "one contact")
c.near("interface 2-3: episodes", s["ep23"], 1, 0, "one contact")
# the impulse is the momentum the interface hands on: 1 % for the rims, where the common
# normal is tilted and the force has a component across the axis
c.near("interface 1-2: impulse vs momentum lost by rod 1", s["J12"], p0 * (1 - s["v1"] / V),
       0.01 * p0, "momentum balance of rod 1")
c.near("interface 2-3: impulse vs momentum of rod 3", s["J23"], p0 * s["v3"] / V, 0.01 * p0,
       "momentum balance of rod 3")
# the net impulse (columns 15-17) is the momentum handed across, vector for vector: rod 1
# touches only rod 2, rod 3 only rod 2 (no force before the first touch, a fixed step)
c.near("interface 1-2: net impulse on rod 1 vs its momentum change", s["Jnet12x"],
       s["px1"] - p0, 1e-9 * p0, "exact up to round-off (column 6 is 0.27 % above it)")
c.near("interface 2-3: net impulse on rod 2 from rod 3 vs minus rod 3's momentum",
       s["Jnet23x"], -s["px3"], 1e-9 * p0, "exact up to round-off")
c.less("interface 1-2: net impulse across the axis", abs(s["Jnet12y"]), 1e-9 * p0,
       "the rims' tilted pair forces cancel around the axis")
for k in ("tc12_us", "tc23_us"):
    c.near(f"{k}: contact duration [us]", s[k], ref["contact_time_us"],
           0.01 * ref["contact_time_us"], "the two-rod impact of the same rods, 1 %")
c.less("momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")
c.true("the second interface touches after the first has released",
       s["first23_us"] > s["first12_us"] + s["tc12_us"], "sequential impacts")

# MPI: the same thermo and the same interface summary to round-off
log2, s2 = cradle("np2", np_=2)
th1, th2 = et.thermo(log)[-1], et.thermo(log2)[-1]
worst = max(np.abs(np.array(th1[k]) - np.array(th2[k])).max() / max(np.abs(th1[k]).max(), 1e-30)
            for k in ("KinEng", "PotEng", "c_v1", "c_v2", "c_v3", "c_px"))
c.less("np 1 vs np 2: worst thermo difference", worst, 1e-10, "round-off")
for k in ("first12_us", "tc12_us", "first23_us", "tc23_us", "ep12", "ep23"):
    c.near(f"np 1 vs np 2: {k}", s2[k], s[k], 0, "the same steps")
for k in ("J12", "J23", "Jnet12x", "Jnet23x"):
    c.near(f"np 1 vs np 2: {k}", s2[k], s[k], 1e-10 * abs(s[k]), "round-off")
# a split run continues the contact history of both interfaces exactly
log3, s3 = cradle("split", split=1)
for k in ("first12_us", "tc12_us", "first23_us", "tc23_us", "ep12", "ep23", "J12", "J23", "v3",
          "Jnet12x", "Jnet23x"):
    c.near(f"split run: {k}", s3[k], s[k], 1e-12 * abs(s[k]), "the uninterrupted run")
c.done()
