#!/usr/bin/env python3
"""OpenMP threads (pair esph/solid/omp, fix esph/integrate/omp; -sf omp -pk omp N) give the
answer of the styles without threads to round-off, alone and with MPI.

Scenes: the 3D rod impact at 0.25 mm (contact from the first step; with newton off on 2
ranks; in 1D and 2D; with an initial gap of
one spacing, where boundary particles merge their surface gaps across threads; with the
options visc/switch, visc/recon, heat, hvar, xsph, artstress and gradient bonet/lok, which
add columns to the sums; off-axis with fix esph/boundary turn body), three bodies in a row (compute esph/contact, one row per
interface), the per-atom contact force of compute esph/atom, the staggered scheme, and an
oblique block impact split into two runs and continued from a restart file in a new process.

Checks:
- -sf omp picks the /omp styles (the log names them);
- one thread (-pk omp 1) is the serial code: every thermo value identical;
- 2 and 3 threads (3: chunks of unequal size, more threads than cores) against no threads:
  every thermo column within 1e-10 of its largest magnitude. A thread sums its chunk of the
  neighbour list, the partners outside its chunk go to private rows added afterwards: the
  same pair terms in another summation order, 1e-16 per sum, carried but not amplified over
  a few hundred steps (test_mpi measures 3e-14 for the MPI order change); a lost or doubled
  pair term is 1e-3 or more;
- two runs with 2 threads are identical (the chunks and the order of the folds are fixed:
  no atomics, no dependence on timing);
- 2 MPI ranks x 2 threads against 1 rank and against 2 ranks without threads (1e-10);
- a run with 2 threads split in two, and continued from a restart file, against the
  uninterrupted run with 2 threads (1e-10: the neighbour list rebuilt at a run boundary
  moves the chunk boundaries, a summation-order change like the ones above)."""
import os
import re

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("OpenMP threads: the answer without threads to round-off")
TOL = 1.0e-10


def omp(n):
    return ("-sf", "omp", "-pk", "omp", str(n))


def compare(name, r1, r2, tol=TOL):
    worst, col = et.worst_difference(r1, r2)
    print(f"INFO {name}: worst relative difference {worst:.3e} in {col}")
    c.less(f"{name}: max relative difference", worst, tol, "summation order only")


ROD = "rod_impact/in.rod_impact"
rod = {"dim": 3, "dx": 0.25, "Limp": 10.0, "Ltgt": 10.0, "tend": 2.0, "thermo_every": 10,
       "out": 0}

# ---- the rod, touching start: 1, 2, 3 threads
logs = {}
logs[0] = et.run(a, ROD, rod, log="log.rod.t0")
for n in (1, 2, 3):
    logs[n] = et.run(a, ROD, rod, log=f"log.rod.t{n}", flags=omp(n))
c.true("-sf omp: pair esph/solid/omp and fix esph/integrate/omp in use",
       "esph/solid/omp" in logs[2] and re.search(r"fix\s+int\s+all\s+esph/integrate", logs[2])
       and "esph/solid/omp" not in logs[0], "the neighbour list names the pair style")
ref = et.production_thermo(logs[0])
t1 = et.production_thermo(logs[1])
c.true("1 thread: thermo identical to no threads", t1 == ref, "the serial code path")
for n in (2, 3):
    compare(f"rod, {n} threads vs none", ref, et.production_thermo(logs[n]))
again = et.run(a, ROD, rod, log="log.rod.t2b", flags=omp(2))
c.true("2 threads twice: thermo identical", et.production_thermo(again) ==
       et.production_thermo(logs[2]), "fixed chunks and fold order")
s0, s2 = et.summary(logs[0]), et.summary(logs[2])
print("INFO ROD_IMPACT none:", s0)
print("INFO ROD_IMPACT 2 threads:", s2)

# ---- MPI x threads
mpi1 = et.run(a, ROD, rod, np=2, log="log.rod.np2")
mpi2 = et.run(a, ROD, rod, np=2, log="log.rod.np2t2", flags=omp(2))
compare("rod, 2 ranks x 2 threads vs 1 rank", ref, et.production_thermo(mpi2))
compare("rod, 2 ranks x 2 threads vs 2 ranks", et.production_thermo(mpi1),
        et.production_thermo(mpi2))

# ---- newton off (pairs with ghost partners computed on both ranks), 1D and 2D
noff = dict(rod, newton="off")
compare("rod, newton off, 2 ranks x 2 threads vs newton on, no threads", ref,
        et.production_thermo(et.run(a, ROD, noff, np=2, log="log.noff.np2t2", flags=omp(2))))
for dim, dx in ((1, 0.1), (2, 0.25)):
    v = dict(rod, dim=dim, dx=dx, Limp=20.0, Ltgt=20.0, tend=3.0)
    d0 = et.production_thermo(et.run(a, ROD, v, log=f"log.d{dim}.t0"))
    compare(f"rod {dim}D, 2 threads vs none", d0,
            et.production_thermo(et.run(a, ROD, v, log=f"log.d{dim}.t2", flags=omp(2))))

# ---- initial gap of one spacing (boundary particles' surface gaps from several threads):
# the gap closes at 5 us, the run ends in contact
gap = dict(rod, gap=1, tend=7.0)
gl0 = et.run(a, ROD, gap, log="log.gap.t0")
gl2 = et.run(a, ROD, gap, log="log.gap.t2", flags=omp(2))
c.true("rod with gap 1: in contact at the end", et.summary(gl0)["contact_time_us"] > 1.0,
       "the comparison covers the contact")
compare("rod with gap 1, 2 threads vs none", et.production_thermo(gl0),
        et.production_thermo(gl2))

# ---- options that add columns and passes
opts = dict(rod, pair_extra="visc/switch 0.1 0.2 visc/recon vanleer heat 0.1 1.0 hvar 2.0 "
            "xsph 0.3 artstress 0.3 4 2.5e-4")
o0 = et.production_thermo(et.run(a, ROD, opts, log="log.opt.t0"))
compare("rod with visc/switch, visc/recon, heat, hvar, xsph, artstress: 2 threads vs none", o0,
        et.production_thermo(et.run(a, ROD, opts, log="log.opt.t2", flags=omp(2))))
bl = dict(rod, pair_extra="gradient bonet/lok")
b0 = et.production_thermo(et.run(a, ROD, bl, log="log.bl.t0"))
compare("rod with gradient bonet/lok: 2 threads vs none", b0,
        et.production_thermo(et.run(a, ROD, bl, log="log.bl.t2", flags=omp(2))))
st = dict(rod, int_extra="scheme staggered")
st0 = et.production_thermo(et.run(a, ROD, st, log="log.st.t0"))
compare("rod, scheme staggered: 2 threads vs none", st0,
        et.production_thermo(et.run(a, ROD, st, log="log.st.t2", flags=omp(2))))
# fix esph/boundary turn body (the bodies' rigid spins, one serial sum after the threaded
# pass), off-axis so that the bodies turn
tb = dict(rod, bnd_extra="turn body", yoff=0.5)
tb0 = et.production_thermo(et.run(a, ROD, tb, log="log.tb.t0"))
compare("off-axis rod, fix esph/boundary turn body: 2 threads vs none", tb0,
        et.production_thermo(et.run(a, ROD, tb, log="log.tb.t2", flags=omp(2))))
# contact/couple: the couples summed in the threads' rows, passed on after the threaded pass
# (off-axis: the bodies turn; the default gradient (full list) and bonet/lok (half list))
for grad in ("corrected", "bonet/lok"):
    cp = dict(rod, yoff=0.5, pair_extra=f"gradient {grad} contact/couple yes")
    cp0 = et.production_thermo(et.run(a, ROD, cp, log="log.cpl.t0"))
    compare(f"off-axis rod, gradient {grad} contact/couple yes: 2 threads vs none", cp0,
            et.production_thermo(et.run(a, ROD, cp, log="log.cpl.t2", flags=omp(2))))
cone = {"dx": 0.25, "fit": 16, "smooth": 1.0, "normal": "cone"}
OBL = "oblique_rod/in.oblique_rod"
cn0 = et.production_thermo(et.run(a, OBL, cone, log="log.cone.t0"))
compare("oblique rod, contact/normal cone: 2 threads vs none", cn0,
        et.production_thermo(et.run(a, OBL, cone, log="log.cone.t2", flags=omp(2))))

# friction: the threads' cross-body pairs recorded, bounded and applied after the loop
fr = {"dx": 0.25, "tend": 3.0, "friction": 0.3}
SLAB = "oblique_slabs/in.oblique_slabs"
fr0 = et.production_thermo(et.run(a, SLAB, fr, log="log.fric.t0"))
compare("oblique slabs, friction 0.3: 2 threads vs none", fr0,
        et.production_thermo(et.run(a, SLAB, fr, log="log.fric.t2", flags=omp(2))))

# ---- three bodies: compute esph/contact per interface
CR = "newton_cradle/in.newton_cradle"
cr = {"dx": 0.25, "thermo_every": 50}
k0 = et.summary(et.run(a, CR, cr, log="log.cradle.t0"), "NEWTON_CRADLE")
k2 = et.summary(et.run(a, CR, cr, log="log.cradle.t2", flags=omp(2)), "NEWTON_CRADLE")
for key in ("first12_us", "tc12_us", "first23_us", "tc23_us", "v1", "v2", "v3"):
    # printed with 4 decimals: one unit of the last digit
    c.near(f"cradle {key}: 2 threads vs none", k2[key], k0[key], 1.0e-4, "printed precision")
for key in ("J12", "J23"):
    c.near(f"cradle {key}: 2 threads vs none (relative)", k2[key] / k0[key], 1.0, 1.0e-5,
           "printed with 6 digits")
for key in ("ep12", "ep23", "row1_I", "row1_J", "row2_I", "row2_J"):
    c.true(f"cradle {key}: 2 threads as none ({k2[key]:.0f})", k2[key] == k0[key], "integers")

# ---- per-atom contact force (compute esph/atom) in mid-contact, split run and restart:
# test_continuation's oblique block impact
DUMP = ("compute ca all esph/atom contact/force contact\n"
        "dump da all custom 20 atom.*.dump id c_ca[1] c_ca[2] vx vy vz\n"
        "dump_modify da sort id format float %.17g\n")
AGAIN = et.block_scene("cfl 0.3")[1]


def block(run_text, dump=""):
    return et.block_scene("cfl 0.3", extra_out=dump)[0] + run_text


def dumps(dirname, step):
    rows = np.loadtxt(os.path.join(dirname, f"atom.{step}.dump"), skiprows=9)
    return rows[np.argsort(rows[:, 0])]


for tag, fl in (("t0", ()), ("t2", omp(2))):
    d = os.path.join(a.workdir, f"atom_{tag}")
    os.makedirs(d, exist_ok=True)
    p = os.path.join(d, "in.block")
    with open(p, "w") as f:
        f.write(block("run 60\n", DUMP))
    et.run(a, p, log="log.atom", flags=fl)
ad0 = dumps(os.path.join(a.workdir, "atom_t0"), 40)
ad2 = dumps(os.path.join(a.workdir, "atom_t2"), 40)
fn_scale = np.abs(ad0[:, 1]).max()
c.true("block impact: contact force present at step 40", fn_scale > 0.0 and
       (ad0[:, 2] > 0).sum() > 10, "the per-atom values are exercised")
c.less("per-atom contact/force, 2 threads vs none (relative to its largest value)",
       np.abs(ad2[:, 1] - ad0[:, 1]).max() / fn_scale, TOL, "summation order only")
c.true("per-atom contact, 2 threads as none", (ad2[:, 2] == ad0[:, 2]).all(), "flags")
vscale = np.abs(ad0[:, 3:6]).max()
c.less("per-atom v, 2 threads vs none (relative to the largest speed)",
       np.abs(ad2[:, 3:6] - ad0[:, 3:6]).max() / vscale, TOL, "summation order only")

# ---- split run and restart with 2 threads against the uninterrupted run with 2 threads


def block_run(tag, texts):
    d = os.path.join(a.workdir, f"split_{tag}")
    os.makedirs(d, exist_ok=True)
    out = []
    for k, text in enumerate(texts):
        p = os.path.join(d, f"in.part{k}")
        with open(p, "w") as f:
            f.write(text)
        out.append(et.run(a, p, log=f"log.part{k}", flags=omp(2)))
    rows = {}
    for log in out:
        for blk in et.thermo(log):
            for i, step in enumerate(blk["Step"]):
                rows[step] = {k: v[i] for k, v in blk.items()}
    steps = sorted(rows)
    return {k: [rows[s][k] for s in steps] for k in rows[steps[0]]}


full = block_run("full", [block("run 100\n")])
split = block_run("split", [block("run 30\nrun 70\n")])
compare("block, 2 threads: split run vs uninterrupted", full, split)
restart = block_run("restart", [block("run 30\nwrite_restart r.bin\n"),
                                 "read_restart r.bin\n" + AGAIN + "run 70\n"])
compare("block, 2 threads: restart in a new process vs uninterrupted", full, restart)
c.done()
