#!/usr/bin/env python3
"""compute esph/atom against hand-computed values, and its per-particle contact force
against the body totals, on 1 and 2 ranks.

1. Particles at imposed states (run 0, nothing moves): Mie-Grueneisen iron compressed,
   stretched and at rho0 with internal energy, linear-EOS aluminum, an imposed deviator.
   The pressure against the formula of doc/pair_esph_solid.rst ("Equations of state")
   evaluated here in Python; the sound speed against a central finite difference of that
   formula, c^2 = dP/drho|_e + P/rho^2 dP/de (an independent check of the code's
   analytic derivative); von Mises stress of a uniaxial and a pure-shear deviator
   against the hand values sigma and sqrt(3) tau; the Cauchy components sigma = -P I + S;
   the volumetric strain rho0/rho - 1; the plastic strain as set; atoms outside the group 0.
   Tolerances: 1e-13 relative for the same formula in a different arithmetic order
   (double round-off, values printed with 17 digits); 1e-7 relative for the sound speed
   (central difference with a relative step of 1e-4: truncation ~1e-8, round-off ~1e-12;
   one-sided second order at rho0, where the Hugoniot's second derivative jumps).
2. Two blocks in contact (3D, 0.25 mm, 20 m/s): every step, the per-particle contact
   normal force summed over each body equals the body pair's contact force of compute
   esph/contact (column 5), within 1e-12 relative (the same pair forces summed in another
   order); both bodies carry the same total (action and reaction); the contact flag is
   set on both faces; boundary particles and a scene without plasticity give 0.
3. The same scene on 2 ranks, the cut x = 0 on the contact plane (every contact pair has
   its partner on the other rank: the per-atom force is right only with the reverse
   communication), newton on and off: the per-atom values of every column in mid-contact
   equal those of 1 rank within 1e-10 of the column's largest value (summation order;
   test_mpi measures 3e-14 on this kind of scene; a missing ghost contribution is
   of order 1)."""
import os
import subprocess

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("compute esph/atom: values, contact force, MPI")

COLS = ["pressure", "vonmises", "sxx", "syy", "szz", "sxy", "sxz", "syz", "strain_vol",
        "sound", "epsp", "contact", "fcontact"]


def read_dump(path, step=None):
    """snapshot of a dump custom file at a step (default: the last): {column: array},
    rows sorted by id"""
    lines = open(path).read().splitlines()
    heads = [i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP")] + [len(lines)]
    k = len(heads) - 2 if step is None else [int(lines[h + 1]) for h in heads[:-1]].index(step)
    block = lines[heads[k]:heads[k + 1]]
    start = [i for i, l in enumerate(block) if l.startswith("ITEM: ATOMS")][0]
    names = block[start].split()[2:]
    data = np.array([[float(x) for x in l.split()] for l in block[start + 1:]])
    data = data[np.argsort(data[:, 0])]
    return {n: data[:, k] for k, n in enumerate(names)}


# ---------- Mie-Grueneisen and linear EOS of the docs ----------
IRON = dict(rho0=7850.0, c0=3574.0, s=1.92, g0=1.69)
K_AL, RHO0_AL = 74.0e9, 2703.0


def p_mg(rho, e, rho0, c0, s, g0):
    eta = 1.0 - rho0 / rho
    k0 = rho0 * c0 * c0
    ph = k0 * eta / (1.0 - s * eta) ** 2 if eta > 0.0 else k0 * eta
    eh = ph * eta / (2.0 * rho0)
    return ph + g0 * rho0 * (e - eh)


def c_fd(pfun, rho, e, rho0):
    """sound speed from central differences of P(rho, e)"""
    dr, de_ = 1e-4 * rho, 1e-4 * max(abs(e), 1.0e4)
    if abs(rho - rho0) < dr:
        # at the kink of the Hugoniot (eta = 0: the second derivative jumps) one-sided,
        # second order, from the compression side
        dpdr = (-3 * pfun(rho, e) + 4 * pfun(rho + dr, e) - pfun(rho + 2 * dr, e)) / (2 * dr)
    else:
        dpdr = (pfun(rho + dr, e) - pfun(rho - dr, e)) / (2 * dr)
    dpde = (pfun(rho, e + de_) - pfun(rho, e - de_)) / (2 * de_)
    c2 = dpdr + pfun(rho, e) / rho ** 2 * dpde
    return np.sqrt(max(c2, 0.0))


def mg(rho, e):
    return p_mg(rho, e, **IRON)


def lin(rho, e):
    return K_AL * (rho / RHO0_AL - 1.0)


# atom id: (type, rho, e, S (xx yy zz xy xz yz), epsp)
sig, tau = 2.0e8, 1.5e8
STATES = {
    1: (1, 8300.0, 0.0, (0, 0, 0, 0, 0, 0), 0.0),               # compressed, no energy
    2: (1, 8300.0, 5.0e4, (0, 0, 0, 0, 0, 0), 0.0),             # compressed with energy
    3: (1, 7600.0, 2.0e3, (0, 0, 0, 0, 0, 0), 0.0),             # stretched (linear branch)
    4: (1, 7850.0, 1.0e5, (2 * sig / 3, -sig / 3, -sig / 3, 0, 0, 0), 0.02),    # uniaxial
    5: (1, 8000.0, 1.0e4, (0, 0, 0, tau, 0, 0), 0.0),           # pure shear xy
    6: (2, 2750.0, 0.0, (1e7, -4e7, 3e7, 2e6, -5e6, 7e6), 0.0),   # linear EOS, general S
    7: (2, 2600.0, 3.0e4, (0, 0, 0, 0, 0, 0), 0.0),             # linear EOS in tension
    8: (1, 8300.0, 5.0e4, (1e8, 0, 0, 0, 0, 0), 0.0),           # outside the group: 0
}
lines = ["units si", "atom_style atomic", "atom_modify map array", "boundary f f f",
         "region box block 0 1 0 1 0 1", "create_box 2 box"]
for i, (t, *_rest) in STATES.items():
    # far apart: no neighbours, run 0 changes nothing
    lines.append(f"create_atoms {t} single {0.1 * i} 0.5 0.5 units box")
lines += ["pair_style esph/solid 1.0e-3 contact off",
          "pair_coeff 1 1 rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69 yield 1e9",
          f"pair_coeff 2 2 rho0 {RHO0_AL} shear 27.6e9 eos linear {K_AL}",
          "fix int all esph/integrate", "set group all mass 1.0e-6"]
for i, (t, rho, e, S, ep) in STATES.items():
    cmd = f"set atom {i} d_esph_rho {rho} d_esph_e {e} d_esph_epsp {ep}"
    for k, v in enumerate(S):
        cmd += f" d2_esph_s[{k + 1}] {v!r}"
    lines.append(cmd)
lines += ["group sel id 1:7",
          "compute all sel esph/atom",
          "compute some sel esph/atom stress/* strain/plastic pressure",
          "compute vm sel esph/atom vonmises",
          "dump d all custom 1 dump.states id c_all[*] c_some[*] c_vm",
          "dump_modify d format float %.17g sort id", "run 0"]
et.run(a, et.write_input(a, "in.states", "\n".join(lines) + "\n"))
d = read_dump(os.path.join(a.lastdir, "dump.states"))

worst = {"pressure": 0.0, "stress": 0.0, "vonmises": 0.0, "strain": 0.0, "sound": 0.0}
for i, (t, rho, e, S, ep) in STATES.items():
    r = int(np.where(d["id"] == i)[0][0])
    got = {n: d[f"c_all[{k + 1}]"][r] for k, n in enumerate(COLS)}
    if i == 8:
        c.less("atom outside the group: every column 0",
               max(abs(v) for v in got.values()), 1e-300, "group")
        continue
    pf = mg if t == 1 else lin
    rho0 = IRON["rho0"] if t == 1 else RHO0_AL
    P = pf(rho, e)
    worst["pressure"] = max(worst["pressure"], abs(got["pressure"] - P) / abs(P))
    sigma = [S[k] - (P if k < 3 else 0.0) for k in range(6)]
    scale = max(abs(P), max(abs(x) for x in S))
    for k, n in enumerate(["sxx", "syy", "szz", "sxy", "sxz", "syz"]):
        worst["stress"] = max(worst["stress"], abs(got[n] - sigma[k]) / scale)
    worst["strain"] = max(worst["strain"], abs(got["strain_vol"] - (rho0 / rho - 1.0)))
    cref = c_fd(pf, rho, e, rho0)
    worst["sound"] = max(worst["sound"], abs(got["sound"] - cref) / cref)
    if i == 4:
        c.near("uniaxial deviator: von Mises = sigma [Pa]", got["vonmises"], sig, 1e-13 * sig,
               "sqrt(3/2 S:S) of diag(2/3, -1/3, -1/3) sigma")
        c.near("plastic strain as set", got["epsp"], ep, 1e-15, "d_esph_epsp")
    if i == 5:
        c.near("pure shear: von Mises = sqrt(3) tau [Pa]", got["vonmises"], np.sqrt(3) * tau,
               1e-13 * tau, "sqrt(3/2 * 2 tau^2)")
    if i == 6:
        vm = np.sqrt(1.5 * (sum(x * x for x in S[:3]) + 2 * sum(x * x for x in S[3:])))
        worst["vonmises"] = abs(got["vonmises"] - vm) / vm
    if i == 3:
        c.near("stretched iron: tension branch P = rho0 c0^2 eta + Gamma0 rho0 (e - E_H) [Pa]",
               got["pressure"], P, 1e-13 * abs(P), "linear Hugoniot for eta < 0")
    # the other computes: the same numbers in the columns asked for
    some = [d[f"c_some[{k + 1}]"][r] for k in range(8)]
    c.true(f"atom {i}: keyword list (stress/* strain/plastic pressure) and single column",
           some == [got[n] for n in ["sxx", "syy", "szz", "sxy", "sxz", "syz", "epsp",
                                     "pressure"]] and d["c_vm"][r] == got["vonmises"],
           "same values, columns in the order given")
c.less("pressure vs the docs' EOS formula (relative)", worst["pressure"], 1e-13,
       "same formula, other arithmetic order")
c.less("Cauchy stress -P I + S (relative to max |P|, |S|)", worst["stress"], 1e-13,
       "exact arithmetic up to round-off")
c.less("von Mises of a general deviator (relative)", worst["vonmises"], 1e-13, "sqrt(3/2 S:S)")
c.less("volumetric strain rho0/rho - 1", worst["strain"], 1e-15, "round-off of one division")
c.less("sound speed vs finite difference of P (relative)", worst["sound"], 1e-7,
       "central difference, relative step 1e-4")

# ---------- two blocks in contact ----------
TWO = """variable newton index on
units si
atom_style atomic
atom_modify map array
boundary f f f
newton ${newton}
processors * 1 1
region box block -3e-3 3e-3 -1e-3 1e-3 -1e-3 1e-3
create_box 2 box
lattice sc 2.5e-4 origin 0.5 0.5 0.5
region b1 block -2e-3 0 -5e-4 5e-4 -5e-4 5e-4 units box
region b2 block 0 2e-3 -5e-4 5e-4 -5e-4 5e-4 units box
create_atoms 1 region b1
create_atoms 2 region b2
group A region b1
group B region b2
pair_style esph/solid 2.5e-4
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix int all esph/integrate
set group all mass $(7850*2.5e-4^3)
set group A i_esph_body 1
set group B i_esph_body 2
fix bnd all esph/boundary spacing 2.5e-4
variable massive atom mass>0.0
group real variable massive
group rA intersect A real
group rB intersect B real
velocity rA set 20 0 0 units box
neighbor 5e-5 bin
neigh_modify every 1 delay 0 check yes
timestep 1e-8
compute atom all esph/atom
compute fA rA reduce sum c_atom[13]
compute fB rB reduce sum c_atom[13]
compute nA rA reduce sum c_atom[12]
compute nB rB reduce sum c_atom[12]
compute cont all esph/contact
thermo_modify format float %.15g
thermo 1
# the rows of compute esph/contact exist once the bodies have touched
run 1
thermo_style custom step c_cont[1][5] c_fA c_fB c_nA c_nB
dump d all custom 60 dump.two id i_esph_body mass c_atom[*]
dump_modify d format float %.17g sort id
run 120
"""
two = et.write_input(a, "in.two", TWO)
th = et.thermo(et.run(a, two, log="log.two.1"))[-1]
fc, fa, fb = (np.array(th[k]) for k in ("c_cont[1][5]", "c_fA", "c_fB"))
on = fc > 0.0
c.true("the blocks are in contact for more than 50 steps", on.sum() > 50,
       f"{on.sum()} steps with a contact force; 2L/c = 0.8 us = 80 steps")
rel = max(np.abs(fa - fc).max(), np.abs(fb - fc).max()) / fc.max()
c.less("sum over each body of the per-particle contact force vs compute esph/contact",
       rel, 1e-12, "the same pair forces, another summation order")
c.less("no contact force where compute esph/contact has none",
       max(np.abs(fa[~on]).max(), np.abs(fb[~on]).max()), 1e-300, "no contact, no force")
# while the interface is loaded (force above half its peak): as the release wave arrives
# the force falls on fewer pairs
loaded = fc >= 0.5 * fc.max()
c.true("contact flag on both faces while loaded",
       min(np.array(th["c_nA"])[loaded].min(), np.array(th["c_nB"])[loaded].min()) >= 16,
       "at least the 4x4 face particles of each block")
one = read_dump(os.path.join(a.lastdir, "dump.two"), 60)
bnd = one["mass"] == 0.0
c.true("boundary particles present, all their columns 0",
       bnd.sum() > 0 and all(np.abs(one[f"c_atom[{k}]"][bnd]).max() == 0.0 for k in range(1, 14)),
       "no material state (doc)")
c.less("no plasticity defined: strain/plastic 0", np.abs(one["c_atom[11]"]).max(), 1e-300,
       "0 where no plasticity")
c.true("contact force only on flagged particles",
       np.all((one["c_atom[13]"] > 0.0) == (one["c_atom[12]"] > 0.0)), "flag = force > 0")

for newton in ("on", "off"):
    th2 = et.thermo(et.run(a, two, {"newton": newton}, np=2, log=f"log.two.2{newton}"))[-1]
    fc2, fa2 = np.array(th2["c_cont[1][5]"]), np.array(th2["c_fA"])
    c.less(f"np 2 newton {newton}: per-particle sum vs compute esph/contact",
           np.abs(fa2 - fc2).max() / fc2.max(), 1e-12, "reverse communication of ghosts")
    other = read_dump(os.path.join(a.lastdir, "dump.two"), 60)
    worst, col = 0.0, ""
    for k in range(1, 14):
        x, y = one[f"c_atom[{k}]"], other[f"c_atom[{k}]"]
        dd = np.abs(x - y).max() / max(np.abs(x).max(), 1e-300)
        if dd > worst:
            worst, col = dd, COLS[k - 1]
    print(f"INFO np 2 newton {newton}: worst relative difference {worst:.3e} ({col})")
    c.less(f"np 2 newton {newton} vs np 1: per-atom values at step 60 (mid-contact)", worst, 1e-10,
           "summation order only")
c.done()
