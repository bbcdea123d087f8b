"""Helpers for the ESPH physics tests: run LAMMPS, read thermo output and the
ROD_IMPACT summary line, check values against references with stated tolerances,
and close with the plain 'N passed, N failed' line that CTest output readers know."""
import argparse
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
EXAMPLES = os.path.join(ROOT, "examples")


def parse_args():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--workdir", required=True)
    a = p.parse_args()
    a.lmp = os.path.abspath(a.lmp)
    a.workdir = os.path.abspath(a.workdir)
    os.makedirs(a.workdir, exist_ok=True)
    # a fresh copy of the examples per test run: never run stale inputs
    shutil.rmtree(os.path.join(a.workdir, "examples"), ignore_errors=True)
    return a


def run(args, infile, variables=None, np=1, log="log.lammps", timeout=900, flags=()):
    """run lmp -in infile with -var overrides (and more command-line flags, e.g.
    ("-sf", "omp", "-pk", "omp", "2")); return the log text. An example input
    (path relative to examples/) runs in a copy of the examples tree inside the work dir,
    so that inputs that include others (../rod_impact/in.rod_impact) find them."""
    if os.path.isabs(infile):
        cwd, name = os.path.dirname(infile), os.path.basename(infile)
    else:
        tree = os.path.join(args.workdir, "examples")
        if not os.path.isdir(tree):
            shutil.copytree(EXAMPLES, tree, ignore=shutil.ignore_patterns("log.*"))
        cwd, name = os.path.join(tree, os.path.dirname(infile)), os.path.basename(infile)
    cmd = [args.lmp, "-in", name, "-log", log, "-nocite", "-screen", "none"] + list(flags)
    for k, v in (variables or {}).items():
        cmd += ["-var", k, str(v)]
    if np > 1:
        cmd = [args.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np)] + cmd
    r = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    logpath = os.path.join(cwd, log)
    text = open(logpath).read() if os.path.exists(logpath) else ""
    args.lastdir = cwd
    if r.returncode != 0:
        sys.stdout.write(r.stdout[-3000:] + r.stderr[-3000:] + text[-3000:])
        raise RuntimeError("lmp failed: " + " ".join(cmd))
    return text


def run_fresh(lmp, infile, variables=None, timeout=1800):
    """run(): the input infile (an absolute path) copied into a fresh temporary directory, so
    that parallel runs of one input neither share a log nor write into the source tree (the
    benches that run many variants side by side); return the log text"""
    import tempfile
    import types
    with tempfile.TemporaryDirectory() as tmp:
        a = types.SimpleNamespace(lmp=lmp, workdir=tmp, mpirun="mpirun")
        path = write_input(a, os.path.basename(infile), open(infile).read())
        return run(a, path, variables, timeout=timeout)


def rule_keywords(name):
    """pair_style esph/solid keywords of a contact rule named on a bench's command line:
    'default' none, 'touch' contact/gap touch (the default), 'projection' contact/gap
    projection, anything else as written"""
    name = name.strip()
    return {"default": "", "touch": "contact/gap touch",
            "projection": "contact/gap projection"}.get(name, name)


def write_input(args, name, text):
    path = os.path.join(args.workdir, name)
    with open(path, "w") as f:
        f.write(text)
    return path


def boundary_dump(fname):
    """LAMMPS lines that dump the boundary particles (zero mass) of the current state: id,
    body, position, normal, sorted by id at full precision (numpy.loadtxt(..., skiprows=9))"""
    return ("variable bm atom mass==0\ngroup bnd variable bm\n"
            f"write_dump bnd custom {fname} id i_esph_body x y z d2_esph_n[1] d2_esph_n[2] "
            "d2_esph_n[3] modify sort id format float %.17g\n")


def small_blocks(r0, pair_extra=""):
    """LAMMPS lines of two small iron bodies on a 0.1 mm lattice touching at x = 0: body 1 in
    the block r0 ("xlo xhi ylo yhi zlo zhi", metres), body 2 in 0..0.4 x 0..0.6 x -0.2..0.2 mm;
    pair_style esph/solid (h 0.13 mm, pair_extra appended), fix esph/integrate, a 5 ns step,
    generated boundary particles; groups b0, b1, real and rb0 (body 1's real particles)"""
    return f"""units si
atom_style atomic
atom_modify map array
boundary f f f
region box block -0.001 0.001 -0.001 0.001 -0.001 0.001
create_box 2 box
lattice sc 0.0001 origin 0.5 0.5 0.5
region r0 block {r0} units box
create_atoms 1 region r0
region r1 block 0 0.0004 0 0.0006 -0.0002 0.0002 units box
create_atoms 2 region r1
group b0 region r0
group b1 region r1
pair_style esph/solid 0.00013 {pair_extra}
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix int all esph/integrate
timestep 5e-09
set group all mass 7.85e-09
set group b0 i_esph_body 1
set group b1 i_esph_body 2
fix bnd all esph/boundary spacing 0.0001
variable massive atom mass>0.0
group real variable massive
group rb0 intersect b0 real
"""


def source_input(args, name):
    """a copy of the input tests/physics/<name> in the work directory (the logs of its runs
    go there, not into the source tree); its path"""
    src = os.path.join(os.path.dirname(os.path.abspath(__file__)), name)
    with open(src) as f:
        return write_input(args, name, f.read())


def thermo(text):
    """list of runs, each a dict column -> list of floats"""
    runs = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].split()[:1] == ["Step"]:
            cols = lines[i].split()
            data = {c: [] for c in cols}
            i += 1
            while i < len(lines) and not lines[i].startswith("Loop time"):
                parts = lines[i].split()
                if len(parts) == len(cols):
                    try:
                        vals = [float(x) for x in parts]
                    except ValueError:
                        i += 1
                        continue
                    for c, v in zip(cols, vals):
                        data[c].append(v)
                i += 1
            runs.append(data)
        i += 1
    return runs


def profiles(path):
    """blocks of a fix ave/chunk profile file: {timestep: array of (x [mm], v_x)}"""
    sys.path.insert(0, os.path.join(ROOT, "tools"))
    from plot_rod_impact import read_profiles
    return read_profiles(path)


def summary(text, key="ROD_IMPACT"):
    for line in text.splitlines():
        if line.startswith(key + " "):
            return {k: float(v) for k, v in re.findall(r"(\w+)=([-+0-9.eE]+)", line)}
    raise RuntimeError(key + " line not found")


class Checks:
    def __init__(self, title):
        self.title = title
        self.npass = self.nfail = 0
        print("==", title)

    def near(self, name, value, ref, tol, why):
        ok = abs(value - ref) <= tol
        self._report(ok, f"{name}: {value:.6g} vs {ref:.6g} (tol {tol:.3g}; {why})")

    def less(self, name, value, limit, why):
        ok = value < limit
        self._report(ok, f"{name}: {value:.6g} < {limit:.6g} ({why})")

    def true(self, name, cond, why):
        self._report(bool(cond), f"{name} ({why})")

    def _report(self, ok, msg):
        if ok:
            self.npass += 1
        else:
            self.nfail += 1
        print(("PASS " if ok else "FAIL ") + msg, flush=True)

    def done(self):
        print(f"{self.npass} passed, {self.nfail} failed")
        sys.exit(0 if self.nfail == 0 else 1)


def production_thermo(text):
    """the longest thermo block of a log (the production run, not a closing run 0)"""
    return max(thermo(text), key=lambda r: len(r["Step"]))


def worst_difference(r1, r2):
    """largest relative difference over the columns of two thermo blocks (each column
    scaled by its largest magnitude, at least 1e-4): (value, column); inf if the blocks
    differ in length"""
    worst, col = 0.0, ""
    for k, x in r1.items():
        x, y = np.array(x), np.array(r2.get(k, []))
        if len(x) != len(y):
            return np.inf, k + " (length)"
        d = np.abs(x - y).max() / max(np.abs(x).max(), 1e-4)
        if d > worst:
            worst, col = d, k
    return worst, col


def example_scene(name, runline, extra=""):
    """the example input up to its run command (thermo printed with 17 digits), and what
    read_restart does not restore: styles, fixes, computes, output (variables survive
    clear)"""
    text = open(os.path.join(EXAMPLES, name, "in." + name)).read()
    head = text[:text.index(runline)].replace("format float %.15g", "format float %.17g")
    head = head.replace("\nthermo_style", "\n" + extra + "thermo_style", 1) if extra else head
    keep = []
    for line in head.splitlines():
        w = line.split()
        if w and (w[0] in ("pair_style", "pair_coeff", "neighbor", "neigh_modify", "compute",
                           "thermo_style", "thermo_modify", "thermo")
                  or line.startswith("fix             int") or "esph/boundary" in line):
            keep.append(line)
    return head, "\n".join(keep) + "\n"


def block_scene(fixopts, pstyle="", pcoeff="", extra_out="", xcols=""):
    """two iron blocks, the upper one hitting the lower at (60, -70, 0) m/s (sliding
    contact from the first step, 0.1 mm): (text of a fresh start without a run command, the
    styles and output to define again after read_restart)"""
    styles = f"""pair_style esph/solid 1e-4 {pstyle}
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69 {pcoeff}
fix int all esph/integrate {fixopts}
"""
    output = f"""fix bnd all esph/boundary spacing 1e-4
neighbor 2e-5 bin
variable px atom mass*vx
variable py atom mass*vy
variable pz atom mass*vz
compute mom all reduce sum v_px v_py v_pz
{extra_out}
thermo_style custom step time dt ke pe etotal c_mom[1] c_mom[2] c_mom[3] f_int[1] f_int[2] &
  f_int[3] f_int[4] f_int[5] f_int[6] f_int[7] f_int[8] {xcols}
thermo_modify format float %.17g
thermo 5
"""
    fresh = f"""units si
atom_style atomic
atom_modify map array
boundary f f f
region box block -0.0004 0.0013 -0.0009 0.0007 -0.0003 0.0009
create_box 2 box
lattice sc 1e-4 origin 0.5 0.5 0.5
region ra block 0 8e-4 -6e-4 0 0 6e-4 units box
region rb block 1e-4 7e-4 0 4e-4 0 6e-4 units box
create_atoms 1 region ra
create_atoms 2 region rb
group A region ra
group B region rb
region rtop block INF INF 2e-4 INF INF INF units box
group Btop region rtop
{styles}timestep 4e-9
set group all mass 7.85e-9
set group A i_esph_body 1
set group B i_esph_body 2
velocity B set 60 -70 0 units box
{output}"""
    return fresh, styles + output
