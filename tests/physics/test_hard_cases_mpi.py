#!/usr/bin/env python3
"""Every hard-case example on 1 and 2 MPI ranks gives the same thermo output to
round-off (short, coarse variants). Tolerance as in test_mpi.py: relative 1e-10 per
thermo column; summation order changes the last bits only, a communication bug shows
as 1e-3 or more. Columns that are zero up to round-off (lateral momenta, ~1e-18) are
compared against a floor of 1e-4 in the scale."""

import esphtest as et

a = et.parse_args()
c = et.Checks("hard cases on 1 and 2 ranks")

cases = [
    ("unequal rods", "unequal_rods/in.unequal_rods",
     {"dim": 1, "dx": 0.2, "tend": 6, "out": 0, "thermo_every": 50}),
    ("dissimilar rods", "dissimilar_rods/in.dissimilar_rods",
     {"dim": 1, "dx": 0.2, "tend": 6, "out": 0, "thermo_every": 50}),
    ("fast impact 3D", "fast_impact/in.fast_impact",
     {"dim": 3, "dx": 0.5, "V": 500, "tend": 3, "out": 0, "thermo_every": 20}),
    ("off-axis rods", "offaxis_rods/in.offaxis_rods",
     {"dx": 0.5, "tend": 3, "out": 0, "thermo_every": 20}),
    ("oblique rod on block", "oblique_rod/in.oblique_rod",
     {"dx": 0.25, "tend": 6, "thermo_every": 20}),
    ("colliding rings", "colliding_rings/in.colliding_rings",
     {"dx": 1.0, "tend": 40, "thermo_every": 50}),
    ("colliding rings, xsph", "colliding_rings/in.colliding_rings",
     {"dx": 1.0, "tend": 40, "thermo_every": 50, "eps": 0.3, "xsph": 0.5}),
    ("spinning block", "spinning_block/in.spinning_block",
     {"dx": 0.2, "tend": 3, "thermo_every": 20}),
    ("initial gap", "rod_impact/in.rod_impact",
     {"dim": 1, "dx": 0.2, "gap": 1.0, "tend": 8, "out": 0, "thermo_every": 50}),
    ("free bar", "free_bar/in.free_bar", {"nsteps": 2000}),
    ("plasticity 1D", "rod_impact/in.rod_impact",
     {"dim": 1, "dx": 0.1, "yield": 0.5e9, "tend": 3, "out": 0, "thermo_every": 50}),
    ("Taylor bar", "taylor_bar/in.taylor_bar", {"dx": 0.81, "tend": 15, "thermo_every": 50}),
]
for name, infile, var in cases:
    tag = name.replace(" ", "_")
    runs = {np_: et.production_thermo(et.run(a, infile, var, np=np_, log=f"log.{tag}.{np_}"))
            for np_ in (1, 2)}
    worst, col = et.worst_difference(runs[1], runs[2])
    print(f"INFO {name}: {len(runs[1]['Step'])} thermo rows, worst relative difference "
          f"{worst:.3e} in {col}")
    c.less(f"{name}: np 2 vs np 1, max relative difference", worst, 1.0e-10,
           "summation order only")
c.done()
