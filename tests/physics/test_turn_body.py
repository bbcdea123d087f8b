#!/usr/bin/env python3
"""fix esph/boundary turn body: the boundary normals of a body in free rigid-like spin turn
with the body (tests/physics/in.turn_body: a block spinning about (1, 0, 3) x 1e4 rad/s and a
sphere about y at 2e4 rad/s, about 30 degrees in 1000 steps).
- The normals after the run against the start normals turned by each body's rotation (the
  best-fit rotation of its real particles, Kabsch): within 0.01 degree (measured 0.001;
  the bodies vibrate a little, so their normals are not exactly rigidly turned).
- A block built across the periodic x boundary (two pieces at both ends of the box, image
  flags 0) turns as the same block built in the middle of the box (a hostile round found
  its normals 28 degrees off when the positions were unwrapped by the image flags), on 1
  and 2 ranks, and fix esph/integrate's angular momentum watch does not warn about it.
- Each fix esph/boundary keeps its own turn setting: with turn body for the block only,
  the block's normals are those of the run with turn body for both, the sphere's those of
  the run with turn spin for both (to round-off; they differ by about 1e-6 between the
  settings).
About 10 s."""
import os

import numpy as np

import esphtest as et

a = et.parse_args()
c = et.Checks("turn body: normals turned with their body")
INP = et.source_input(a, "in.turn_body")
BOX_X = 6.0e-3


def dump(path):
    """rows id mass x y z nx ny nz body, sorted by id"""
    lines = open(path).read().splitlines()
    k = [i for i, l in enumerate(lines) if l.startswith("ITEM: ATOMS")][0]
    d = np.array([[float(v) for v in l.split()] for l in lines[k + 1:] if l.strip()])
    return d[np.argsort(d[:, 0])]


def run(tag, np_=1, **var):
    log = et.run(a, INP, dict(tag=tag, **var), np=np_, log=f"log.{tag}")
    c.true(f"{tag}: no angular momentum warning", "angular momentum of body" not in log,
           "free bodies keep their angular momentum (the block across the periodic boundary "
           "must be seen whole)")
    return dump(os.path.join(a.workdir, f"dump.start.{tag}")), \
        dump(os.path.join(a.workdir, f"dump.end.{tag}"))


def turn_error(d0, d1, body, xc):
    """largest angle [deg] between the end normals and the start normals turned by the
    best-fit rotation of the body's real particles (x by the minimum image about xc)"""
    def pos(d, sel):
        p = d[sel][:, 2:5].copy()
        p[:, 0] -= xc + BOX_X * np.floor((p[:, 0] - xc) / BOX_X + 0.5)
        return p
    real = (d0[:, 8] == body) & (d0[:, 1] > 0)
    bnd = (d0[:, 8] == body) & (d0[:, 1] == 0)
    P, Q = pos(d0, real), pos(d1, real)
    P -= P.mean(0)
    Q -= Q.mean(0)
    U, _, Vt = np.linalg.svd(P.T @ Q)
    s = np.sign(np.linalg.det(Vt.T @ U.T))
    R = Vt.T @ np.diag([1.0, 1.0, s]) @ U.T
    angle = np.degrees(np.arccos(np.clip((np.trace(R) - 1.0) / 2.0, -1.0, 1.0)))
    n0, n1 = d0[bnd][:, 5:8], d1[bnd][:, 5:8]
    cos = np.clip(((n0 @ R.T) * n1).sum(1) / np.linalg.norm(n1, axis=1), -1.0, 1.0)
    return np.degrees(np.arccos(cos)).max(), angle


runs = {}
runs["straddle"] = run("straddle", st=1)
runs["middle"] = run("middle", st=0)
runs["straddle_np2"] = run("straddle_np2", np_=2, st=1)
runs["block_only"] = run("block_only", st=1, b2="turn spin")
runs["spin"] = run("spin", st=1, b1="turn spin", b2="turn spin")

for tag, xc in (("straddle", 3e-3), ("middle", 0.0), ("straddle_np2", 3e-3)):
    d0, d1 = runs[tag]
    for body, name in ((1, "block"), (2, "sphere")):
        err, angle = turn_error(d0, d1, body, xc if body == 1 else 0.0)
        print(f"INFO {tag} {name}: turned {angle:.2f} deg, normals off by {err:.2e} deg")
        c.true(f"{tag} {name}: the body turned", angle > 10.0, f"{angle:.1f} degrees")
        c.less(f"{tag} {name}: normals vs rigidly turned start normals [deg]", err, 0.01,
               "turn body is exact for a rigid rotation; the bodies vibrate a little "
               "(measured 0.001)")


def body_diff(r1, r2, body):
    s = r1[1][:, 8] == body
    return np.abs(r1[1][s][:, 5:8] - r2[1][s][:, 5:8]).max()


c.less("straddle, np 2 vs np 1: normals", max(body_diff(runs["straddle_np2"], runs["straddle"],
                                                        b) for b in (1, 2)), 1e-12,
       "the bodies' spins are sums over ranks: round-off")
c.less("block only turn body: block's normals vs both turn body", body_diff(
    runs["block_only"], runs["straddle"], 1), 1e-13, "its own fix's setting: round-off")
c.less("block only turn body: sphere's normals vs both turn spin", body_diff(
    runs["block_only"], runs["spin"], 2), 1e-13, "its own fix's setting: round-off")
dd = body_diff(runs["straddle"], runs["spin"], 2)
c.less("the settings differ: sphere's normals, turn body vs turn spin", -dd, -1e-9,
       f"{dd:.1e}: otherwise the comparisons above would not tell the settings apart")
c.done()
