#!/usr/bin/env python3
"""The Morris-Monaghan viscosity switch (pair_style esph/solid ... visc/switch alpha_min l,
doc/visc_switch.md): per-particle alpha_i that decays to alpha_min away from compression.

1. 1D rod impact (examples/rod_impact -var dim 1, iron, 50 m/s): the residual impactor
   velocity after separation (exact 0) at dx = 0.2, 0.1, 0.05, 0.025 mm, with and without
   the switch. Measured (doc/visc_switch.md): paper viscosity 1.194 / 0.843 / 0.599 / 0.430
   m/s (order 0.49), switch 0.1 0.2: 0.661 / 0.430 / 0.289 / 0.203 m/s (order 0.57). The
   issue's goal, order >= 0.9, is NOT reached: at 50 m/s the strain is 0.5 %, the source
   max(-div v, 0) (alpha - alpha_i) is ~1 % of the decay rate l c / h, so alpha_i stays at
   alpha_min and the scheme behaves as a constant alpha = beta = 0.1 (measured 0.610 / 0.411
   m/s), whose front still spreads diffusively (~h^0.5). Checked: order >= 0.52 (measured
   0.567, without the switch 0.49, so the check separates them), the residual at most 0.6
   of the paper viscosity's at every dx (measured 0.47-0.55).
2. Hard case 3 (examples/fast_impact, 1D, 500 m/s, dx 0.2 mm) with the switch: finite,
   momentum split exact, energy drift below 0.5 % (measured 0.116 %, without 0.013 %).
3. Smooth wave (examples/free_bar, 4000 steps): the fundamental mode keeps its kinetic
   energy: ke_fraction 0.916 with the switch against 0.471 with the paper viscosity (same
   phase); checked > 0.85, energy drift below 0.1 % (measured 0.021 %).
4. Continuation: the 1D rod with the switch, split at step 100 (in contact, alpha_i
   evolving) and continued from a restart file after clear, equals the uninterrupted run
   at 1e-12 of each thermo column's scale, and d_esph_alpha, x and v of every atom after
   the last step agree to the same tolerance (a run boundary reorders sums: round-off)."""
import math
import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("viscosity switch: 1D convergence, hard-case stability, continuation")
# the switch and the paper's viscosity as measured in doc/visc_switch.md (without the
# default's reconstruction)
PAPER = "visc/recon off"
SW = "visc/switch 0.1 0.2 visc/recon off"

# --- 1. convergence of the residual velocity ---
DX = [0.2, 0.1, 0.05, 0.025]
res = {}
for extra in (PAPER, SW):
    res[extra] = []
    for dx in DX:
        s = et.summary(et.run(a, "rod_impact/in.rod_impact",
                              {"dim": 1, "dx": dx, "contact": "solid", "tend": 12.0, "out": 0,
                               "thermo_every": 1000, "pair_extra": extra},
                              log=f"log.conv.{dx}.{'sw' if extra == SW else 'av'}"))
        res[extra].append(s["v_impactor"])
        c.near(f"momentum split at {dx} mm {'switch' if extra == SW else 'paper AV'} [m/s]",
               s["v_impactor"] + s["v_target"], 50.0, 1e-9, "equal masses, exact")
order = {k: math.log(v[0] / v[-1]) / math.log(DX[0] / DX[-1]) for k, v in res.items()}
print("INFO residual [m/s] paper AV:", " ".join(f"{v:.4f}" for v in res[PAPER]),
      f"order {order[PAPER]:.3f}")
print("INFO residual [m/s] switch  :", " ".join(f"{v:.4f}" for v in res[SW]),
      f"order {order[SW]:.3f}")
c.less("order of the residual with the switch (negated)", -order[SW], -0.52,
       "measured 0.567, paper AV 0.49; the goal 0.9 is not reached (see docstring)")
for dx, r0, r1 in zip(DX, res[PAPER], res[SW]):
    c.less(f"residual ratio switch / paper AV at {dx} mm", r1 / r0, 0.6, "measured 0.47-0.55")

# --- 2. fast impact ---
s = et.summary(et.run(a, "fast_impact/in.fast_impact",
                      {"dim": 1, "dx": 0.2, "V": 500, "tend": 8, "out": 0, "thermo_every": 100,
                       "pair_extra": SW}, log="log.fast"))
print("INFO fast impact with the switch", s)
c.true("fast impact: finite", all(math.isfinite(v) for v in s.values()), "no NaN")
c.near("fast impact: momentum split [m/s]", s["v_impactor"] + s["v_target"], 500.0, 1e-8,
       "equal masses, exact")
c.less("fast impact: |energy drift| [%]", abs(s["energy_drift_pct"]), 0.5,
       "measured 0.116 %; the REFERENCES 7 acceptance")

# --- 3. free bar: a smooth wave is not damped ---
src = open(os.path.join(et.EXAMPLES, "free_bar", "in.free_bar")).read()
src = src.replace("visc ${alpha} ${beta} 0.1", "visc ${alpha} ${beta} 0.1 " + SW)
assert SW in src
fb = et.summary(et.run(a, et.write_input(a, "in.free_bar_sw", src), {"nsteps": 4000},
                       log="log.free_bar"), key="FREE_BAR")
print("INFO free bar with the switch", fb)
c.less("free bar: kinetic energy kept (negated)", -fb["ke_fraction"], -0.85,
       "measured 0.916 with the switch, 0.471 with the paper viscosity")
c.less("free bar: |energy drift| [%]", abs(fb["energy_drift_pct"]), 0.1, "measured 0.021 %")

# --- 4. continuation ---
head, styles = et.example_scene("rod_impact", "run             ${nsteps}")
DUMP = ("write_dump all custom final.dump id x y z vx vy vz d_esph_alpha modify sort id "
        "format float %.17g\n")
VAR = {"dim": 1, "dx": 0.2, "tend": 4.0, "out": 0, "thermo_every": 5, "pair_extra": SW}
variants = {"full": "run 300\n",
            "split": "run 100\nrun 200\n",
            "restart": f"run 100\nwrite_restart r.bin\nclear\nread_restart r.bin\n{styles}"
                       "run 200\n"}
out = {}
for name, tail in variants.items():
    wd = os.path.join(a.workdir, f"cont.{name}")
    os.makedirs(wd, exist_ok=True)
    path = os.path.join(wd, "in.cont")
    with open(path, "w") as f:
        f.write(head + tail + DUMP)
    log = et.run(a, path, VAR, log="log.cont")
    rows = {}
    for r in et.thermo(log):
        for i in range(len(r["Step"])):
            rows[int(r["Step"][i])] = {k: v[i] for k, v in r.items()}
    out[name] = (rows, np.loadtxt(os.path.join(wd, "final.dump"), skiprows=9))
ref, ra = out["full"]
alpha = ra[:, 7]
real = alpha > 0
c.true("alpha_i evolved below its ceiling", real.any() and alpha[real].min() < 0.5,
       f"min alpha after 300 steps {alpha[real].min():.4f}")
cols = [k for k in next(iter(ref.values())) if k != "Step"]
scale = {k: max(abs(r[k]) for r in ref.values()) for k in cols}
for g in (("KinEng", "PotEng", "TotEng", "f_int[1]"), ("c_px", "c_pyimp"), ("c_vimp", "c_vtgt")):
    s = max(scale.get(k, 0.0) for k in g)
    for k in g:
        if k in scale:
            scale[k] = s
scale["v_Lz"] = max(scale.get("v_Lz", 0.0), scale["c_px"] * 1.0e-3)
for name in ("split", "restart"):
    rows, aa = out[name]
    worst, nrow = 0.0, 0
    for st, r in rows.items():
        if st not in ref:
            continue
        nrow += 1
        for k in cols:
            d = abs(r[k] - ref[st][k])
            worst = max(worst, d / scale[k] if scale[k] > 0 else (0.0 if d == 0 else np.inf))
    same = aa.shape == ra.shape and np.all(aa[:, 0] == ra[:, 0])
    if same:
        L = np.abs(ra[:, 1:4]).max()
        vmax = np.sqrt((ra[:, 4:7] ** 2).sum(axis=1)).max()
        worst = max(worst, np.abs(aa[:, 1:4] - ra[:, 1:4]).max() / L,
                    np.abs(aa[:, 4:7] - ra[:, 4:7]).max() / vmax,
                    np.abs(aa[:, 7] - ra[:, 7]).max() / max(np.abs(ra[:, 7]).max(), 1e-300))
    print(f"INFO continuation {name}: worst {worst:.3e} over {nrow} thermo rows and the atoms")
    c.true(f"continuation {name}: same atoms", same, "ids after the last step")
    c.less(f"continuation {name}: thermo, x, v, alpha", worst, 1.0e-12,
           "round-off of a run boundary's reordered sums")
    c.true(f"continuation {name}: thermo rows compared", nrow >= 50, "one every 5 steps")
c.done()
