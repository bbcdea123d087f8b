#!/usr/bin/env python3
"""fix esph/integrate scheme staggered: an integrator that is stable without the linear
artificial viscosity (doc/fix_esph_integrate.rst, doc/visc_switch.md section 4).

The predicted scheme advances density, stress and energy with the rates of the predicted
end-of-step state; as a linear map on one elastic mode (v' = w s, s' = -w v) its
amplification factor with the last rates in the prediction (extrapolate no, the former
default) exceeds 1 at every w dt (1 + c (w dt)^4: 1.0004 at 0.2, 1.009 at 0.4): without the
alpha term of the viscosity every mode grows. The default prediction extrapolates the rates
of the last two computations with the weight that cancels c (1.0000057 at 0.2, 1.0093 at
0.6; modes above about 0.65 still grow): checked here against the former one. The staggered scheme finds the rates at
v^(n+1/2) before the drift (a second pass over the neighbours), advances the state to n+1
and then computes the forces: the leapfrog of the first-order system, |G| = 1 up to w dt =
2, and the internal energy takes the work of the forces of both ends of the step.

1. 1D rod impact (examples/rod_impact, iron, 50 m/s, dx 0.1 mm, the example's step 0.3
   h / (c_L + V)) with visc 0 1 (no linear term): predicted with extrapolate no +52.9 %
   (unstable, checked > 10 % as the contrast), predicted (default) 0.015 % (checked
   < 0.05 %), staggered 0.016 % (checked < 0.05 %); momentum split exact; residual impactor velocity
   0.424 m/s against 0.843 with the paper's viscosity (checked < 0.6 of it).
   With visc 0 0 (no viscosity at all; stress-free rods touching at t = 0): contact time
   7.794 us, energy 0.013 %; before, no pair had a force, so none interacted and the
   rods passed through each other.
2. The viscosity switch with alpha_min 0.01 at dx 0.05 mm: predicted +286 % (unstable;
   not run here), staggered 0.020 % (checked < 0.05 %), residual 0.264 m/s.
3. Free bar (examples/free_bar, 4000 steps) with visc 0 0: predicted with extrapolate no
   energy x1500 (checked > 100 % as the contrast), predicted (default) 0.009 % and
   staggered -0.026 % (checked |drift| < 0.1 %). Over
   1e5 steps visc 0 0 is not stable even staggered (a mode grows after ~3e4 steps: the
   neutral stability is that of the linear problem); visc 0 1 staggered: -0.014 % after
   1e5 steps (checked < 0.1 %).
4. 3D rods (the paper's scene at 0.25 mm, visc 0 1): final impactor mean velocity 0.742
   m/s against 1.157 with the default and 0.63 of the 3D reference (checked < 0.85),
   energy 0.022 % (checked < 0.1 %); np 2 prints the same ROD_IMPACT line (1e-10)."""
import math

import esphtest as et

a = et.parse_args()
c = et.Checks("integrator: the staggered scheme without linear viscosity")
ST = "scheme staggered"
# no linear viscosity, the quadratic term as the paper has it (the figures below are of
# this form; the default reconstruction would act on the quadratic term too)
V01 = "visc 0 1 0.1 visc/recon off"
ROD = "rod_impact/in.rod_impact"


def rod(extra_pair, extra_int, dim=1, dx=0.1, np=1, tag=""):
    return et.summary(et.run(a, ROD, {"dim": dim, "dx": dx, "tend": 12.0, "out": 0,
                                      "thermo_every": 1000, "pair_extra": extra_pair,
                                      "int_extra": extra_int}, np=np,
                             log=f"log.rod.{dim}.{dx}.{tag}.{np}"))


# --- 1. no linear viscosity, the example's time step ---
pold = rod(V01, "extrapolate no", tag="pold")
pred = rod(V01, "", tag="pred")
stag = rod(V01, ST, tag="stag")
paper = rod("visc/recon off", "", tag="paper")
print("INFO 1D 0.1 mm visc 0 1: predicted, extrapolate no", pold)
print("INFO 1D 0.1 mm visc 0 1: predicted", pred)
print("INFO 1D 0.1 mm visc 0 1: staggered", stag)
c.less("predicted scheme, extrapolate no, visc 0 1: energy drift grows (negated) [%]",
       -pold["energy_drift_pct"], -10.0, "measured +52.9 %: the scheme amplifies every mode")
c.less("predicted scheme (extrapolated), visc 0 1: |energy drift| [%]",
       abs(pred["energy_drift_pct"]), 0.05,
       "measured 0.015 %: the extrapolation cancels the amplification of the smooth modes")
c.less("staggered, visc 0 1: |energy drift| [%]", abs(stag["energy_drift_pct"]), 0.05,
       "measured 0.016 %; the paper viscosity with the default scheme 0.005 %")
c.near("staggered, visc 0 1: momentum split [m/s]", stag["v_impactor"] + stag["v_target"],
       50.0, 1e-9, "equal masses, exact")
c.less("staggered, visc 0 1: residual / paper viscosity's", stag["v_impactor"] /
       paper["v_impactor"], 0.6, "measured 0.424 / 0.843 m/s")
c.near("staggered, visc 0 1: contact time [us]", stag["contact_time_us"], 7.75, 0.01 * 7.75,
       "measured 7.794; the model's non-linear value 7.743-7.751 (REFERENCES 1c), 1 %")

# no viscosity at all: stress-free bodies touching at the start must still collide (the
# solid rule lets a pair without force interact while it approaches)
nov = rod("visc 0 0 0.1", ST, tag="novisc")
print("INFO 1D 0.1 mm visc 0 0 staggered", nov)
c.near("staggered, visc 0 0: contact time [us]", nov["contact_time_us"], 7.75, 0.01 * 7.75,
       "measured 7.794 (before the gate fix the rods passed through each other: no contact)")
c.less("staggered, visc 0 0: |energy drift| [%]", abs(nov["energy_drift_pct"]), 0.05,
       "measured 0.013 %")

# --- 2. the viscosity switch with a low floor ---
sw = rod("visc/switch 0.01 0.2 visc/recon off", ST, dx=0.05, tag="sw")
print("INFO 1D 0.05 mm visc/switch 0.01 0.2 staggered", sw)
c.less("staggered, visc/switch 0.01: |energy drift| [%]", abs(sw["energy_drift_pct"]), 0.05,
       "measured 0.020 % (the predicted scheme: +286 %)")

# --- 3. free bar without any viscosity ---
fb = {}
for name, ie in (("predicted_old", "extrapolate no"), ("predicted", ""), ("staggered", ST)):
    fb[name] = et.summary(et.run(a, "free_bar/in.free_bar",
                                 {"nsteps": 4000, "alpha": 0, "beta": 0, "int_extra": ie},
                                 log=f"log.free_bar.{name}"), key="FREE_BAR")
    print(f"INFO free bar visc 0 0 {name}", fb[name])
pd = fb["predicted_old"]["energy_drift_pct"]
c.less("free bar visc 0 0, predicted, extrapolate no: energy grows (negated) [%]",
       -(pd if math.isfinite(pd) else 1e9), -100.0, "measured x1500 after 4000 steps")
c.less("free bar visc 0 0, predicted (extrapolated): |energy drift| [%]",
       abs(fb["predicted"]["energy_drift_pct"]), 0.1, "measured 0.009 %")
c.less("free bar visc 0 0, staggered: |energy drift| [%]",
       abs(fb["staggered"]["energy_drift_pct"]), 0.1, "measured -0.026 %")
# hard case 8, the 1e5-step run, with the quadratic term only (visc 0 0 is not for long
# runs: after ~3e4 steps a mode grows, kinetic energy 4.4x the initial energy at 7e4)
fbl = et.summary(et.run(a, "free_bar/in.free_bar",
                        {"nsteps": 100000, "alpha": 0, "beta": 1, "int_extra": ST},
                        log="log.free_bar.long"), key="FREE_BAR")
print("INFO free bar visc 0 1 staggered 1e5 steps", fbl)
c.less("free bar visc 0 1, staggered, 1e5 steps: |energy drift| [%]",
       abs(fbl["energy_drift_pct"]), 0.1, "measured -0.014 %")

# --- 4. 3D rods ---
r1 = rod(V01, ST, dim=3, dx=0.25, tag="3d")
r2 = rod(V01, ST, dim=3, dx=0.25, np=2, tag="3d")
print("INFO 3D 0.25 mm visc 0 1 staggered np 1", r1)
c.less("3D 0.25 mm staggered visc 0 1: final impactor velocity [m/s]", r1["v_impactor"], 0.85,
       "measured 0.742; default 1.157; 3D reference 0.63")
c.less("3D 0.25 mm staggered visc 0 1: |energy drift| [%]", abs(r1["energy_drift_pct"]), 0.1,
       "measured 0.022 %")
for k in ("contact_time_us", "v_impactor", "v_target", "energy_drift_pct"):
    c.near(f"3D np 2 = np 1: {k}", r2[k], r1[k], 1e-10 * max(1.0, abs(r1[k])), "round-off")
c.done()
