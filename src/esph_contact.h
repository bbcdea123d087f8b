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

// Contact rule between two real particles of different bodies (seed paper 4.3).
// Pure math, no LAMMPS dependency: unit-tested alone.
//
// Inputs: surface normals n_i, n_j (unit outward normals of each particle's own body,
// eq. 30, or zero when unknown), depths d_i, d_j of the particles below their body's
// surface, separation xij = x_i - x_j, relative velocity vij = v_i - v_j, and the pair
// force on i, fij, that full SPH coupling would apply.
//
// Common normal: nc ~ w_i n_i - w_j n_j (coherence-weighted, see contact_normal), pointing
// from i into the other body.
// Rules:
//   PAPER : interact iff the particles approach along nc, (vij.nc)(xij.nc) < 0 (eq. 31).
//   SOLID : (default) interact iff the surfaces touch, gap = -xij.nc - d_i - d_j <= tol,
//           and either the particles approach along nc or the normal force is compressive
//           (pushes i away from j); the transmitted normal force is clipped to compression.
// Either way only normal components couple: the force is projected on nc and the relative
// velocity entering the strain rate is (vij.nc) nc.

#ifndef LMP_ESPH_CONTACT_H
#define LMP_ESPH_CONTACT_H

#include <cmath>

namespace ESPH {

enum ContactRule { CONTACT_OFF = 0, CONTACT_SOLID = 1, CONTACT_PAPER = 2 };

/* common normal from i towards j. The normals of real particles carry their coherence
   as length: |n| = |sum_k n_k W_ik| / sum_k W_ik, 1 inside a flat face, less near edges
   and corners where the boundary normals disagree. Weighting each normal by |n|^8 lets a
   flat face decide against an edge touching it (off-axis impact), and averages two
   alike surfaces. Falls back on -xij/|xij| when the normals cancel. */

inline void contact_normal(const double *ni, const double *nj, const double *xij, double *nc)
{
  const double ci2 = ni[0] * ni[0] + ni[1] * ni[1] + ni[2] * ni[2];
  const double cj2 = nj[0] * nj[0] + nj[1] * nj[1] + nj[2] * nj[2];
  // |n|^8 n / |n| = |n|^7 n
  const double wi = ci2 * ci2 * ci2 * sqrt(ci2);
  const double wj = cj2 * cj2 * cj2 * sqrt(cj2);
  double a0 = wi * ni[0] - wj * nj[0], a1 = wi * ni[1] - wj * nj[1], a2 = wi * ni[2] - wj * nj[2];
  double len2 = a0 * a0 + a1 * a1 + a2 * a2;
  if (len2 < 1.0e-12 * (wi * wi + wj * wj) || len2 == 0.0) {
    a0 = -xij[0];
    a1 = -xij[1];
    a2 = -xij[2];
    len2 = a0 * a0 + a1 * a1 + a2 * a2;
  }
  const double inv = (len2 > 0.0) ? 1.0 / sqrt(len2) : 0.0;
  nc[0] = a0 * inv;
  nc[1] = a1 * inv;
  nc[2] = a2 * inv;
}

/* surface gap between the particles' body surfaces along nc (negative: overlap) */

inline double contact_gap(const double *xij, const double *nc, double di, double dj)
{
  return -(xij[0] * nc[0] + xij[1] * nc[1] + xij[2] * nc[2]) - di - dj;
}

/* gate: true when the pair interacts. vn = vij.nc, xn = xij.nc (< 0 normally),
   fn = fij.nc (< 0: compressive, pushes i away from j) */

inline bool contact_gate(int rule, double gap, double gaptol, double vn, double xn, double fn)
{
  const bool approach = vn * xn < 0.0;
  if (rule == CONTACT_PAPER) return approach;
  if (gap > gaptol) return false;
  return approach || fn < 0.0;
}

}    // namespace ESPH

#endif
