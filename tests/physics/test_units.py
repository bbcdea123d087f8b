#!/usr/bin/env python3
"""The same contact scene in units si, metal and real: the same physics to round-off.

Scene (3D, coarse): an iron block (Mie-Grueneisen, von Mises yield 0.3 GPa with linear
hardening, so that it deforms plastically) strikes an aluminum block (linear EOS) at
100 m/s across an initial gap of 0.1 spacings; artificial heat transfer on, Coulomb
friction 0.3 (the blocks' different lateral expansion slides the faces: it changes ke by
1e-3), CFL time step, and a stock fix addforce pushing on the target. Every input of the si scene is
converted to metal and to real by Python (below), with the unit system that LAMMPS's
own constants define (see UNITS); then the outputs are converted back and compared:
positions, velocities, per-atom density, specific energy, deviatoric stress, plastic
strain, forces (atom->f), compute esph/atom (pressure, Cauchy stress, sound speed,
contact force), compute esph/contact (force, impulse, first touch, end of contact,
peak force), fix esph/integrate (internal energy, CFL step, contact force), thermo ke,
pe, time and the time step, and the sum of fx over the target (pair forces + addforce).

Tolerance: 1e-10 of each quantity's largest magnitude. The conversions are exact
scalings done in floating point: every input and every factor carries a relative
round-off of ~1e-16, the mechanics then runs on numbers that differ by that much, and
the time integration (about 200 steps, a wave problem with contact and plasticity)
amplifies it; measured: below 1e-12 (the INFO lines). A unit slip anywhere (a missing
conversion of a pressure, energy or force) is a factor 1e-5 .. 1e5 and fails by
orders of magnitude. si itself is checked bitwise by the example regression (its
reference logs are unchanged).

The metal scene also runs on 2 MPI ranks (against si on 1: the summation order
differs too, test_mpi measures 3e-14 for that alone).

Also: a unit style that stays unsupported (electron) is an error naming it and the
supported ones."""
import os
import subprocess

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("unit styles si, metal, real: the same physics after conversion")

# LAMMPS's constants (src/update.cpp, Update::set_units): ftm2v, mvv2e, nktv2p
LAMMPS = {
    "metal": dict(ftm2v=1.0 / 1.0364269e-4, mvv2e=1.0364269e-4, nktv2p=1.6021765e6),
    "real": dict(ftm2v=1.0 / 48.88821291 / 48.88821291, mvv2e=48.88821291 * 48.88821291,
                 nktv2p=68568.415),
}


def units(style):
    """SI value of one unit of each kind in the unit style. Distance, time and pressure
    units are the style's (Angstrom; ps or fs; bar = 1e5 Pa or atm = 101325 Pa); the mass
    unit follows from LAMMPS's constants so that pressure = mvv2e nktv2p
    mass/(distance time^2) holds exactly as LAMMPS defines it (it is 1.66053886e-27 kg
    in metal, g/mol with LAMMPS's rounded constants: CODATA's amu differs by 1.3e-7, a
    property of LAMMPS's constants, not of the package)."""
    if style == "si":
        return dict(L=1.0, T=1.0, M=1.0, P=1.0, E=1.0, F=1.0)
    k = LAMMPS[style]
    L, T, P = 1.0e-10, (1.0e-12 if style == "metal" else 1.0e-15), \
        (1.0e5 if style == "metal" else 101325.0)
    M = k["mvv2e"] * k["nktv2p"] * P * L * T * T
    E = M * L * L / (T * T) / k["mvv2e"]    # energy: mvv2e converts m v^2 to it
    F = k["ftm2v"] * M * L / (T * T)        # force: ftm2v converts F t / m to velocity
    return dict(L=L, T=T, M=M, P=P, E=E, F=F)


# the scene in SI; dimension of each input: (L, T, M, P, E, F) exponents via kind
DX = 2.5e-4
SI = dict(
    dx=(DX, "L"), gap=(0.1 * DX, "L"), skin=(0.2 * DX, "L"),
    xlo=(-4.0e-3, "L"), xhi=(4.0e-3, "L"), ylo=(-1.0e-3, "L"), yhi=(1.0e-3, "L"),
    bx=(1.5e-3, "L"), by=(5.0e-4, "L"),
    V=(100.0, "V"), dt0=(1.0e-9, "T"), dtmax=(2.0e-8, "T"),
    rho_fe=(7850.0, "D"), G_fe=(80.0e9, "P"), c0_fe=(3574.0, "V"), Y_fe=(0.3e9, "P"),
    H_fe=(2.0e9, "P"),
    rho_al=(2703.0, "D"), G_al=(27.6e9, "P"), K_al=(74.0e9, "P"),
    m_fe=(7850.0 * DX ** 3, "M"), m_al=(2703.0 * DX ** 3, "M"),
    fpush=(-0.5, "F"),
)


def factor(u, kind):
    return {"L": u["L"], "T": u["T"], "M": u["M"], "P": u["P"], "E": u["E"], "F": u["F"],
            "V": u["L"] / u["T"], "D": u["M"] / u["L"] ** 3, "e": u["E"] / u["M"],
            "J": u["F"] * u["T"], "1": 1.0}[kind]


SCENE = """units {style}
atom_style atomic
atom_modify map array
boundary f f f
region box block {xlo!r} {xhi!r} {ylo!r} {yhi!r} {ylo!r} {yhi!r}
create_box 2 box
lattice sc {dx!r} origin 0.5 0.5 0.5
region b1 block -{bx!r} 0 -{by!r} {by!r} -{by!r} {by!r} units box
region b2 block 0 {bx!r} -{by!r} {by!r} -{by!r} {by!r} units box
create_atoms 1 region b1
create_atoms 2 region b2
group A region b1
group B region b2
displace_atoms B move {gap!r} 0 0 units box
pair_style esph/solid {dx!r} heat 0.1 0.1 friction 0.3
pair_coeff 1 1 rho0 {rho_fe!r} shear {G_fe!r} eos mie/gruneisen {c0_fe!r} 1.92 1.69 &
           yield {Y_fe!r} hardening {H_fe!r}
pair_coeff 2 2 rho0 {rho_al!r} shear {G_al!r} eos linear {K_al!r}
timestep {dt0!r}
fix int all esph/integrate cfl 0.3 dtmax {dtmax!r}
set group A mass {m_fe!r}
set group B mass {m_al!r}
set group A i_esph_body 1
set group B i_esph_body 2
fix bnd all esph/boundary spacing {dx!r}
variable massive atom mass>0.0
group real variable massive
group rA intersect A real
group rB intersect B real
velocity rA set {V!r} 0 0 units box
fix push rB addforce {fpush!r} 0 0
neighbor {skin!r} bin
neigh_modify every 1 delay 0 check yes
compute atom all esph/atom
compute fxB rB reduce sum fx
compute cont all esph/contact
thermo 10
thermo_style custom step time dt ke pe c_fxB f_int[1] f_int[3] f_int[8]
thermo_modify format float %.17g
run 30
# the rows of compute esph/contact exist once the bodies have touched
thermo_style custom step time dt ke pe c_fxB f_int[1] f_int[3] f_int[8] &
             c_cont[1][5] c_cont[1][6] c_cont[1][7] c_cont[1][11]
thermo_modify format float %.17g
dump d all custom 80 dump.{style} id x y z vx vy vz fx fy fz d_esph_rho d_esph_e &
     d2_esph_s[1] d2_esph_s[2] d2_esph_s[3] d2_esph_s[4] d2_esph_s[5] d2_esph_s[6] &
     d_esph_epsp c_atom[*]
dump_modify d format float %.17g sort id
run 160
print "CONTACT tfirst $(f_int[4]:%.17g) tlast $(f_int[5]:%.17g) episodes $(f_int[6])"
"""

# dimension of every thermo and dump column
THERMO = {"Time": "T", "Dt": "T", "KinEng": "E", "PotEng": "E", "c_fxB": "F",
          "f_int[1]": "E", "f_int[3]": "T", "f_int[8]": "F", "c_cont[1][5]": "F",
          "c_cont[1][6]": "J", "c_cont[1][7]": "T", "c_cont[1][11]": "F"}
DUMP = dict(x="L", y="L", z="L", vx="V", vy="V", vz="V", fx="F", fy="F", fz="F",
            d_esph_rho="D", d_esph_e="e", d_esph_epsp="1")
DUMP.update({f"d2_esph_s[{k}]": "P" for k in range(1, 7)})
# compute esph/atom: pressure, von Mises, 6 stresses, strain/vol, sound, epsp, contact,
# contact/force
for k, kind in enumerate("PPPPPPPP1V11F", start=1):
    DUMP[f"c_atom[{k}]"] = kind


def read_dumps(path):
    """{step: {column: array}}, rows sorted by id"""
    lines = open(path).read().splitlines()
    heads = [i for i, l in enumerate(lines) if l.startswith("ITEM: TIMESTEP")] + [len(lines)]
    out = {}
    for h0, h1 in zip(heads[:-1], heads[1:]):
        block = lines[h0:h1]
        start = [i for i, l in enumerate(block) if l.startswith("ITEM: ATOMS")][0]
        names = block[start].split()[2:]
        data = np.array([[float(x) for x in l.split()] for l in block[start + 1:]])
        out[int(block[1])] = {n: data[:, k] for k, n in enumerate(names)}
    return out


res = {}
for style, np_ in (("si", 1), ("metal", 1), ("real", 1), ("metal", 2)):
    u = units(style)
    vals = {k: v / factor(u, kind) for k, (v, kind) in SI.items()}
    path = et.write_input(a, f"in.units.{style}", SCENE.format(style=style, **vals))
    text = et.run(a, path, np=np_, log=f"log.{style}.{np_}")
    runs = et.thermo(text)
    ct = [l.split() for l in text.splitlines() if l.startswith("CONTACT ")][0]
    name = style if np_ == 1 else f"{style} np {np_}"
    res[name] = dict(u=u, thermo=runs[-1], first=runs[0],
                      dump=read_dumps(os.path.join(a.lastdir, f"dump.{style}")),
                      tfirst=float(ct[2]), tlast=float(ct[4]), episodes=float(ct[6]))

si = res["si"]
th = si["thermo"]
f8 = np.array(th["f_int[8]"])
c.true("si: the blocks touch, transmit force and separate again",
       si["tfirst"] > 0.0 and si["tlast"] > si["tfirst"] and f8.max() > 0.0
       and f8[-1] == 0.0,
       f"first touch {si['tfirst']:.4g} s, end {si['tlast']:.4g} s, peak {f8.max():.4g} N, "
       f"{si['episodes']:.0f} episode(s) (the faces' tail after separation reaches 1 % of the "
       "peak once more)")
# the peak force against the 1D elastic impact of the two blocks (1 mm^2, 100 m/s): stress
# V Z_A Z_B / (Z_A + Z_B) with Z = rho c_L (iron 7850 x 5135, aluminum 2703 x 6402 m/s),
# 1.21e3 N; the iron's yield only lowers it. With the masses across bodies (before
# 2026-12-06) the aluminum particles took the iron's mass into their density rate: 1.59e3 N
ZA, ZB = 7850.0 * np.sqrt(3574.0**2 + 4.0 * 80e9 / (3.0 * 7850.0)), \
    2703.0 * np.sqrt(74e9 / 2703.0 + 4.0 * 27.6e9 / (3.0 * 2703.0))
fmax = 100.0 * ZA * ZB / (ZA + ZB) * 1.0e-6
c.less("si: peak contact force over the 1D elastic impact force", f8.max() / fmax, 1.05,
       f"{fmax:.4g} N, an upper bound (measured 0.88; 1.31 before the volume weights)")
ep = si["dump"][max(si["dump"])]["d_esph_epsp"]
c.true("si: the iron block deforms plastically", ep.max() > 1e-4,
       f"largest plastic strain {ep.max():.3g}")
c.true("si: CFL steps vary", len(set(th["Dt"])) > 1, "the time step estimate is compared too")

TOL = 1.0e-10
for style in ("metal", "real", "metal np 2"):
    r = res[style]
    u = r["u"]
    worst = {}
    # thermo, both runs
    for key in ("first", "thermo"):
        ref, got = si[key], r[key]
        c.true(f"{style}: same thermo steps ({key} run)", got["Step"] == ref["Step"],
               "the CFL step sequence gives the same step count")
        for col, kind in THERMO.items():
            if col not in ref:
                continue
            x = np.array(ref[col])
            y = np.array(got[col]) * factor(u, kind)
            scale = max(np.abs(x).max(), 1e-300)
            worst[col] = max(worst.get(col, 0.0), np.abs(y - x).max() / scale)
    # per-atom, every dumped step
    c.true(f"{style}: same dump steps and atoms", sorted(r["dump"]) == sorted(si["dump"])
           and all(len(r["dump"][s]["id"]) == len(si["dump"][s]["id"]) for s in si["dump"]),
           f"{len(si['dump'])} snapshots")
    for step, ref in si["dump"].items():
        got = r["dump"][step]
        for col, kind in DUMP.items():
            x, y = ref[col], got[col] * factor(u, kind)
            scale = max(np.abs(x).max(), 1e-300)
            worst[col] = max(worst.get(col, 0.0), np.abs(y - x).max() / scale)
    for key, kind in (("tfirst", "T"), ("tlast", "T")):
        worst["fix " + key] = abs(r[key] * factor(u, kind) - si[key]) / abs(si[key])
    col = max(worst, key=worst.get)
    print(f"INFO {style} vs si: largest relative difference {worst[col]:.3e} ({col}); "
          + ", ".join(f"{k} {v:.1e}" for k, v in sorted(worst.items())))
    for k, v in sorted(worst.items()):
        c.less(f"{style} vs si: {k}", v, TOL, "relative to the largest |value|; round-off")
    c.true(f"{style}: one contact episode", r["episodes"] == si["episodes"], "as in si")

# a unit style that is not supported: the error names it and the supported ones
bad = SCENE.format(style="si", **{k: v for k, (v, kind) in SI.items()}).replace(
    "units si", "units electron")
path = et.write_input(a, "in.units.electron", bad)
r = subprocess.run([a.lmp, "-in", path, "-nocite", "-log", "none"], cwd=a.workdir,
                   capture_output=True, text=True, timeout=120)
err = [l for l in (r.stdout + r.stderr).splitlines() if "ERROR" in l]
c.true("units electron: an error naming it and the supported unit styles",
       r.returncode != 0 and err and "units electron" in err[0]
       and "expected units si, metal, real, cgs, micro, nano or lj" in err[0],
       err[0] if err else "no error")
c.done()
