#!/usr/bin/env python3
"""The same input on 1, 2 and 4 MPI ranks, and with newton off, gives the same thermo output
to round-off.
3D rods with contact, coarse (dx = 0.25 mm): with 2 and 4 ranks the sub-domain boundary
x = 0 cuts the contact interface. Also 1D, contact off (pure solid core).
Tolerance: relative 1e-10 on every thermo column (printed with 15 digits) over ~360 steps. Sums over neighbours
are accumulated in a different order on different rank counts (ghost/reverse
communication), which changes the last bits (1e-16); a wave problem carries such
differences along without amplifying them much over a few hundred steps. A real
communication bug (a missing ghost update) gives differences of 1e-3 or more. Measured: 3e-14 (3D, contact), 3e-13 (1D)."""
import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("MPI: 1, 2 and 4 ranks agree")

cases = {
    "3d-contact": {"dim": 3, "dx": 0.25, "tend": 2.0, "thermo_every": 20, "out": 0},
    "1d-nocontact": {"dim": 1, "dx": 0.1, "tend": 3.0, "contact": "off", "thermo_every": 20,
                     "out": 0},
}
for name, var in cases.items():
    runs = {}
    for np_ in (1, 2, 4):
        log = et.run(a, "rod_impact/in.rod_impact", var, np=np_, log=f"log.{name}.{np_}")
        runs[np_] = et.thermo(log)[-1]
    ref = runs[1]
    for np_ in (2, 4):
        worst, col = 0.0, ""
        for k in ref:
            x, y = np.array(ref[k]), np.array(runs[np_][k])
            if len(x) != len(y):
                worst, col = np.inf, k + " (length)"
                break
            # columns that are zero up to round-off (lateral momentum and angular momentum
            # of the aligned impact, ~1e-18) are compared against an absolute floor
            scale = max(np.abs(x).max(), 1e-4)
            d = np.abs(x - y).max() / scale
            if d > worst:
                worst, col = d, k
        print(f"INFO {name} np={np_}: worst relative difference {worst:.3e} in {col}")
        c.less(f"{name}: np {np_} vs np 1, max relative difference", worst, 1.0e-10,
               "summation order only")

# newton off (pairs with ghost partners computed on both ranks) against newton on
ref = et.thermo(et.run(a, "rod_impact/in.rod_impact", cases["3d-contact"], log="log.non"))[-1]
for np_ in (1, 2):
    off = et.thermo(et.run(a, "rod_impact/in.rod_impact", dict(cases["3d-contact"], newton="off"),
                           np=np_, log=f"log.noff.{np_}"))[-1]
    worst = max(np.abs(np.array(ref[k]) - np.array(off[k])).max() / max(np.abs(ref[k]).max(), 1e-4)
                for k in ref)
    print(f"INFO newton off np={np_}: worst relative difference {worst:.3e}")
    c.less(f"newton off, np {np_} vs newton on: max relative difference", worst, 1.0e-10,
           "summation order only")
c.done()
