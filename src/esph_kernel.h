/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

// SPH kernels for the ESPH package: cubic B-spline (Monaghan & Lattanzio 1985,
// the seed paper's kernel) and Wendland C2, normalised in 1D, 2D and 3D.
// Support radius 2h for both. Pure math, no LAMMPS dependency: unit-tested alone.

#ifndef LMP_ESPH_KERNEL_H
#define LMP_ESPH_KERNEL_H

#include <cmath>

namespace ESPH {

enum KernelType { CUBIC = 0, WENDLAND = 1 };

static constexpr double KERNEL_SUPPORT = 2.0;    // support radius in units of h

/* normalisation sigma_D / h^D of the kernel of type k in dimension dim */

inline double kernel_norm(int k, int dim, double h)
{
  static constexpr double PI = 3.14159265358979323846;
  double s;
  if (k == CUBIC) {
    s = (dim == 1) ? 2.0 / 3.0 : (dim == 2) ? 10.0 / (7.0 * PI) : 1.0 / PI;
  } else {
    // Wendland C2 (Dehnen & Aly 2012 form, support 2h): W = s/h^D (1 - q/2)^4 (2q + 1);
    // in 1D the C2 function is (1 - q/2)^3 (1.5q + 1)
    s = (dim == 1) ? 5.0 / 8.0 : (dim == 2) ? 7.0 / (4.0 * PI) : 21.0 / (16.0 * PI);
  }
  double hd = h;
  for (int d = 1; d < dim; d++) hd *= h;
  return s / hd;
}

/* kernel value w and gradient factor dw (dW/dr / r) in one evaluation.
   norm = kernel_norm(k, dim, h), hinv = 1/h, r = distance.
   grad_i W_ij = dw * (x_i - x_j). Returns false outside the support. */

inline bool kernel_eval(int k, int dim, double norm, double hinv, double r, double &w, double &dw)
{
  const double q = r * hinv;
  if (q >= KERNEL_SUPPORT) {
    w = dw = 0.0;
    return false;
  }
  double dwdq;
  if (k == CUBIC) {
    if (q < 1.0) {
      w = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
      dwdq = -3.0 * q + 2.25 * q * q;
    } else {
      const double t = 2.0 - q;
      w = 0.25 * t * t * t;
      dwdq = -0.75 * t * t;
    }
  } else {
    const double t = 1.0 - 0.5 * q;
    if (dim == 1) {
      w = t * t * t * (1.5 * q + 1.0);
      dwdq = -3.0 * q * t * t;    // d/dq = -1.5 t^2 (1.5q+1) + 1.5 t^3 = -3 q t^2
    } else {
      const double t3 = t * t * t;
      w = t3 * t * (2.0 * q + 1.0);
      dwdq = -5.0 * q * t3;    // d/dq = -2 t^3 (2q+1) + 2 t^4 = -5 q t^3
    }
  }
  w *= norm;
  // dW/dr / r = norm * dwdq * hinv / r; at r = 0 the gradient vanishes (dwdq ~ q)
  dw = (r > 0.0) ? norm * dwdq * hinv / r : 0.0;
  return true;
}

}    // namespace ESPH

#endif
