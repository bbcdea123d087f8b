#!/usr/bin/env python3
"""Contact algorithm on 1D rods (cheap): an initial gap is felt only when it closes,
touching rods at rest stay at rest, the result does not depend on the initial gap,
and the bare criterion (31) of the paper against the default rule."""
import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("contact in 1D: gap, rest, rules")
base = {"dim": 1, "dx": 0.1, "tend": 12.0, "thermo_every": 100, "out": 0}

ref = et.run(a, "rod_impact/in.rod_impact", base, log="log.gap0")
s0 = et.summary(ref)

# gap of 2 spacings: the rods meet at t = 0.2 mm / 50 m/s = 4 us
for gap, tmeet in ((2.0, 4.0e-6), (0.5, 1.0e-6)):
    log = et.run(a, "rod_impact/in.rod_impact", dict(base, gap=gap, tend=12.0 + tmeet * 1e6),
                 log=f"log.gap{gap}")
    first = et.summary(log, "ROD_IMPACT_CONTACT")["first_contact_us"]
    dt = et.thermo(log)[-1]["v_tus"][1] / 100.0    # thermo every 100 steps
    # the gate opens when the gap is below gap/tol = 1e-3 h (0.1 um: 0.002 us at 50 m/s)
    c.near(f"gap {gap} dx: first contact [us]", first, tmeet * 1e6, 2.0 * dt + 0.002,
           "t = gap / V to within two steps and the gap tolerance")
    th = et.thermo(log)[-1]
    t = np.array(th["v_tus"])
    vt = np.array(th["c_vtgt"])
    c.less(f"gap {gap} dx: target untouched before contact [m/s]",
           np.abs(vt[t < tmeet * 1e6 - 2 * dt]).max(), 1e-300, "no force across an open gap")
    s = et.summary(log)
    c.near(f"gap {gap} dx: contact time [us]", s["contact_time_us"], s0["contact_time_us"],
           2.0 * dt, "no sensitivity to the initial gap (hard case 7)")
    c.near(f"gap {gap} dx: final impactor velocity [m/s]", s["v_impactor"], s0["v_impactor"],
           0.02, "no sensitivity to the initial gap")

# touching rods at rest stay at rest, with no interaction across the interface
log = et.run(a, "rod_impact/in.rod_impact", dict(base, V=0.0, tend=3.0), log="log.rest")
th = et.thermo(log)[-1]
c.less("rods at rest: kinetic energy [J]", max(th["KinEng"]), 1e-300,
       "zero stress, zero velocity: exactly nothing happens")
c.less("rods at rest: interacting pairs", max(th["f_int[2]"]), 0.5,
       "neither approaching nor compressed: no contact")

# the bare criterion (31): contact only while approaching
log = et.run(a, "rod_impact/in.rod_impact", dict(base, contact="paper"), log="log.paper")
sp = et.summary(log, "ROD_IMPACT")
cp = et.summary(log, "ROD_IMPACT_CONTACT")
print("INFO paper rule:", sp, cp)
print("INFO solid rule:", s0, et.summary(ref, "ROD_IMPACT_CONTACT"))
c.true("paper rule: the rods separate (target faster than impactor)",
       sp["v_target"] > sp["v_impactor"] + 40.0, "criterion (31) releases on separation")
c.done()
