#!/usr/bin/env python3
"""The plugin is autoloaded from LAMMPS_PLUGIN_PATH into a PLUGIN-enabled lmp of this
LAMMPS version, and a small ESPH input then runs with it (no 'plugin load' in the input).
usage: check_autoload.py HOST_LMP PLUGIN_DIR"""
import os, subprocess, sys, tempfile

lmp, plugdir = sys.argv[1], sys.argv[2]
env = dict(os.environ, LAMMPS_PLUGIN_PATH=plugdir)
env["LD_LIBRARY_PATH"] = os.path.join(os.path.dirname(os.path.dirname(lmp)), "lib") + \
    os.pathsep + env.get("LD_LIBRARY_PATH", "")
inp = """units si
atom_style atomic
region box block 0 1e-3 0 1e-3 0 1e-3
create_box 1 box
lattice sc 1e-4 origin 0.5 0.5 0.5
create_atoms 1 box
pair_style esph/solid 1e-4
pair_coeff * * rho0 7850 shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix 1 all esph/integrate
neighbor 2e-5 bin
set group all mass 7.85e-9
velocity all set 1.0 0 0 units box
timestep 1e-9
run 10
"""
with tempfile.TemporaryDirectory() as d:
    with open(os.path.join(d, "in.auto"), "w") as f:
        f.write(inp)
    r = subprocess.run([lmp, "-in", "in.auto", "-log", "none"], cwd=d, env=env,
                       capture_output=True, text=True, timeout=120)
out = r.stdout + r.stderr
ok = r.returncode == 0 and "Loaded 1 plugins from" in out and "Loop time" in out
print(out[-2000:])
print("1 passed, 0 failed" if ok else "0 passed, 1 failed")
sys.exit(0 if ok else 1)
