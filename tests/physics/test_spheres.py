#!/usr/bin/env python3
"""Two iron spheres (R = 1 mm, 25 m/s each, head-on) built on one cubic lattice
(tests/physics/in.lattice_spheres, 0.2 mm: R/dx = 5, about 500 particles each). Exact
frictionless contact: no lateral momentum, no spin, Hertz's contact time.
- a lattice mirror-symmetric about both centres: symmetry holds to round-off, and the
  contact time is Hertz's;
- a lattice offset by (0.3, 0.2, 0.1) spacings: the spheres are not mirror images, their
  faces are staircases, and they leave with lateral momentum and spin (an open problem of
  issues 12 and 17, reported here and guarded against getting worse).
- the normals of the regions the spheres were cut from (fix esph/boundary region).
- the regions' normals turned with each sphere's rigid spin (fix esph/boundary turn body) at
  R/dx = 15: lateral momentum below 1e-3 of the axial one (issue 12), on 1 and 2 ranks.
About 3 minutes."""
import math

import esphtest as et

a = et.parse_args()
c = et.Checks("lattice spheres")
INP = et.source_input(a, "in.lattice_spheres")


def case(name, **var):
    s = et.summary(et.run(a, INP, var, log=f"log.{name}"), "SPHERES")
    print(f"INFO {name}: {s}")
    return s


# Hertz (Johnson 1985): t = 2.87 (m*^2 / (R* E*^2 v))^(1/5), m* = m/2, R* = R/2,
# E* = E / (2 (1 - nu^2)), v = 50 m/s closing speed; iron of the seed paper
rho0, G, K = 7850.0, 80.0e9, 7850.0 * 3574.0**2
E = 9.0 * K * G / (3.0 * K + G)
nu = (3.0 * K - 2.0 * G) / (2.0 * (3.0 * K + G))
R = 1.0e-3
m = 4.0 / 3.0 * math.pi * R**3 * rho0
tH = 2.87 * ((m / 2) ** 2 / (R / 2 * (E / (2 * (1 - nu**2))) ** 2 * 50.0)) ** 0.2 * 1e6

sym = case("sym", ox=0.0, oy=0.0, oz=0.0)
c.less("mirror-symmetric lattice: lateral momentum / axial", max(sym["lat1_rel"], sym["lat2_rel"]),
       1e-12, "mirror symmetry about the spheres' centres: round-off")
c.less("mirror-symmetric lattice: spin [rad/s]", max(sym["spin1"], sym["spin2"]), 1.0,
       "mirror symmetry: none")
c.near("mirror-symmetric lattice: contact time [us] vs Hertz", sym["tc_us"], tH, 0.1 * tH,
       f"Hertz {tH:.3f} us; 10 %: five particles per radius, the contact patch is a few facets")
c.true("mirror-symmetric lattice: one contact episode", sym["episodes"] == 1, "hit and rebound")

off = case("offset", fit=0)
c.less("offset lattice: |lateral of sphere 1 - lateral of sphere 2| / axial",
       abs(off["lat1_rel"] - off["lat2_rel"]), 1e-12,
       "pairwise forces: the lateral momenta cancel to round-off")
c.less("offset lattice: lateral momentum / axial (finding)", off["lat1_rel"], 0.05,
       "measured 3.8e-2 at 0.2 mm; exact 0: staircase faces and facet contact (issue 12)")
fit = case("offset_fit8", fit=8)
c.less("offset lattice, fit 8: lateral momentum / axial (finding)", fit["lat1_rel"], 0.006,
       "measured 4.0e-3: normals fitted to the sphere")
bl = case("offset_bonet_lok", grad="bonet/lok", fit=0)
c.less("offset lattice, bonet/lok: lateral momentum / axial (finding)", bl["lat1_rel"], 0.05,
       "measured 3.7e-2: the lateral push is the contact's, not the bodies' stress forces")
# the spin is the axial force's couple, not a lateral push: with a lattice that is
# mirror-symmetric in x only (the spheres mirror images of each other across the contact
# plane, each a staircase in y) there is no lateral momentum, yet the spheres spin, equal
# and opposite (the centre of pressure of the two pole facets lies off the line of centres)
xm = case("xmirror", ox=0.0, oy=0.2, oz=0.0)
c.less("x-mirror lattice: lateral momentum / axial", max(xm["lat1_rel"], xm["lat2_rel"]), 1e-12,
       "mirror symmetry across the contact plane: round-off")
c.near("x-mirror lattice: spin of sphere 2 vs sphere 1 [rad/s]", xm["spin2"], xm["spin1"],
       1e-6 * xm["spin1"] + 0.1, "mirror images: equal spins (printed to 0.1 rad/s)")
# ... and it converges with the resolution: rim speed over impact speed w R / V at R/dx = 5
# and 10 (R 2 mm at the same spacing: the same scene at half the spacing, scaled)
w5 = max(fit["spin1"], fit["spin2"]) * 1.0e-3 / 25.0
big = case("offset_fit8_R2", fit=8, R=2.0, tend=13.0)
w10 = max(big["spin1"], big["spin2"]) * 2.0e-3 / 25.0
c.less("offset lattice, fit 8: spin w R / V at R/dx = 10 over R/dx = 5", w10 / w5, 0.6,
       f"{w5:.3f} -> {w10:.3f}; exact 0, first order in dx / R gives 0.5 (measured 0.37; "
       "0.034 at R/dx = 20, doc/hard_cases.md 4)")
c.less("offset lattice, fit 8, R/dx = 10: lateral momentum / axial (finding)", big["lat1_rel"],
       0.01, "measured 7.7e-3: the fitted and spin-rotated normals' error does not fall with "
       "resolution (doc/hard_cases.md 4)")
# the normals of the regions the spheres were cut from (fix esph/boundary region): exact
# start normals; the lateral momentum falls, not to 0 (the normals then turn with the
# interpolated spin, doc/hard_cases.md 4); the same on 2 ranks
REG = "region s1 region s2"
reg = case("offset_region", fit=0, bextra=REG)
c.less("offset lattice, region normals: lateral momentum / axial (finding)", reg["lat1_rel"],
       0.8 * fit["lat1_rel"], f"measured 2.5e-3 against fit 8's {fit['lat1_rel']:.1e} (the "
       "bound: clearly below fit 8): the start normals exact instead of fitted to the "
       "staircase")
c.true("offset lattice, region normals: one contact episode", reg["episodes"] == 1,
       "fit 8 gives two at this spacing")
reg2 = et.summary(et.run(a, INP, dict(fit=0, bextra=REG), np=2, log="log.offset_region_np2"),
                  "SPHERES")
c.less("offset lattice, region normals: np 2 vs np 1 (lateral momentum)",
       abs(reg2["lat1_rel"] - reg["lat1_rel"]), 1e-9 + 1e-6 * reg["lat1_rel"],
       "the same boundary particles and normals on any rank count; round-off")
# fix esph/boundary turn body: the regions' normals turned with each sphere's rigid spin
# (omega = I^-1 L of its real particles) instead of the spin interpolated at every boundary
# particle, which on a staircase follows the dents of the few facet particles. At R/dx = 15
# (R 3 mm at 0.2 mm: 33 000 particles, 1620 steps), two lattice offsets; the same with turn
# spin as the contrast. Measured (lateral / axial; spin as rim speed w R / V):
#   R/dx        5       10      12.5    15              20
#   turn body   6.4e-3  3.2e-3  2.4e-3  8.3e-5, 5.2e-4  6.0e-4, 6.4e-4, 1.6e-4
#   turn spin   2.5e-3  3.1e-3  -       3.0e-3, 1.3e-3  4.9e-3
#   w R / V     0.22    0.074   0.10    0.028, 0.046    0.025, 0.011, 0.0075
# (R/dx = 20: offsets (0.3, 0.2, 0.1), (0.3, 0.25, 0), (0.1, 0.35, 0.2); doc/hard_cases.md)
TB = "region s1 region s2 turn body"
R15 = dict(fit=0, R=3.0, tend=18.0)
for name, lo in (("a", dict(ox=0.3, oy=0.2, oz=0.1)), ("b", dict(ox=0.1, oy=0.35, oz=0.2))):
    tb = case(f"turn_body_R15{name}", bextra=TB, **R15, **lo)
    sp = case(f"turn_spin_R15{name}", bextra="region s1 region s2", **R15, **lo)
    lab = f"R/dx = 15, offset ({lo['ox']}, {lo['oy']}, {lo['oz']})"
    c.less(f"{lab}, turn body: lateral momentum / axial", tb["lat1_rel"], 1.0e-3,
           "issue 12's bound; exact 0, measured 8.3e-5 / 5.2e-4 (the error of the start normals "
           "is gone with the regions', what is left is the facets' contact)")
    c.less(f"{lab}, turn body against turn spin: lateral momentum", tb["lat1_rel"],
           0.5 * sp["lat1_rel"], f"turn spin {sp['lat1_rel']:.1e}: the interpolated spin of "
           "the facet particles turns the normals off the surface")
    c.true(f"{lab}, turn body: one contact episode", tb["episodes"] == 1, "hit and rebound")
    w = max(tb["spin1"], tb["spin2"]) * 3.0e-3 / 25.0
    c.less(f"{lab}, turn body: spin w R / V", w, 0.07,
           f"measured {w:.3f}; exact 0, first order in dx / R (0.22 at R/dx = 5): the centre "
           "of pressure of a contact patch a few particles wide lies off the line of centres")
    if name == "a":
        tb2 = et.summary(et.run(a, INP, dict(bextra=TB, **R15, **lo), np=2,
                                log="log.turn_body_R15a_np2"), "SPHERES")
        c.less(f"{lab}, turn body: np 2 vs np 1 (lateral momentum / axial)",
               abs(tb2["lat1_rel"] - tb["lat1_rel"]), 1e-6 * tb["lat1_rel"],
               "the bodies' spins are sums over ranks: round-off, amplified over 1600 steps "
               "of contact (printed to 11 digits)")
        c.less(f"{lab}, turn body: np 2 vs np 1 (spin) [rad/s]",
               abs(tb2["spin1"] - tb["spin1"]), 1e-6 * tb["spin1"], "round-off")
print(f"INFO spins [rad/s]: offset {off['spin1']:.0f}/{off['spin2']:.0f}, fit 8 "
      f"{fit['spin1']:.0f}/{fit['spin2']:.0f}, bonet/lok {bl['spin1']:.0f}/{bl['spin2']:.0f} "
      "(exact 0; a sphere's spin of 1000 rad/s is a rim speed of 1 m/s)")
c.done()
