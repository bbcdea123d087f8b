#!/usr/bin/env python3
"""3D rod impact at a coarse spacing (dx = h = 0.25 mm, R/4), with the contact algorithm
(default rule), with the paper's bare criterion (31), and without contact (traditional SPH).
References (shared/REFERENCES.md 1(d)): 3D elasticity gives t_c = 8.23 us and mean
velocities 0.63 / 49.37 m/s after separation; bar theory 8.139 us and 0 / 50 m/s."""
import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("3D rods, coarse: contact vs traditional SPH")
base = {"dim": 3, "dx": 0.25, "tend": 14.0, "thermo_every": 50, "out": 0}

log = et.run(a, "rod_impact/in.rod_impact", base, log="log.solid")
s = et.summary(log)
sc = et.summary(log, "ROD_IMPACT_CONTACT")
print("INFO solid:", s, sc)
th = et.thermo(log)[-1]
t = np.array(th["v_tus"])
# Tolerances at R/4: measured contact times 8.84 / 8.33 us at dx = 0.25 / 0.1 mm converge
# on 8.23 us from above (at R/4 the rod has 4 particles per radius; the contact rule's
# coupling band of 0.05 h adds about 0.1 us at 0.25 mm, 8.73 us with a band of 0.01 h), so
# 8 % here, and the 0.2 mm run must be closer. The residual impactor velocity is 3D
# lateral inertia (0.63) plus the AV-spread release (~1 m/s at this h, see test_rod1d),
# so below 2 m/s; after separation the means must stay constant.
c.near("contact time [us]", s["contact_time_us"], 8.23, 0.08 * 8.23,
       "3D elastic 8.23 us; coarse R/4 resolution, converging from above")
s2 = et.summary(et.run(a, "rod_impact/in.rod_impact", dict(base, dx=0.2, thermo_every=500),
                       log="log.solid02"))
c.less("contact time converges: |t(0.2 mm) - 8.23| < |t(0.25 mm) - 8.23|",
       abs(s2["contact_time_us"] - 8.23), abs(s["contact_time_us"] - 8.23), "resolution")
c.less("impactor mean velocity after separation [m/s]", s["v_impactor"], 2.0,
       "0.63 (3D elasticity) + AV residual at R/4")
c.near("momentum split [m/s]", s["v_impactor"] + s["v_target"], 50.0, 1e-9, "equal masses")
after = t > s["contact_time_us"] + 1.0
vi = np.array(th["c_vimp"])[after]
c.less("impactor velocity change after separation [m/s]", vi.max() - vi.min(), 0.05,
       "free flight: no force across the opened gap")
c.true("the rods have separated (gap > 0)", sc["gap_mm"] > 0.0, "gap opens at 50 m/s")
c.less("energy drift [%]", abs(s["energy_drift_pct"]), 0.5, "REFERENCES 7 acceptance")
c.less("momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")

log = et.run(a, "rod_impact/in.rod_impact", dict(base, contact="off"), log="log.off")
so = et.summary(log)
tho = et.thermo(log)[-1]
print("INFO off:", so)
# traditional SPH: the kernel couples the rods like one body and they cluster (Fig. 2)
c.less("without contact: target slower than 45 m/s", so["v_target"], 45.0,
       "artificial tension holds the rods together")
c.less("without contact: facing surfaces stay within one spacing [mm]",
       max(tho["v_gapmm"]), 0.25, "the rods stick")

# the paper's bare criterion (31) pumps energy under sustained compression (doc/hard_cases.md
# 2); to 8 us (later the rods fly apart and particles leave the box)
log = et.run(a, "rod_impact/in.rod_impact", dict(base, contact="paper", tend=8.0),
             log="log.paper")
sp = et.summary(log)
print("INFO paper:", sp, et.summary(log, "ROD_IMPACT_CONTACT"))
c.less("contact paper: energy grows (finding)", -sp["energy_drift_pct"], -50.0,
       "the documented instability of eq. (31) in 3D: measured +413 % by 8 us")
c.done()
