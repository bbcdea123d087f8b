#!/usr/bin/env python3
"""Thermo pe is the internal energy at the end of each step (doc/pair_esph_solid.rst,
Energy output).

The pair style tallies sum_i m_i e_i; fix esph/integrate's vector element 1 is the same sum
after its final_integrate. Until 2026-12-07 the tally took the predicted energies the force
computation used, whose rate is the previous step's: in the first step of an impact 56 %
below the energy after the step, 0.1-0.4 % off while the bodies ring (a helper's sweep,
/tmp/sweep51/pe), and etotal carried that into every energy check. Now the tally advances
e_i with the rate just computed, as final_integrate() does, so the two agree to round-off
at every step:

1. Sliding contact of two iron blocks from the first step (the block scene of
   test_continuation), the default predicted scheme: |pe - f_int[1]| <= 1e-12 |f_int[1]| on
   every thermo row (every 5 steps, 80 steps), also on 2 ranks; and pe changes by more than
   that between rows (the comparison is not between two constants).
2. The same with scheme staggered (the energy takes the mean of its two passes' rates).
3. A split run (run 40 + run 40): the setup row of the second run repeats the last row of
   the first (the setup computation tallies the state as it is, which is the energy after
   the last step)."""
import esphtest as et

a = et.parse_args()
c = et.Checks("energy output: thermo pe against the integrator's internal energy")

TOL = 1.0e-12


def rows_of(log):
    th = et.thermo(log)
    return [dict(zip(b.keys(), vals)) for b in th for vals in zip(*b.values())]


def check_rows(title, rows):
    worst = 0.0
    for r in rows:
        worst = max(worst, abs(r["PotEng"] - r["f_int[1]"]) / max(abs(r["f_int[1]"]), 1e-300))
    c.less(f"{title}: max |pe - f_int[1]| / |f_int[1]| over {len(rows)} rows", worst, TOL,
           "the same sum of m e after the step, computed twice (round-off)")
    pes = [r["PotEng"] for r in rows]
    spread = (max(pes) - min(pes)) / max(abs(max(pes)), 1e-300)
    c.true(f"{title}: pe changes between rows (relative spread {spread:.3g} > 1e-6)",
           spread > 1.0e-6,
           "the blocks convert kinetic into internal energy: a constant would pass trivially")


for name, fixopts in (("predicted", ""), ("staggered", "scheme staggered")):
    fresh, _ = et.block_scene(fixopts)
    for np_ in (1, 2):
        inp = et.write_input(a, f"in.{name}", fresh + "run 80\n")
        log = et.run(a, inp, np=np_, log=f"log.{name}.{np_}")
        check_rows(f"{name}, np {np_}", rows_of(log))

# a split run: the second run's setup row is the energy after the first run's last step
fresh, _ = et.block_scene("")
inp = et.write_input(a, "in.split", fresh + "run 40\nrun 40\n")
log = et.run(a, inp, log="log.split")
blocks = et.thermo(log)
first, second = blocks[0], blocks[1]
last1 = first["PotEng"][-1]
setup2 = second["PotEng"][0]
c.less("split run: |pe at the second run's setup - pe at the first run's last step| / pe",
       abs(setup2 - last1) / abs(last1), TOL,
       "the same state; the setup computation tallies it as it is")
check_rows("split run", rows_of(log))
c.done()
