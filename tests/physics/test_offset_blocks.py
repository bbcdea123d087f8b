#!/usr/bin/env python3
"""Two iron cubes (1.2 mm, 6 particles across at 0.2 mm, 25 m/s each along x) whose faces
overlap by half their height (tests/physics/in.offset_blocks): an edge of each cube meets
the flat face of the other. Exact frictionless contact of flat faces: the force along x,
no momentum across (issue 12: a contact that holds on faces, edges and corners).
- the touch (contact/gap touch, the default): the cubes couple when the cells of their
  particles meet, 0.02 spacings before the faces (the projection alone: 0.28 spacings
  before, the edges along their tilted normals), and the start across one spacing of gap
  gives what a touching start gives (the faces 0.02 spacings apart);
- the default (mean) common normal: the edges' bisector normals tilt the common normal by
  up to 22.5 degrees, and the cubes leave with a momentum across of 0.38 of the impact
  momentum (0.53 with the projection's early touch): a finding, reported and guarded
  against getting worse;
- contact/normal cone: the face's normal, 0.029 (0.033 with the projection).
- a cube turned corner first onto a face (in.corner_face) touches no earlier than the
  corner meets the face, and couples half a spacing later (a finding, issue 12: the
  corner's real particles average the gaps of its faces), as with the projection; cubes
  turned 45 degrees meeting edge to edge (in.edge_cubes, parallel and crossed edges) alike;
  a cube's edge landing on a face couples on time at 30 degrees, 0.15 spacings late at 45
  (a finding), and cubes turned 30 degrees alike (their edges land on each other's faces)
  on time;
  a small face landing inside a larger one (in.footprint): the rebound does not depend on
  the size of a closed gap, a touching start differs (a finding).
About 45 seconds."""

import math
import esphtest as et

a = et.parse_args()
c = et.Checks("offset cubes: edges on faces")
INP = et.source_input(a, "in.offset_blocks")

# the region surfaces start one spacing (0.2 mm) apart and close at 50 m/s: 4.0 us
T_MEET = 0.2e-3 / 50.0 * 1e6
res = {}
SPACING_US = T_MEET    # the time to close one spacing [us]
for name, extra, shift in (("mean", "", 0.0), ("cone", "contact/normal cone", 0.0),
                           ("touching", "", 0.98),
                           ("projection", "contact/gap projection", 0.0),
                           ("plane", "contact/gap plane", 0.0),
                           ("plane_cone", "contact/gap plane contact/normal cone", 0.0)):
    s = et.summary(et.run(a, INP, {"pextra": extra, "shift": shift}, log=f"log.{name}"),
                   "OFFSET_BLOCKS")
    print(f"INFO {name}: {s}")
    res[name] = s
    c.less(f"{name}: momenta across cancel", abs(s["p1y_rel"] + s["p2y_rel"]), 1e-12,
           "pairwise forces")
    c.true(f"{name}: one contact episode", s["episodes"] == 1, "hit and rebound")
    if name.startswith("plane"):
        c.less(f"{name}: first touch not before the faces are 0.1 spacings apart [us]",
               -s["t_first"], -0.9 * T_MEET, f"the faces meet at {T_MEET:.2f} us; measured "
               "3.91 us: the faces' tangent planes bound the edges' gap")
    elif name == "projection":
        c.less(f"{name}: first touch not before the faces are 0.3 spacings apart [us]",
               -s["t_first"], -0.7 * T_MEET, f"the faces meet at {T_MEET:.2f} us; measured "
               "2.86 us (the projection on the tilted normal difference at the edges)")
    elif name != "touching":
        c.less(f"{name}: first touch within 0.03 spacings of the faces' meeting [spacings]",
               abs(T_MEET - s["t_first"]) / SPACING_US, 0.03,
               f"the faces meet at {T_MEET:.2f} us; the cells touch 0.02 spacings before, plus "
               "a step of 0.006 (measured 3.931 us: 0.017)")
# a gap start against a touching start (the faces 0.02 spacings apart): once the gap has
# closed, the same contact
g, t = res["mean"], res["touching"]
c.less("gap start against touching start: momentum across, relative",
       abs(g["p1y_rel"] / t["p1y_rel"] - 1.0), 0.01,
       "the same contact once the gap has closed (measured 8.6e-5; the projection alone: "
       f"{abs(res['projection']['p1y_rel'] / t['p1y_rel'] - 1.0):.2f})")
c.less("gap start against touching start: contact time, relative",
       abs(g["tc_us"] / t["tc_us"] - 1.0), 0.01,
       "measured 0 (the projection alone: "
       f"{abs(res['projection']['tc_us'] / t['tc_us'] - 1.0):.2f})")
c.less("gap start against touching start: axial momentum, relative",
       abs(g["p1x_rel"] / t["p1x_rel"] - 1.0), 0.01, "measured 6.3e-5")
# the touch on 2 and 4 ranks: the same pairs of bodies couple at the same step
for np_ in (2, 4):
    s = et.summary(et.run(a, INP, {"pextra": ""}, np=np_, log=f"log.mean_np{np_}"),
                   "OFFSET_BLOCKS")
    print(f"INFO mean np {np_}: {s}")
    c.true(f"np {np_}: first touch at the step of np 1", s["t_first"] == g["t_first"],
           "the touching pairs of bodies gathered on every rank")
    c.less(f"np {np_}: momentum across against np 1, relative",
           abs(s["p1y_rel"] / g["p1y_rel"] - 1.0), 1e-9, "round-off (printed to 7 digits)")
# a cube turned corner first (tests/physics/in.corner_face): the touch is decided by the
# particles' cells, turned with the cube, but the corner's real particles average the gaps
# of the three faces' boundary particles and couple late (issue 12, open; until 2026-12-06
# the scene's face lay half a spacing nearer than its comment said, and the late coupling
# passed for an exact one)
CF = et.source_input(a, "in.corner_face")
cf = {}
for name, extra in (("touch", ""), ("projection", "contact/gap projection")):
    cf[name] = et.summary(et.run(a, CF, {"pextra": extra}, log=f"log.corner_{name}"),
                          "CORNER_FACE")
    print(f"INFO turned corner, {name}: {cf[name]}")
late = (cf["touch"]["t_first"] - T_MEET) / SPACING_US
c.less("turned corner on a face: no touch before the meeting [spacings]", -late, 0.03,
       f"the corner meets the face at {T_MEET:.2f} us; the cells meet then")
c.less("turned corner on a face: first touch after the meeting (finding) [spacings]", late, 0.55,
       "exact 0; measured 0.494 (5.98 us): the corner's real particles average the gaps of "
       "its faces' boundary particles (pair_esph_solid.rst, Touch, open; issue 12)")
c.less("turned corner on a face: first touch not after the projection's [us]",
       cf["touch"]["t_first"] - cf["projection"]["t_first"], 1e-9,
       "the turned cells meet with the corner (measured the same step)")
c.true("turned corner on a face: one contact episode", cf["touch"]["episodes"] == 1,
       "hit and rebound")
c.less("turned corner on a face: energy drift, relative", abs(cf["touch"]["edrift"]), 1e-3,
       "contact keeps the energy (measured 1.2e-4)")
# edges (tests/physics/in.edge_cubes). Edges meeting edges: the edges' real particles average
# the gaps of the faces' boundary particles as the corner's do (issue 12, open): findings,
# guarded against getting worse; the point symmetry of those scenes keeps the momentum
# across. An edge landing on a face (cross 2: the second cube aligned with the box) couples
# when it meets it at 30 degrees, 0.15 spacings late at 45 (a finding). The cubes turned 30
# degrees alike do not meet edge to edge: each edge lands on the other's face when the faces
# with the normal (cos 30, sin 30, 0) come together, their centres a / cos 30 apart along x
# (a = 1.2 mm, the side): (2 (half + gap / 2) - a / cos 30) / (2 V) = 9.07 us
EC = et.source_input(a, "in.edge_cubes")
T30 = (2.0 * 0.6e-3 * (math.cos(math.pi / 6) + math.sin(math.pi / 6)) + 0.2e-3 -
       1.2e-3 / math.cos(math.pi / 6)) / 50.0 * 1e6
for name, var, t_meet, bound, measured, symmetric in (
        ("edges parallel", {}, T_MEET, 0.85, "0.80", True),
        ("edges crossed", {"cross": 1}, T_MEET, 0.95, "0.88", True),
        ("edge on a face, 45 degrees", {"cross": 2}, T_MEET, 0.2, "0.15 (4.59 us)", False),
        ("edge on a face, 30 degrees", {"cross": 2, "ang": 30}, T_MEET, 0.03, "0.009 (4.035 us)",
         False),
        ("cubes at 30 degrees, edges on faces", {"ang": 30}, T30, 0.03, "-0.02 (8.99 us)", False)):
    e = et.summary(et.run(a, EC, var, log="log." + name.replace(" ", "_").replace(",", "")),
                   "EDGE")
    print(f"INFO {name}: {e}")
    late = (e["t_first"] - t_meet) / SPACING_US
    c.less(f"{name}: no touch before the meeting [spacings]", -late, 0.03,
           f"they meet at {t_meet:.3f} us")
    c.less(f"{name}: first touch after the meeting [spacings]", late, bound,
           f"exact 0; measured {measured} (pair_esph_solid.rst, Touch; issue 12)")
    if symmetric:
        c.less(f"{name}: momentum across / impact momentum", abs(e["p1y_rel"]), 1e-12,
               "the scene's point symmetry: round-off")
    else:
        c.true(f"{name}: one contact episode", e["episodes"] == 1, "hit and rebound")
# a small face landing inside a larger one (tests/physics/in.footprint, 0.25 mm): once a gap
# has closed, its size does not matter; a touching start differs (a finding, issue 12: the
# particles under the small face's corners read gaps within 0.03 spacings of zero)
FP = et.source_input(a, "in.footprint")
fp = {g: et.summary(et.run(a, FP, {"gap": g}, log=f"log.footprint_{g}"), "FOOTPRINT")
      for g in (0.0, 0.3, 1.0)}
print(f"INFO footprint: {fp}")
c.less("footprint: rebound from gaps of 0.3 and 1 spacing, relative difference",
       abs(fp[0.3]["vA"] / fp[1.0]["vA"] - 1.0), 1e-3,
       "the contact of a closed gap does not remember its size (measured equal to the printed "
       "digits)")
c.less("footprint: rebound from a touching start against a gap (finding), / 50 m/s",
       abs(fp[0.0]["vA"] - fp[0.3]["vA"]) / 50.0, 0.06,
       "exact 0; measured 0.045 (-16.81 against -19.07 m/s; pair_esph_solid.rst, Touch, open)")
c.true("footprint: one contact episode from every start",
       all(v["episodes"] == 1 for v in fp.values()), "hit and rebound")
c.less("cone rule: momentum across / impact momentum", abs(res["cone"]["p1y_rel"]), 0.05,
       "exact 0; measured 0.033 (0.025 at 0.1 mm): the face's normal for an edge on a face")
c.less("mean normal: momentum across / impact momentum (finding)", abs(res["mean"]["p1y_rel"]),
       0.45, "exact 0; measured 0.38 (0.53 with the projection's early touch): the edges' "
       "bisector normals tilt the common normal (doc/hard_cases.md, findings; issue 12)")
c.less("cone rule against the mean normal: momentum across", abs(res["cone"]["p1y_rel"]),
       0.1 * abs(res["mean"]["p1y_rel"]), "the point of the cone rule")
c.less("contact/gap plane, mean normal: momentum across / impact momentum",
       abs(res["plane"]["p1y_rel"]), 0.4 * abs(res["projection"]["p1y_rel"]),
       "exact 0; measured 0.168 against the projection's 0.53: the edges no longer touch "
       "early, across the gap, along their tilted normals")
c.less("contact/gap plane with the cone rule: momentum across / impact momentum",
       abs(res["plane_cone"]["p1y_rel"]), 0.03, "exact 0; measured 0.024 (the projection 0.033)")
c.done()
