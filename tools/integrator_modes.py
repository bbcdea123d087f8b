#!/usr/bin/python3
"""Amplification of one undamped elastic mode per step of fix esph/integrate's predicted
scheme, with the last rates in the prediction (extrapolate no) and with the rates
extrapolated from the last two force computations (extrapolate yes, weight a = 4/3):
the numbers of doc/fix_esph_integrate.rst.

The mode is v' = w s, s' = -w v (a stress-velocity pair of linear elasticity). One step of
the scheme with the time step h, force F = w s~ and rate R = -w v~ evaluated at the
predicted state (v~, s~):
    v+ = v + h/2 F,  s+ = s + h/2 R                                  (half step)
    v~ = v+ + h/2 Fx, s~ = s+ + h/2 Rx                               (prediction)
    F' = w s~, R' = -w v~                                            (force computation)
    v' = v+ + h/2 F', s' = s+ + h/2 R'                               (second half)
with Fx = F + (a - 1) (F - F_prev) (a = 1: the former prediction). The state (v, s, F, R,
F_prev, R_prev) maps linearly; the largest |eigenvalue| is the amplification per step.

usage: tools/integrator_modes.py [--a 1.3333] [--wdt 0.05 0.1 0.2 0.4 0.6 0.8]
"""
import argparse

import numpy as np


def step_matrix(a, wdt):
    m = np.zeros((6, 6))
    h = wdt
    for k in range(6):
        x = np.zeros(6)
        x[k] = 1.0
        v, s, F, R, Fp, Rp = x
        vh, sh = v + h / 2 * F, s + h / 2 * R
        Fx, Rx = F + (a - 1.0) * (F - Fp), R + (a - 1.0) * (R - Rp)
        vp, sp = vh + h / 2 * Fx, sh + h / 2 * Rx
        Fn, Rn = sp, -vp
        m[:, k] = [vh + h / 2 * Fn, sh + h / 2 * Rn, Fn, Rn, F, R]
    return m


def main():
    p = argparse.ArgumentParser()
    p.add_argument("--a", type=float, nargs="+", default=[1.0, 4.0 / 3.0])
    p.add_argument("--wdt", type=float, nargs="+", default=[0.016, 0.05, 0.1, 0.2, 0.4, 0.6, 0.8])
    args = p.parse_args()
    for a in args.a:
        cells = []
        for wdt in args.wdt:
            ev = np.linalg.eigvals(step_matrix(a, wdt))
            phys = ev[np.argmin(abs(ev - np.exp(1j * wdt)))]
            cells.append(f"{wdt:g}: |G|-1 = {max(abs(ev)) - 1:+.2e}, phase {np.angle(phys) / wdt - 1:+.1e}")
        print(f"MODES a={a:.6g}  " + "  ".join(cells))


if __name__ == "__main__":
    main()
