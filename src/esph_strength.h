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

// Hypoelastic deviatoric stress rate with the Jaumann rate (seed paper 2.3).
// Cauchy convention (tension positive): sigma = -P I + S,
//   dS/dt = 2 G (D - tr(D)/3 I) + W S - S W,
//   D = (L + L^T)/2 (eq. 14), W = (L - L^T)/2 (eq. 17), L_ab = d v_a / d x_b.
// The seed paper's eqs. 16/18 print the spin terms with inconsistent signs and
// indices; this is the standard objective form (Gray, Monaghan & Swift 2001).
// Voigt order of the 6 stored components: xx yy zz xy xz yz.
// Pure math, no LAMMPS dependency: unit-tested alone.

#ifndef LMP_ESPH_STRENGTH_H
#define LMP_ESPH_STRENGTH_H

#include <Eigen/Core>

#include <cmath>

namespace ESPH {

inline Eigen::Matrix3d voigt_to_matrix(const double *s)
{
  Eigen::Matrix3d m;
  m << s[0], s[3], s[4], s[3], s[1], s[5], s[4], s[5], s[2];
  return m;
}

inline void matrix_to_voigt(const Eigen::Matrix3d &m, double *s)
{
  s[0] = m(0, 0);
  s[1] = m(1, 1);
  s[2] = m(2, 2);
  s[3] = m(0, 1);
  s[4] = m(0, 2);
  s[5] = m(1, 2);
}

/* Jaumann-rate deviatoric stress rate for velocity gradient L, stress S, shear modulus G */

inline void jaumann_rate(const Eigen::Matrix3d &L, const double *s, double G, double *dsdt)
{
  // the spin w_ab = W_ab (a < b) and the strain rate D; W S - S W is symmetric, its entry
  // ab is (W S)_ab + (W S)_ba, written out for the six stored components
  const double w01 = 0.5 * (L(0, 1) - L(1, 0));
  const double w02 = 0.5 * (L(0, 2) - L(2, 0));
  const double w12 = 0.5 * (L(1, 2) - L(2, 1));
  const double sxx = s[0], syy = s[1], szz = s[2], sxy = s[3], sxz = s[4], syz = s[5];
  const double g2 = 2.0 * G;
  const double dev = (L(0, 0) + L(1, 1) + L(2, 2)) / 3.0;
  dsdt[0] = g2 * (L(0, 0) - dev) + 2.0 * (w01 * sxy + w02 * sxz);
  dsdt[1] = g2 * (L(1, 1) - dev) + 2.0 * (w12 * syz - w01 * sxy);
  dsdt[2] = g2 * (L(2, 2) - dev) - 2.0 * (w02 * sxz + w12 * syz);
  dsdt[3] = G * (L(0, 1) + L(1, 0)) + w01 * (syy - sxx) + w02 * syz + w12 * sxz;
  dsdt[4] = G * (L(0, 2) + L(2, 0)) + w01 * syz + w02 * (szz - sxx) - w12 * sxy;
  dsdt[5] = G * (L(1, 2) + L(2, 1)) - w01 * sxz - w02 * sxy + w12 * (szz - syy);
}

/* von Mises equivalent stress sqrt(3/2 S:S) of a deviator in Voigt order
   (xx yy zz xy xz yz) */

inline double von_mises(const double *s)
{
  const double s2 =
      s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
  return sqrt(1.5 * s2);
}

/* von Mises plasticity with linear isotropic hardening, radial return: when the trial
   sigma_eq = sqrt(3/2 S:S) exceeds Y = Y0 + H epsp, the plastic strain grows by
   depsp = (sigma_eq - Y) / (3 G + H) and the deviator is scaled back onto the grown
   yield surface Y + H depsp. H = 0: perfect plasticity. Y0 <= 0: elastic. Returns depsp
   (0 when G = H = 0). The plastic work needs no extra term: the energy equation already
   receives the full stress power. */

inline double radial_return(double *s, double Y0, double H = 0.0, double G = 0.0, double epsp = 0.0)
{
  if (Y0 <= 0.0) return 0.0;
  const double seq = von_mises(s);
  const double Y = Y0 + H * epsp;
  if (seq <= Y) return 0.0;
  const double depsp = (3.0 * G + H > 0.0) ? (seq - Y) / (3.0 * G + H) : 0.0;
  const double f = (Y + H * depsp) / seq;
  for (int k = 0; k < 6; k++) s[k] *= f;
  return depsp;
}

}    // namespace ESPH

#endif
