#!/usr/bin/env python3
"""Bodies on lattices of different spacings (tests/physics/in.two_spacings: two iron blocks,
one fix esph/boundary of its own spacing each, 0.1 mm apart, 50 m/s, 800 steps of 5 ns).
The faces meet at gap / V = 2.0 us whatever the two spacings: the touch's cells and the
reach of the gap's partners are each body's own (measured: first touch 1.91 / 1.90 us, the
touch's 0.02 mean spacings early, where A's edges face B's larger face; 1.995 us with equal
spacings). Before the pair style took each body's
spacing (it took the first fix's for all), 0.2 / 0.25 mm first touched at 2.42 us with the
faces 21 um inside each other, 0.25 / 0.2 at 1.40 us across a 30 um gap, 0.3 / 0.2 at 0.88
us, 0.2 / 0.3 at 2.92 us with a warning that B's volumes were 3.4 x spacing^3. About 20 s."""

import esphtest as et

a = et.parse_args()
c = et.Checks("bodies on lattices of different spacings")
INP = et.source_input(a, "in.two_spacings")
STEP = 5e-3    # us


def scene(name, np_=1, **var):
    text = et.run(a, INP, var, np=np_, log=f"log.{name}")
    return et.summary(text, "TWO_SPACINGS"), text


ref = None
for dxa, dxb, hh in ((0.2, 0.2, 0.25), (0.2, 0.25, 0.25), (0.25, 0.2, 0.25), (0.2, 0.3, 0.3),
                     (0.3, 0.2, 0.3)):
    name = f"{dxa}_{dxb}"
    s, text = scene(name, dxa=dxa, dxb=dxb, hh=hh)
    print(f"INFO dxa {dxa} dxb {dxb} h {hh}: {s}")
    # the touch's cells, cubes of (1 + 0.02) x each body's spacing, meet 0.02 mean spacings
    # before the faces (pair_esph_solid.rst, Touch); where the faces are of equal size the
    # gap itself decides later (1 step early), where A's edges face B's larger face their
    # projected gap is closed at the touch
    lead = s["meet_us"] - s["first_us"]
    bound = 0.03 * 0.5 * (dxa + dxb) * 1e-3 / 50.0 * 1e6
    c.less(f"{name}: first touch before the faces meet [us]", lead, bound,
           "within 0.03 mean spacings (test_gap_reach's bound; the touch's tolerance 0.02)")
    c.less(f"{name}: first touch after the faces meet [us]", -lead, 2 * STEP,
           "not later than 2 steps (issue 12's bound for gaps)")
    c.true(f"{name}: one contact episode", s["episodes"] == 1, "hit and rebound")
    c.true(f"{name}: the blocks part", s["va"] < s["vb"], "after the rebound B is faster than A")
    c.true(f"{name}: no warning", "WARNING" not in text,
           "each body's volumes against its own spacing (B's were 3.4 x spacing^3 of A's fix)")
    if (dxa, dxb) == (0.2, 0.25):
        ref = s
s2, _ = scene("0.2_0.25_np2", np_=2, dxa=0.2, dxb=0.25, hh=0.25)
for k in ("first_us", "tc_us", "va", "vb"):
    c.near(f"0.2_0.25: np 2 vs np 1 {k}", s2[k], ref[k], 1e-9 + 1e-9 * abs(ref[k]), "round-off")
# a body in the groups of two fixes with different spacings is an error that names it
bad = et.write_input(a, "in.two_spacings_bad", open(INP).read().replace(
    "fix             bndB B esph/boundary spacing ${hb}",
    "fix             bndB B esph/boundary spacing ${hb}\nfix             bndC A esph/boundary spacing ${hb}"))
try:
    et.run(a, bad, {"dxa": 0.2, "dxb": 0.25}, log="log.bad")
    c.true("a body in two fixes of different spacings: error", False, "it ran")
except RuntimeError:
    log = open(a.lastdir + "/log.bad").read()
    c.true("a body in two fixes of different spacings: error naming the body and the spacings",
           "Body 1 (i_esph_body) has real particles in the groups of fixes esph/boundary" in log,
           "a body is on one lattice")
c.done()
