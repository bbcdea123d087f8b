#!/usr/bin/env python3
"""The surface gap is a property of the boundary particles, not of the smoothing length
(tests/physics/in.gap_edge; doc/pair_esph_solid.rst, "Surface gap"): a small iron block
0.32 spacings above a larger one, approaching at 60 m/s, the larger block's top edges one
to two spacings beyond the smaller one's sides. A larger h or hvar widens the neighbour
list; the gap's partners stay within two spacings (the kernel support at h = spacing).
Before that limit (found by a hostile round, 2026-12-06) the edges took the "gap" of
oblique partners further out, negative, and with h = 1.5 or 2 spacings or hvar 1.5 the
blocks pushed each other from step 0 across the open gap: 13 / 40 / 14 N and 221 / 2099 /
112 interacting pairs at step 0, first touch at t = 0. With contact/gap plane the corners
touch within a tenth of a spacing of the faces' meeting (the default projection: 0.26
spacings before it), on 1 and 2 ranks. About 30 seconds."""

import esphtest as et

a = et.parse_args()
c = et.Checks("surface gap: partners within two spacings, whatever h")
INP = et.source_input(a, "in.gap_edge")
DT_US = 0.01    # the input's fixed step [us]


def case(name, np=1, **var):
    s = et.summary(et.run(a, INP, var, np=np, log=f"log.{name}"), "GAP_EDGE")
    print(f"INFO {name}: {s}")
    return s


ref = case("h1", hfac=1.0)
c.true("h = spacing: touches within the run", ref["t_first_us"] > 0.0,
       "the reference for the other runs (measured 0.26 us)")
res = {}
for name, var in (("h1.5", dict(hfac=1.5)), ("h2", dict(hfac=2.0)),
                  ("hvar1.5", dict(pextra="hvar 1.5"))):
    s = res[name] = case(name, **var)
    c.true(f"{name}: no interacting pair across the open gap at step 0",
           s["pairs0"] == 0 and s["force0"] == 0.0,
           "the faces are 0.32 spacings apart (before the limit: 221 / 2099 / 112 pairs)")
    c.true(f"{name}: first touch not before the one at h = spacing",
           s["t_first_us"] < 0.0 or s["t_first_us"] >= ref["t_first_us"] - DT_US,
           f"the same boundary particles and gaps; h = spacing: {ref['t_first_us']} us "
           "(a run that has not touched reports a negative time)")
hv = res["hvar1.5"]
c.less("hvar 1.5: first touch as at h = spacing [us]", abs(hv["t_first_us"] - ref["t_first_us"]),
       0.5 * DT_US, "h starts at h0 = spacing, and so do the gaps")
c.less("hvar 1.5: contact force after 40 steps against h = spacing, relative",
       abs(hv["force"] / ref["force"] - 1.0), 0.01,
       "h changes only by the compression of the last 14 steps (measured 7e-4)")
two = case("hvar1.5_np2", np=2, pextra="hvar 1.5")
c.true("hvar 1.5: 2 ranks touch at the step of 1", two["t_first_us"] == hv["t_first_us"],
       "the same gap partners on every rank")
c.less("hvar 1.5: contact force after 40 steps, 2 ranks against 1, relative",
       abs(two["force"] / hv["force"] - 1.0), 1e-10, "round-off")

# contact/gap plane (pair_esph_solid.rst, "Surface gap"): a candidate's gap is bounded by the
# tangent planes of the two boundary particles. The small block's bottom corners read the
# projection's -0.34 spacings with the faces 0.32 apart, and the blocks touch at 0.26 us
# (the faces 0.26 spacings apart); the larger block's face plane reads the corners' true
# 0.32. The faces meet at 0.32 spacings / 60 m/s = 1.333 us.
T_MEET = 0.32 * 2.5e-4 / 60.0 * 1e6
SPACING_US = 2.5e-4 / 60.0 * 1e6    # the time to close one spacing [us]
pl = case("plane", pextra="contact/gap plane", nsteps=200)
c.true("contact/gap plane: touches within the run", 0.0 < pl["t_first_us"] <= T_MEET + DT_US,
       f"the faces meet at {T_MEET:.3f} us (measured 1.06 us)")
c.less("contact/gap plane: gap at the first touch [spacings]",
       (T_MEET - pl["t_first_us"]) / SPACING_US, 0.1,
       "corners and edges touch within a tenth of a spacing of the faces (measured 0.066; "
       f"the projection: {(T_MEET - ref['t_first_us']) / SPACING_US:.2f})")
c.true("contact/gap plane: no interacting pair at step 0", pl["pairs0"] == 0 and
       pl["force0"] == 0.0, "the faces are 0.32 spacings apart")
pl2 = case("plane_np2", np=2, pextra="contact/gap plane", nsteps=200)
c.true("contact/gap plane: 2 ranks touch at the step of 1", pl2["t_first_us"] == pl["t_first_us"],
       "the same candidates on every rank")
c.less("contact/gap plane: contact force after 200 steps, 2 ranks against 1, relative",
       abs(pl2["force"] / pl["force"] - 1.0), 1e-9, "round-off")
c.done()
