#!/usr/bin/env python3
"""Example-script regression runner (after LAMMPS tools/regression-tests).

For every examples/<case>/in.<name> listed in the config, and every reference log
log.<date>.<name>.g++.<np> beside it, run `mpirun -np <np> lmp -in in.<name> <args>` in a
scratch copy of the example folder, extract the thermo blocks of both logs and compare
them column by column: same number of runs, same columns, same steps, and every value
within abs or rel tolerance. Prints one PASS/FAIL line per comparison and closes with
'N passed, N failed'.

usage: run_regression.py --lmp LMP [--mpirun MPIRUN] --config CFG --workdir DIR EXAMPLES_DIR
       run_regression.py ... --gen-ref   (write new reference logs instead of comparing)
"""
import argparse
import datetime
import fnmatch
import glob
import os
import re
import shutil
import subprocess
import sys

import yaml


def thermo_blocks(text):
    runs, lines, i = [], text.splitlines(), 0
    while i < len(lines):
        if lines[i].split()[:1] == ["Step"]:
            cols = lines[i].split()
            rows = []
            i += 1
            while i < len(lines) and not lines[i].startswith("Loop time"):
                p = lines[i].split()
                if len(p) == len(cols):
                    try:
                        rows.append([float(x) for x in p])
                    except ValueError:
                        pass
                i += 1
            runs.append((cols, rows))
        i += 1
    return runs


def tol_for(cfg, name, col):
    tol = dict(cfg.get("default", {}).get("tolerance", {}).get("*", {"abs": 0, "rel": 0}))
    per = cfg.get("inputs", {}).get(name, {}).get("tolerance", {})
    for pat, t in per.items():
        if fnmatch.fnmatch(col, pat):
            tol = dict(t)
    return tol["abs"], tol["rel"]


def compare(cfg, name, ref, new):
    if len(ref) != len(new):
        return False, f"{len(new)} thermo blocks, reference has {len(ref)}"
    worst = ""
    for (rc, rr), (nc, nr) in zip(ref, new):
        if rc != nc:
            return False, f"columns {nc} differ from reference {rc}"
        if len(rr) != len(nr):
            return False, f"{len(nr)} thermo rows, reference has {len(rr)}"
        for a, b in zip(rr, nr):
            for col, x, y in zip(rc, a, b):
                ab, rl = tol_for(cfg, name, col)
                if abs(x - y) > ab + rl * abs(x):
                    return False, f"{col} at step {a[0]:.0f}: {y!r} vs reference {x!r}"
        worst = f"{len(rr)} rows x {len(rc)} columns within tolerance"
    return True, worst


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--lmp", required=True)
    p.add_argument("--mpirun", default="mpirun")
    p.add_argument("--config", required=True)
    p.add_argument("--workdir", required=True)
    p.add_argument("--gen-ref", action="store_true")
    p.add_argument("--nprocs", default="1,4")
    p.add_argument("examples")
    a = p.parse_args()
    a.lmp = os.path.abspath(a.lmp)
    a.examples = os.path.abspath(a.examples)
    shutil.rmtree(a.workdir, ignore_errors=True)
    cfg = yaml.safe_load(open(a.config))
    npass = nfail = 0
    for name, icfg in cfg.get("inputs", {}).items():
        for inp in sorted(glob.glob(os.path.join(a.examples, "*", name))):
            case_dir = os.path.dirname(inp)
            short = name[3:]
            for np_ in [int(x) for x in a.nprocs.split(",")]:
                refs = sorted(glob.glob(os.path.join(case_dir, f"log.*.{short}.g++.{np_}")))
                if not refs and not a.gen_ref:
                    continue
                # a scratch copy of the whole examples tree: inputs may include others
                tree = os.path.join(a.workdir, f"np{np_}")
                if not os.path.isdir(tree):
                    shutil.copytree(a.examples, tree, ignore=shutil.ignore_patterns("log.*"))
                work = os.path.join(tree, os.path.basename(case_dir))
                cmd = [a.lmp, "-in", name, "-log", "log.test", "-nocite", "-screen", "none"]
                cmd += icfg.get("args", "").split()
                if np_ > 1:
                    cmd = [a.mpirun, "--allow-run-as-root", "--oversubscribe", "-np", str(np_)] + cmd
                try:
                    r = subprocess.run(cmd, cwd=work, capture_output=True, text=True,
                                       timeout=icfg.get("timeout", cfg["default"]["timeout"]))
                    ok_run = r.returncode == 0
                    err = (r.stdout + r.stderr)[-1500:]
                except subprocess.TimeoutExpired:
                    ok_run, err = False, "timeout"
                label = f"{os.path.basename(case_dir)}/{name} np={np_}"
                if not ok_run:
                    nfail += 1
                    print(f"FAIL {label}: run failed\n{err}")
                    continue
                text = open(os.path.join(work, "log.test")).read()
                if a.gen_ref:
                    date = datetime.date.today().strftime("%d%b%y")
                    for old in refs:
                        os.remove(old)
                    dst = os.path.join(case_dir, f"log.{date}.{short}.g++.{np_}")
                    shutil.copy(os.path.join(work, "log.test"), dst)
                    print(f"wrote {dst}")
                    continue
                ok, msg = compare(cfg, name, thermo_blocks(open(refs[-1]).read()),
                                  thermo_blocks(text))
                print(("PASS " if ok else "FAIL ") + f"{label} vs {os.path.basename(refs[-1])}: {msg}")
                npass += ok
                nfail += not ok
    if not a.gen_ref:
        if npass + nfail == 0:
            print("FAIL no example with a reference log found")
            nfail = 1
        print(f"{npass} passed, {nfail} failed")
    sys.exit(1 if nfail else 0)


if __name__ == "__main__":
    main()
