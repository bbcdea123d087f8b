#!/usr/bin/env python3
"""Amplification factor per step of fix esph/integrate's two schemes on one elastic mode,
v' = w s, s' = -w v (a velocity and a stress amplitude; w dt = C for the fastest 1D mode of
the cubic spline at h = dx). Printed: w dt, then the spectral radius of one step of the
predicted scheme (state v, s and the stored rates of the last force computation) and of
the staggered scheme (kick, rate pass, state update, force pass), and of the predicted
scheme with the rates of its prediction extrapolated from the last two computations
(fix esph/integrate extrapolate yes, the default: r + (a - 1) (r - r_prev), a = 4/3, which
cancels the (w dt)^4 term of the predicted scheme's growth). Above 1: the mode grows.
Used by doc/visc_switch.md section 5 and doc/fix_esph_integrate.rst."""
import numpy as np


def radius(step, n):
    m = np.zeros((n, n))
    for k in range(n):
        e = np.zeros(n)
        e[k] = 1.0
        m[:, k] = step(e)
    return max(abs(np.linalg.eigvals(m)))


def predicted(w):
    # state: v^n, s^n, force rate F^n = w s~^n, stress rate D^n = -w v~^n (dt = 1)
    def step(st):
        v, s, f, d = st
        vh, sh = v + 0.5 * f, s + 0.5 * d        # half steps
        vp, sp = vh + 0.5 * f, sh + 0.5 * d      # prediction of the end of the step
        f1, d1 = w * sp, -w * vp                 # force computation at the prediction
        return [vh + 0.5 * f1, sh + 0.5 * d1, f1, d1]
    return radius(step, 4)


def extrapolated(w, a=4.0 / 3.0):
    # state: v^n, s^n, F^n, D^n and the rates of the computation before, F^(n-1), D^(n-1)
    def step(st):
        v, s, f, d, fp, dp = st
        vh, sh = v + 0.5 * f, s + 0.5 * d                      # half steps
        fx, dx = f + (a - 1.0) * (f - fp), d + (a - 1.0) * (d - dp)
        vp, sp = vh + 0.5 * fx, sh + 0.5 * dx                  # extrapolated prediction
        f1, d1 = w * sp, -w * vp
        return [vh + 0.5 * f1, sh + 0.5 * d1, f1, d1, f, d]
    return radius(step, 6)


def staggered(w):
    # state: v^n, s^n, force rate F^n = w s^n
    def step(st):
        v, s, f = st
        vh = v + 0.5 * f              # kick
        s1 = s - w * vh               # rate pass at v^(n+1/2), stress to n+1
        f1 = w * s1                   # force pass
        return [vh + 0.5 * f1, s1, f1]
    return radius(step, 3)


if __name__ == "__main__":
    print("w_dt predicted staggered extrapolated   (predicted - 1, extrapolated - 1)")
    for w in (0.016, 0.05, 0.1, 0.2, 0.3, 0.4, 0.6, 0.8, 1.0, 1.5, 1.9):
        p, x = predicted(w), extrapolated(w)
        print(f"{w:5.3f} {p:.7f} {staggered(w):.7f} {x:.7f}   ({p - 1:+.2e}, {x - 1:+.2e})")
