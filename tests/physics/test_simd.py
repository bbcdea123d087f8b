#!/usr/bin/env python3
"""pair_style esph/solid simd yes (the default): the bulk pairs (two real particles of one
body, or any two real particles with contact off) in AVX-512 registers from an extra full
neighbour list, every other pair in the scalar loop from the split half list
(src/pair_esph_solid_simd.cpp). The answer must be simd no's (the scalar loop alone) to
round-off.

Scene: examples/rod_impact, 3D, dx = 0.25 mm, two 10 mm iron rods at 50 m/s, contact from
the first step, 2 us (140 steps), thermo every 10 steps printed with 15 digits; variants in
2D and 1D (dx = 0.1 mm, 420 steps), contact off, contact/normal cone (its cone sums of the
boundary-real pairs are the vector pass's too), heat 0.1 1.0 with visc/switch 0.1 0.2,
visc/recon minmod with gradient plain, newton off on 2 ranks, 2 MPI ranks, 2 OpenMP threads
(-sf omp -pk omp 2), and a plastic scene (yield 3e8 Pa: no deformable type without a yield
stress is left, so the reconstruction switches itself off and the vector pass runs without
it).

Checks:
- in use: with simd yes pair esph/solid requests a full neighbour list next to its half
  list; LAMMPS prints it in the log's "Neighbor list info" block ("attributes: full" under a
  pair esph/solid list). That is checked for every supported variant with simd yes, and its
  absence with simd no, without depending on timing. The vector pass needs AVX-512 F, VL and
  DQ (simd_cpu()); on a CPU without them (no avx512f/avx512vl/avx512dq in /proc/cpuinfo) the
  in-use checks are skipped and every run is scalar, so the equality checks still hold;
- simd yes against simd no: every thermo column within 1e-10 of its largest magnitude
  (et.worst_difference). Both sides compute the same pair terms with the same formulas; the
  vector pass computes each bulk pair from both sides and sums i's terms in another order
  (eight lanes, then a tree reduction), and the compiler may fuse multiply-adds: 1e-16 per
  sum, carried but not amplified over a few hundred steps. Measured: 6e-15 ... 4e-14 for the
  3D variants, 1.4e-13 in 1D, 1.8e-12 in 2D (c_pyimp, zero up to round-off, against its
  1e-4 floor); the bound is test_omp's for its summation-order change. A lost, doubled or
  wrongly signed pair term, or a pair taken by both passes, is 1e-3 or more; so is the
  effect of each option on these thermo columns (measured with simd no: heat 0.1 1.0 on
  against off 2.5e-3, visc/switch against the constant viscosity 2.9e-2, minmod against
  vanleer (gradient plain) 9e-3, gradient plain against corrected (minmod) 0.16), so a
  vector pass that dropped one would fail;
- np 1 against np 2 with simd yes (1e-10: the decomposition changes the summation order;
  measured 8e-15);
- a run split in two run commands, and one continued from a restart file (write_restart,
  clear, read_restart, the styles again), against the uninterrupted run, all with simd yes
  (1e-10: a run boundary rebuilds the neighbour lists, the full one included, and with it
  the split list of the scalar loop: a summation-order change again; measured 6e-15 and
  1.3e-14);
- the lists the pass orders are made anew whenever they must be: a rerun of a dump (LAMMPS
  sets neighbor->ncalls back to 0 at each frame), contact paper -> solid with run pre no (the
  partners change without a new list), and a compute centro/atom whose list is a copy of the
  pair's full list (it picks its nearest neighbours in the list's order, so the pass then
  orders a copy of its own): simd yes against simd no, every thermo block, 1e-10 as above.
  Before the fixes: 0.63, 1.05 and 6.3e-3 (the hostile round of 2026-12-05);
- options the vector pass does not implement (xsph 0.5, gradient bonet/lok) fall back
  silently: no error or warning, no full list in the log, and thermo identical to simd no
  (the same code path: bit for bit, stronger than round-off)."""
import os
import re

import esphtest as et

a = et.parse_args()
c = et.Checks("simd yes (the vector pass of the bulk pairs): simd no's answer to round-off")
TOL = 1.0e-10


def cpu_has_avx512():
    try:
        text = open("/proc/cpuinfo").read()
    except OSError:
        return False
    flags = set()
    for line in text.splitlines():
        if line.startswith("flags"):
            flags.update(line.split(":", 1)[1].split())
    return {"avx512f", "avx512vl", "avx512dq"} <= flags


AVX512 = cpu_has_avx512()
print(f"INFO AVX-512 F/VL/DQ on this CPU: {AVX512}"
      + ("" if AVX512 else " (in-use checks skipped; every run is scalar)"))

FULL = re.compile(r"\(\d+\) pair esph/solid(?:/omp)?, perpetual[^\n]*\n\s+attributes: full")
HALF = re.compile(r"\(\d+\) pair esph/solid(?:/omp)?, perpetual[^\n]*\n\s+attributes: half")


def lists(log):
    """(neighbour list info printed, a half list of the pair style, a full list of it)"""
    return "Neighbor list info" in log, bool(HALF.search(log)), bool(FULL.search(log))


def check_in_use(name, log, expect):
    info, half, full = lists(log)
    c.true(f"{name}: neighbour list info in the log with the pair's half list", info and half,
           "the list checks below are not vacuous")
    if expect and not AVX512:
        print(f"SKIP {name}: full list (simd in use) not checked, no AVX-512")
        return
    if expect:
        c.true(f"{name}: full list requested by pair esph/solid (simd in use)", full,
               "simd yes on an AVX-512 CPU with supported physics")
    else:
        c.true(f"{name}: no full list (scalar loop only)", not full,
               "simd no or an option the vector pass does not implement")


def compare(name, r1, r2, tol=TOL):
    worst, col = et.worst_difference(r1, r2)
    print(f"INFO {name}: worst relative difference {worst:.3e} in {col}")
    c.less(f"{name}: max relative difference", worst, tol, "summation order and FMA only")


def with_pair(v, extra):
    v = dict(v)
    v["pair_extra"] = (v.get("pair_extra", "") + " " + extra).strip()
    return v


ROD = "rod_impact/in.rod_impact"
rod = {"dx": 0.25, "Limp": 10.0, "Ltgt": 10.0, "tend": 2.0, "out": 0, "thermo_every": 10}
OMP2 = ("-sf", "omp", "-pk", "omp", "2")

# name: (variables, ranks, command-line flags)
scenes = {
    "3D rod": (rod, 1, ()),
    "2D strip": (dict(rod, dim=2, dx=0.1), 1, ()),
    "1D rod": (dict(rod, dim=1, dx=0.1), 1, ()),
    "contact off": (dict(rod, contact="off"), 1, ()),
    "heat + visc/switch": (with_pair(rod, "heat 0.1 1.0 visc/switch 0.1 0.2"), 1, ()),
    "visc/recon minmod, gradient plain": (with_pair(rod, "visc/recon minmod gradient plain"), 1,
                                          ()),
    "newton off, 2 ranks": (dict(rod, newton="off"), 2, ()),
    "2 ranks": (rod, 2, ()),
    "2 OpenMP threads": (rod, 1, OMP2),
    "plastic (yield 3e8)": (dict(rod, **{"yield": 3e8}), 1, ()),
    "contact/normal cone": (with_pair(rod, "contact/normal cone"), 1, ()),
}

prod = {}
for k, (name, (v, np_, fl)) in enumerate(scenes.items()):
    logs = {}
    for s in ("yes", "no"):
        logs[s] = et.run(a, ROD, with_pair(v, f"simd {s}"), np=np_, flags=fl,
                         log=f"log.s{k}.{s}")
        prod[(name, s)] = et.production_thermo(logs[s])
    check_in_use(f"{name}, simd yes", logs["yes"], True)
    check_in_use(f"{name}, simd no", logs["no"], False)
    compare(f"{name}: simd yes vs simd no", prod[(name, "no")], prod[(name, "yes")])

# the plastic scene yields (else it would repeat the elastic one)
vp, ve = prod[("plastic (yield 3e8)", "yes")]["c_vimp"][-1], prod[("3D rod", "yes")]["c_vimp"][-1]
c.less("plastic scene differs from the elastic one (negated relative difference of the final "
       "impactor velocity)", -abs(vp - ve) / abs(ve), -1.0e-3,
       f"plasticity acts: {vp:.6g} vs elastic {ve:.6g} m/s")

# the cone sums (of the boundary-real pairs, in the vector pass) act: the cone rule's answer
# is not the mean normal's
worst, col = et.worst_difference(prod[("3D rod", "yes")], prod[("contact/normal cone", "yes")])
c.less("contact/normal cone differs from the mean normal (negated worst relative difference)",
       -worst, -1.0e-6, f"{worst:.3e} in {col}: the cones turn the rims' common normals")

# ---- decomposition: np 1 against np 2, simd yes
compare("3D rod, simd yes: np 2 vs np 1", prod[("3D rod", "yes")], prod[("2 ranks", "yes")])

# ---- split run and restart with simd yes against the uninterrupted run
head, styles = et.example_scene("rod_impact", "run             ${nsteps}")
NSTEPS, SPLIT = 140, 60    # in contact throughout (contact from the first step)
variants = {"full": f"run {NSTEPS}\n",
            "split": f"run {SPLIT}\nrun {NSTEPS - SPLIT}\n",
            "restart": f"run {SPLIT}\nwrite_restart r.bin\nclear\nread_restart r.bin\n{styles}"
                       f"run {NSTEPS - SPLIT}\n"}
cont = {}
for name, tail in variants.items():
    wd = os.path.join(a.workdir, f"cont.{name}")
    os.makedirs(wd, exist_ok=True)
    path = os.path.join(wd, "in.cont")
    with open(path, "w") as f:
        f.write(head + tail)
    log = et.run(a, path, with_pair(rod, "simd yes"), log="log.cont")
    rows = {}
    for blk in et.thermo(log):
        for i, step in enumerate(blk["Step"]):
            rows[step] = {col: vals[i] for col, vals in blk.items()}
    steps = sorted(rows)
    cont[name] = {col: [rows[s][col] for s in steps] for col in rows[steps[0]]}
    nfull = len(FULL.findall(log))
    if AVX512:
        # the restart redefines the pair style: its run prints the list info again
        want = 2 if name == "restart" else 1
        c.true(f"continuation {name}: full list in every setup that prints the lists "
               f"({nfull})", nfull >= want, "simd yes after a run boundary and a restart")
c.true("continuation: the uninterrupted run has every step", len(cont["full"]["Step"]) ==
       NSTEPS // 10 + 1, f"{len(cont['full']['Step'])} thermo rows")
compare("3D rod, simd yes: split run vs uninterrupted", cont["full"], cont["split"])
compare("3D rod, simd yes: restart (clear, read_restart) vs uninterrupted", cont["full"],
        cont["restart"])

# ---- the lists the vector pass orders (simd_split()): made anew whenever LAMMPS builds the
# lists, also in a rerun (which sets neighbor->ncalls back to 0 at each frame) and after a
# change of the contact rule with run pre no; another style sharing the full list (compute
# centro/atom picks its 12 nearest neighbours in the list's order, ties on a lattice) sees
# LAMMPS's order. Each was a hostile-round failure: the rerun's forces 7-17x off, the
# contact pairs of paper -> solid 0.6-0.9 off, the sum of centro/atom 7e-3 off




cases = {
    "rerun of a dump": ("rod_impact", "",
                        "dump tr all custom 10 traj.txt id x y z vx vy vz\n"
                        "dump_modify tr format float %.17g\nrun 60\nundump tr\n"
                        "rerun traj.txt dump x y z vx vy vz\n", {}),
    "compute centro/atom sharing the full list": (
        "rod_impact", "compute cen all centro/atom 12\ncompute rcen all reduce sum c_cen\n",
        "run 30\nthermo_style custom step pe c_rcen f_int[2]\n"
        "thermo_modify format float %.17g\nrun 30\n", {}),
    "contact paper -> solid, run pre no": (
        "rod_impact", "",
        "run 40\npair_style esph/solid ${h} dimension ${dim} visc 1.0 1.0 0.1 contact solid "
        "${pair_extra}\nrun 20 pre no\n", {"contact": "paper"}),
}
for k, (name, (ex, extra, tail, vars_)) in enumerate(cases.items()):
    head, _ = et.example_scene(ex, "run             ${nsteps}", extra)
    got = {}
    for s in ("yes", "no"):
        wd = os.path.join(a.workdir, f"lists{k}.{s}")
        os.makedirs(wd, exist_ok=True)
        path = os.path.join(wd, "in.lists")
        with open(path, "w") as f:
            f.write(head + tail)
        got[s] = et.thermo(et.run(a, path, with_pair(dict(rod, **vars_), f"simd {s}"),
                                   log="log.lists"))
    nrows = [sum(len(b["Step"]) for b in got[s]) for s in ("yes", "no")]
    c.true(f"{name}: the same thermo blocks and rows", len(got["yes"]) == len(got["no"]) >= 2
           and nrows[0] == nrows[1] >= 6, f"{len(got['no'])} blocks, rows {nrows}")
    worst, col = max(et.worst_difference(bn, by) for bn, by in zip(got["no"], got["yes"]))
    print(f"INFO {name}: worst relative difference {worst:.3e} in {col}")
    c.less(f"{name}: simd yes vs simd no, max relative difference", worst, TOL,
           "summation order and FMA only")

# ---- options outside the vector pass: a silent fallback to the scalar loop
for k, extra in enumerate(("xsph 0.5", "gradient bonet/lok")):
    logs = {s: et.run(a, ROD, with_pair(rod, f"{extra} simd {s}"), log=f"log.fb{k}.{s}")
            for s in ("yes", "no")}
    check_in_use(f"{extra}, simd yes", logs["yes"], False)
    c.true(f"{extra}, simd yes: no more warnings than simd no",
           logs["yes"].count("WARNING") == logs["no"].count("WARNING"), "the fallback is silent")
    c.true(f"{extra}: simd yes thermo identical to simd no",
           et.production_thermo(logs["yes"]) == et.production_thermo(logs["no"]),
           "the same scalar code path, bit for bit")
c.done()
