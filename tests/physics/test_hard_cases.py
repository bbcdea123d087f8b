#!/usr/bin/env python3
"""Hard cases beyond the paper's scene (coarse variants of examples/unequal_rods,
dissimilar_rods, fast_impact, offaxis_rods, free_bar). Theory: 1D bar / impedance
theory with the uniaxial-strain wave speed c_p = sqrt((K + 4/3 G)/rho0)."""
import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("hard cases")
MAT = {"iron": (7850.0, 80.0e9, 3574.0), "aluminum": (2703.0, 27.6e9, 5240.0)}


def cp(m):
    rho, G, c0 = MAT[m]
    return np.sqrt((rho * c0 ** 2 + 4.0 / 3.0 * G) / rho)


# 1. unequal rods: 10 mm striker on a 20 mm target (1D)
log = et.run(a, "unequal_rods/in.unequal_rods", {"dim": 1, "dx": 0.1, "out": 0, "tend": 12})
s = et.summary(log)
print("INFO unequal:", s)
tc = 2 * 10e-3 / cp("iron") * 1e6
# measured +4.3 %: after the release the striker rests on the target with a decaying,
# ringing contact force that stays above 1 % of the peak for ~0.17 us (30 steps)
c.near("unequal: contact time [us]", s["contact_time_us"], tc, 0.05 * tc,
       "bar theory 2 L_striker / c_p; 5 %: the force tail of the spread release")
c.near("unequal: striker after contact [m/s]", s["v_impactor"], 0.0, 0.5, "striker stops")
c.near("unequal: target mean velocity [m/s]", s["v_target"], 25.0, 0.5, "V L_striker / L_target")

# 2. dissimilar materials, both directions (1D): interface velocity Z_i V / (Z_i + Z_t)
for mi, mt in (("aluminum", "iron"), ("iron", "aluminum")):
    log = et.run(a, "dissimilar_rods/in.dissimilar_rods",
                 {"dim": 1, "dx": 0.1, "tend": 12, "mat_imp": mi, "mat_tgt": mt},
                 log=f"log.{mi}")
    s = et.summary(log)
    zi, zt = MAT[mi][0] * cp(mi), MAT[mt][0] * cp(mt)
    u = zi * 50.0 / (zi + zt)
    blocks = et.profiles(f"{a.lastdir}/profile.solid.1d.txt")
    prof = blocks[sorted(blocks)[1]]    # 3 us
    near = prof[np.abs(prof[:, 0]) < 5.0, 1]
    print(f"INFO {mi} on {mt}: interface velocity {near.mean():.3f} (theory {u:.3f}); summary {s}")
    c.near(f"{mi} on {mt}: interface velocity at 3 us [m/s]", near.mean(), u, 0.02 * u,
           "1D impedance-mismatch theory, Z = rho c_p; 2 % for the Mie-Grueneisen non-linearity")
    c.less(f"{mi} on {mt}: momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")
    c.less(f"{mi} on {mt}: energy drift [%]", abs(s["energy_drift_pct"]), 0.5, "REFERENCES 7")

# 3. fast impact, 200 and 500 m/s, 1D and coarse 3D: no interpenetration, no blow-up
for dim, dx, V in ((1, 0.1, 200), (1, 0.1, 500), (3, 0.25, 500)):
    log = et.run(a, "fast_impact/in.fast_impact",
                 {"dim": dim, "dx": dx, "V": V, "tend": 10, "out": 0, "thermo_every": 20},
                 log=f"log.fast{dim}{V}")
    s = et.summary(log)
    th = et.thermo(log)[-1]
    gmin = min(th["v_gapmm"])
    print(f"INFO fast {dim}D {V} m/s: {s}, min gap {gmin:.4f} mm")
    c.true(f"fast {dim}D {V} m/s: finite results", all(np.isfinite(list(s.values()))), "no blow-up")
    c.less(f"fast {dim}D {V} m/s: interpenetration [spacings]", -gmin / dx, 0.5,
           "facing surfaces never overlap by half a spacing")
    c.less(f"fast {dim}D {V} m/s: energy drift [%]", abs(s["energy_drift_pct"]), 1.0,
           "energy accounted for (AV heat included)")
    c.less(f"fast {dim}D {V} m/s: momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")

# 4. off-axis impact (target offset by R/2), coarse 3D, corrected gradient
log = et.run(a, "offaxis_rods/in.offaxis_rods", {"dx": 0.25, "tend": 12, "out": 0,
                                                 "thermo_every": 50}, log="log.offaxis")
s = et.summary(log)
th = et.thermo(log)[-1]
p0 = 50.0 * 7850 * (0.25e-3) ** 3 * 4160    # order of the impactor momentum
py = np.abs(np.array(th["c_pyimp"])).max()
Lz = np.array(th["v_Lz"])
print(f"INFO offaxis: {s}; max |p_y(impactor)| {py:.3e}, L_z {Lz[0]:.4e} -> {Lz[-1]:.4e}")
c.less("off-axis: momentum drift", s["momentum_drift_rel"], 1e-12, "pairwise forces")
# lateral momentum of the impactor: the pair forces across the interface are along the
# contact normal (frictionless by construction); the rods bend, their end faces tilt by a
# few degrees and the normal force gets a lateral component (measured 7 % of p0)
print(f"INFO off-axis: lateral impulse / axial momentum {py / p0:.4f}")
c.less("off-axis: lateral impulse / axial momentum", py / p0, 0.15,
       "end-face tilt of the bending rods (a few degrees)")
c.less("off-axis: energy drift [%]", abs(s["energy_drift_pct"]), 0.5, "REFERENCES 7")
c.less("off-axis: angular momentum drift (relative)", abs(Lz[-1] - Lz[0]) / abs(Lz[0]), 1e-2,
       "SPH stress forces are not central: approximate, REFERENCES 7")

# 4b. a rod hitting a block face tilted by 30 degrees (coarse 3D, staircase face)
log = et.run(a, "oblique_rod/in.oblique_rod", {"dx": 0.2}, log="log.orod")
s = et.summary(log, "OBLIQUE_ROD")
print(f"INFO oblique rod: {s}")
# at 0.2 mm the protruding lattice step at the tip of the rim touches 0.5 us before the
# rest of the rim, is pushed back by 0.07 spacings and touches again (12 pairs, a precursor
# episode); chatter would give many episodes
c.less("oblique rod: contact episodes", s["episodes"], 2.5, "hit and rebound, plus the precursor touch of the rim's lattice step")
c.less("oblique rod: momentum drift", s["momentum_drift_rel"], 1e-12, "round-off")
c.less("oblique rod: energy drift [%]", abs(s["energy_drift_pct"]), 0.5, "REFERENCES 7")
# frictionless physics gives mu_eff = 0; the staircase face of a lattice body gives noisy
# normals and a lattice friction of 0.015-0.17 (0.077 here at 0.2 mm, 0.165 at 0.25, 0.015
# at 0.15; doc/hard_cases.md): reported as a finding, guarded against getting worse
c.less("oblique rod: lattice friction |J_t|/|J_n| of the staircase face", s["mu_eff"], 0.12,
       "measured 0.05-0.09; exact 0 (see doc/hard_cases.md)")

# 6. a spinning block (corrected gradient) hitting a block at rest, coarse 3D
log = et.run(a, "spinning_block/in.spinning_block", {"dx": 0.2}, log="log.spin")
s = et.summary(log, "SPINNING")
th = et.thermo(log)[-1]
px = np.array(th["c_px[1]"])
Lz = np.array(th["v_Lz"])
print(f"INFO spinning block: {s}; L_z {Lz[0]:.4e} -> {Lz[-1]:.4e}")
c.true("spinning block: one contact episode, the blocks separate",
       s["episodes"] == 1 and s["vxB"] > s["vxA"], "contact with rotating normals")
c.less("spinning block: momentum drift", abs(px[-1] - px[0]) / px[0], 1e-12, "round-off")
c.less("spinning block: energy drift [%]", abs(s["energy_drift_pct"]), 0.5, "REFERENCES 7")
# angular momentum about the origin (exact: conserved). With the corrected gradient the
# bodies' own stress forces are not central (measured +22.8 % by 14 us, growing in free
# flight); with gradient bonet/lok they carry no torque, and only the contact changes L_z:
# its pair forces act along the common normal between particles that are offset along the
# face, a couple that does not cancel where the contact patch is not symmetric
# gradient torquefree (the plain force less its torque) likewise
for grad, bound, measured in (("bonet/lok", 0.02, "0.79 %"), ("torquefree", 0.05, "2.8 %")):
    log = et.run(a, "spinning_block/in.spinning_block", {"dx": 0.2, "grad": grad,
                                                         "thermo_every": 20},
                 log="log.spin_" + grad.replace("/", ""))
    sb = et.summary(log, "SPINNING")
    th = et.thermo(log)[-1]
    Lz, npair = (np.array(th[k]) for k in ("v_Lz", "f_int[2]"))
    touch = np.nonzero(npair > 0)[0]
    before = np.abs(Lz[:touch[0]] / Lz[0] - 1.0).max()
    after = Lz[touch[-1] + 1:] / Lz[0] - 1.0
    print(f"INFO spinning block {grad}: {sb}; L_z change before contact {before:.2e}, "
          f"after {after[0]:.4e} .. {after[-1]:.4e}")
    c.less(f"spinning block {grad}: |L_z change| in free flight before contact", before, 1e-12,
           "torque-free stress forces: round-off")
    c.less(f"spinning block {grad}: L_z spread after separation", np.ptp(after), 1e-12,
           "free flight again: round-off")
    c.less(f"spinning block {grad}: |L_z change| by the contact", abs(after[-1]), bound,
           f"the contact's couple only (measured {measured}, against 22.8 % with gradient "
           "corrected)")
    c.less(f"spinning block {grad}: energy drift [%]", abs(sb["energy_drift_pct"]), 0.5,
           "REFERENCES 7")

# 9 (part). elastic-perfectly-plastic iron (von Mises, Y = 0.5 GPa), 1D uniaxial strain,
# 50 m/s: a two-wave structure. Elastic precursor at c_p with particle velocity
# u_HEL = c_p Y / (2G) = 16.05 m/s (Hugoniot elastic limit of uniaxial strain), plastic
# wave at the bulk speed c_b = sqrt(K/rho0) = c0 = 3574 m/s up to V/2 = 25 m/s.
log = et.run(a, "rod_impact/in.rod_impact", {"dim": 1, "dx": 0.05, "tend": 3, "yield": 0.5e9,
                                             "contact": "off", "thermo_every": 200},
             log="log.plastic")
s = et.summary(log)
blocks = et.profiles(f"{a.lastdir}/profile.off.1d.txt")
prof = blocks[max(blocks)]
x, v = prof[:, 0], prof[:, 1]
t = 3.0e-6
uhel = cp("iron") * 0.5e9 / (2 * 80.0e9)
pre = v[(x > 12.0) & (x < 14.0)].mean()
xpl = x[x > 0][np.argmax(v[x > 0] < 0.5 * (25.0 + uhel))]
print(f"INFO plastic: precursor {pre:.3f} m/s (theory {uhel:.3f}), plastic front {xpl:.2f} mm "
      f"(c0 t = {3574.0 * t * 1e3:.2f}), energy drift {s['energy_drift_pct']} %")
c.near("plastic: elastic precursor velocity [m/s]", pre, uhel, 0.01 * uhel,
       "u_HEL = c_p Y/(2G); 1 % for the discretisation")
c.near("plastic: plastic front at 3 us [mm]", xpl, 3574.0 * t * 1e3, 0.03 * 3574.0 * t * 1e3,
       "bulk speed c0 t; +1.7 % expected from the Mie-Grueneisen stiffening (K' = 6.7 at eta ~ 0.5 %)")
c.near("plastic: plateau behind the plastic wave [m/s]", v[(x > 1.0) & (x < 8.0)].mean(), 25.0,
       0.05, "V/2 by symmetry")
c.less("plastic: energy drift [%]", abs(s["energy_drift_pct"]), 0.5,
       "plastic work goes into the internal energy")

# 8. long run: free bar, 1e5 steps (with the default viscosity). Without viscosity the
# predictor-corrector stress update is weakly unstable at CFL 0.3 (blow-up after ~8000
# steps; stable at CFL 0.1): documented in doc/hard_cases.md, not asserted here.
log = et.run(a, "free_bar/in.free_bar", {"nsteps": 100000}, log="log.bar")
s = et.summary(log, "FREE_BAR")
d = np.loadtxt(f"{a.lastdir}/free_bar.end", skiprows=9)
xs = np.sort(d[:, 1])
gap = np.diff(xs).min() / 0.2e-3
print(f"INFO free bar: {s}, smallest spacing {gap:.3f} dx")
c.true("free bar: no NaN after 1e5 steps", np.all(np.isfinite(d)), "stable")
c.less("free bar: energy drift [%]", abs(s["energy_drift_pct"]), 0.1,
       "compatible energy equation; the viscosity turns vibration into heat")
c.less("free bar: clumping (1 - smallest spacing / dx)", 1 - gap, 0.1,
       "no pairing: particles stay about one spacing apart")
c.done()
