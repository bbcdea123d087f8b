/* ----------------------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   internal to pair esph/solid (its .cpp files): the slots of its per-atom
   work arrays and the small pair helpers its passes share
------------------------------------------------------------------------- */

#ifndef LMP_PAIR_ESPH_SOLID_SLOTS_H
#define LMP_PAIR_ESPH_SOLID_SLOTS_H

#include "esph_contact.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace ESPHSolid {

using namespace ESPH;

// slots of the accumulator array acc[i][*]
// real particles
static constexpr int A_G = 0;         // 0..8: G = sum_j m_j (v_j - v_i) (x) grad_i W_ij
static constexpr int A_AVHEAT = 9;    // viscous heating
static constexpr int A_HEAT = 10;     // artificial heat transfer
static constexpr int A_NSUM = 11;     // 11..13: sum_k n_k W_ik over boundary particles k
static constexpr int A_DSUM = 14;     // sum_k W_ik (x_k - x_i).n_k
static constexpr int A_WSUM = 15;     // sum_k W_ik
// 16..24: M_i = sum_j m_j (x_j - x_i) (x) grad_i W_ij, summed by the pair loop (gradient
// corrected) or by the correction pass before it (gradient bonet/lok)
static constexpr int A_M = 16;
static constexpr int A_XSPH = 25;    // 25..27: sum_j m_j / rhobar_ij (v_j - v_i) W_ij (xsph)
static constexpr int A_GW = 28;      // sum_k W_ik over own boundary particles with a gap
static constexpr int A_GG = 29;      // sum_k W_ik (gap_k + dt gapdot_k)
static constexpr int A_GV = 30;      // sum_k W_ik gapdot_k
// end of the gap slots, communicated together: A_GW..A_GV of real particles (slot 31
// A_FSUM with friction), B_GAP..B_GAP+3 of boundary particles
static constexpr int GAP_END = 32;
// 32..37: sum_k W_ik n_k (x) n_k over own boundary particles (Voigt), the cone of the
// surface (contact normal cone)
static constexpr int A_NN = 32;
// 38..40: sum over the real particle's cross-body pairs of the couple of the pair force
// about the contact point (contact/couple yes, contact_couple())
static constexpr int A_CT = 38;
// the check of the boundary normals at a fresh start: a normal is off when its cosine with
// the direction away from its body's real particles is below NORMAL_CHECK_COS; a warning
// when more than NORMAL_CHECK_SHARE of them are
static constexpr double NORMAL_CHECK_COS = 0.5, NORMAL_CHECK_SHARE = 0.05;
// values per atom of the largest forward communication (the hoisted quantities): 12 +
// 6 contact geometry + 6 normal cone + 2 heat + 1 switch + 6 reconstruction
static constexpr int FORWARD_MAX = 12 + 6 + 6 + 2 + 1 + 6;
// neighbours per block of the pair loop (distances and kernel first, then the pairs)
static constexpr int NBLOCK = 64;
// length that regularises the alignment score of two boundary particles, and below which
// an open gap counts as touching (round-off of coinciding faces), in h0
static constexpr double GAP_EPS = 1.0e-6;
// a contact pair's normal force below this share of its stress scale (rho c^2 on the pair's
// kernel gradient) is round-off: it neither pushes nor pulls (pair_loop())
static constexpr double FN_ROUNDOFF = 1.0e-12;

// optional pair terms, bits of the last template parameter of pair_loop()
static constexpr int EXTRA_ASTRESS = 1;
static constexpr int EXTRA_XSPH = 2;
static constexpr int EXTRA_FRICTION = 4;
static constexpr int EXTRA_RIGID = 8;
static constexpr int EXTRA_VISC = 16;    // visc/switch or visc/recon
static constexpr int EXTRA_CONE = 32;    // contact/normal cone alone (the friction and rigid
                                         // variants have the cones at run time)
// friction: the Coulomb forces of all the cross-body pairs of a real particle, summed by
// the pair loop in this slot (unused otherwise by real particles) for friction_pass()
static constexpr int A_FSUM = 31;
// friction (friction_pass()): the dashpot of a particle's pairs together stops their slip
// within STICK_STEPS steps, so that they cannot reverse it (one step is unstable on the
// network of pairs: +89 % energy on sticking slabs); their spring would stop it within
// SPRING_STEPS steps (its period about 2 pi sqrt(SPRING_STEPS) steps)
static constexpr double STICK_STEPS = 2.0;
static constexpr double SPRING_STEPS = 16.0;
// boundary particles
static constexpr int B_A = 0;        // 0..8: sum_p V_p v_p (x) grad_k W_kp
static constexpr int B_B = 9;        // 9..11: sum_p V_p grad_k W_kp
static constexpr int B_VSUM = 12;    // 12..14: sum_p V_p W_kp v_p
static constexpr int B_WSUM = 15;    // sum_p V_p W_kp
static constexpr int B_M = 16;       // 16..24: sum_p V_p (x_p - x_k) (x) grad_k W_kp
static constexpr int B_XSUM = 25;    // 25..27: sum_p V_p W_kp (x_p - x_k)
static constexpr int B_GAP = 28;     // 28..31: facing partners (contact_bnd_merge)

// slots of the hoisted array hq[i][*]: one row per atom (owned and ghost), in blocks of 8
// that the vector pass (pair_esph_solid_simd.cpp) loads whole, so that its rows are this
// array's. A boundary particle's row has mass, density and sound speed 0
static constexpr int Q_X = 0;    // 0..2 position (filled for the vector pass only)
static constexpr int Q_M = 3;    // mass (vector pass only)
static constexpr int Q_V = 4;    // 4..6 predicted velocity
static constexpr int Q_RHO = 7;
static constexpr int Q_C = 8;
static constexpr int Q_A = 9;         // 9..14 sigma / rho^2 (Voigt)
static constexpr int Q_BODY = 15;     // body (vector pass only)
static constexpr int Q_D = 16;        // 16..21 strain rate D_i of the reconstruction (visc/recon)
static constexpr int Q_ALPHA = 22;    // the switched viscosity coefficient alpha_i (visc/switch)
static constexpr int Q_H = 23;
static constexpr int Q_E = 24;
static constexpr int Q_ZETA = 25;
static constexpr int Q_N = 26;       // 26..28 normal
static constexpr int Q_GAP = 29;     // surface gap (d_esph_gap)
static constexpr int Q_GAPV = 30;    // its rate (d_esph_gapv)
static constexpr int Q_ENG = 31;     // engagement with another body (d_esph_eng)
// a boundary particle, whose sigma / rho^2 is 0, has in those slots (for the vector pass):
// its normal, 1 if it has a gap (else 0), its gap forecast gap + dt gapdot and its gap
// rate (both 0 without a gap): add_gap_sums()'s terms
static constexpr int Q_BN = Q_A, Q_BGFLAG = Q_A + 3, Q_BGAP = Q_A + 4, Q_BGAPV = Q_A + 5;
// with the artificial stress only (not communicated: computed for ghosts from Q_A)
static constexpr int Q_R = 32;        // 32..37 artificial stress R / rho^2 (Voigt)
static constexpr int Q_RFLAG = 38;    // 1 if R != 0
// with the gradient correction bonet/lok: B_i (9, row major) in the last columns, from qcol_b;
// with contact/normal cone the cone C_i (Voigt, 6) after it, from qcol_n

enum {
  COMM_HOIST,
  COMM_ACC,
  COMM_NORMALS,
  COMM_GAPS,
  COMM_ATOM_CONTACT,
  COMM_CORR,
  COMM_COUPLE,
  COMM_TOUCH,
  COMM_FRIC,
  COMM_FRIC_FOUND
};

static constexpr double BIG_DT = 1.0e300;

/* ----------------------------------------------------------------------
   solid rule: the gap of a cross-body pair, the gaps of both particles
   brought to the present with their rates
------------------------------------------------------------------------- */

inline double solid_gap(const double *qi, const double *qj, double dt)
{
  return contact_gap_pair(qi[Q_GAP] + dt * qi[Q_GAPV], qj[Q_GAP] + dt * qj[Q_GAPV]);
}

// conditioning of the gradient correction's M: r = |det M| / (|M|_F^2 rho), a lower bound of
// its smallest singular value over rho; a full neighbourhood has r = 1/3, a face 1/4.5, a
// corner of a cube 1/6. Below COND_LO the neighbourhood is nearly flat in one direction (a
// body one particle thick) and the inverse would amplify noise without bound: the plain
// gradient is used; up to COND_HI the two are blended, so that nothing switches abruptly
static constexpr double COND_LO = 0.02, COND_HI = 0.05;

/* ----------------------------------------------------------------------
   M of the correction from its sums (row major), the out-of-plane diagonal
   set to rho, its inverse, and the weight beta of the corrected gradient
   against the plain one (1 where M is well conditioned, falling to 0 from
   COND_HI to COND_LO); false below COND_LO (the plain gradient is used)
------------------------------------------------------------------------- */

inline bool correction_inverse(const double *m, double rho, int dim, Eigen::Matrix3d &M,
                               Eigen::Matrix3d &Minv, double &beta)
{
  M << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  for (int d = dim; d < 3; d++) M(d, d) = rho;
  // the inverse by the cofactors, whose first row gives the determinant
  const double c00 = M(1, 1) * M(2, 2) - M(1, 2) * M(2, 1);
  const double c01 = M(1, 2) * M(2, 0) - M(1, 0) * M(2, 2);
  const double c02 = M(1, 0) * M(2, 1) - M(1, 1) * M(2, 0);
  const double sdet = M(0, 0) * c00 + M(0, 1) * c01 + M(0, 2) * c02;
  const double det = fabs(sdet);
  const double scale = rho * M.squaredNorm();
  if (!(det > COND_LO * scale)) return false;
  const double id = 1.0 / sdet;
  Minv << c00 * id, (M(0, 2) * M(2, 1) - M(0, 1) * M(2, 2)) * id,
      (M(0, 1) * M(1, 2) - M(0, 2) * M(1, 1)) * id, c01 * id,
      (M(0, 0) * M(2, 2) - M(0, 2) * M(2, 0)) * id, (M(0, 2) * M(1, 0) - M(0, 0) * M(1, 2)) * id,
      c02 * id, (M(0, 1) * M(2, 0) - M(0, 0) * M(2, 1)) * id,
      (M(0, 0) * M(1, 1) - M(0, 1) * M(1, 0)) * id;
  beta = (det < COND_HI * scale) ? (det / scale - COND_LO) / (COND_HI - COND_LO) : 1.0;
  return true;
}

/* ----------------------------------------------------------------------
   the correction matrix's pair term: m[3a+b] += (s x[a]) g[b], i.e.
   m += s x (x) g (row major)
------------------------------------------------------------------------- */

inline void add_outer(double *m, double s, const double *x, const double *g)
{
  for (int a = 0; a < 3; a++) {
    const double xa = s * x[a];
    m[3 * a] += xa * g[0];
    m[3 * a + 1] += xa * g[1];
    m[3 * a + 2] += xa * g[2];
  }
}

/* ----------------------------------------------------------------------
   sums for the normal (eq. 30) and depth of real particle p from boundary
   particle k: dx = x_i - x_j and sgn = +1 if k == i, -1 if k == j, so that
   x_k - x_p = sgn dx
------------------------------------------------------------------------- */

inline void add_normal_sums(double *ap, double w, double sgn, const double *dx, const double *nk)
{
  ap[A_NSUM] += w * nk[0];
  ap[A_NSUM + 1] += w * nk[1];
  ap[A_NSUM + 2] += w * nk[2];
  ap[A_DSUM] += w * (sgn * dx[0] * nk[0] + sgn * dx[1] * nk[1] + sgn * dx[2] * nk[2]);
  ap[A_WSUM] += w;
}

/* ----------------------------------------------------------------------
   contact/couple: the couple t of a cross-body pair, half to each particle
   (aj nullptr: j is another rank's)
------------------------------------------------------------------------- */

inline void add_couple(double *ai, double *aj, const double *t)
{
  for (int a = 0; a < 3; a++) ai[A_CT + a] += 0.5 * t[a];
  if (aj)
    for (int a = 0; a < 3; a++) aj[A_CT + a] += 0.5 * t[a];
}

/* ----------------------------------------------------------------------
   second moment of the boundary normals around real particle p (the cone)
------------------------------------------------------------------------- */

inline void add_cone_sums(double *ap, double w, const double *nk)
{
  ap[A_NN] += w * nk[0] * nk[0];
  ap[A_NN + 1] += w * nk[1] * nk[1];
  ap[A_NN + 2] += w * nk[2] * nk[2];
  ap[A_NN + 3] += w * nk[0] * nk[1];
  ap[A_NN + 4] += w * nk[0] * nk[2];
  ap[A_NN + 5] += w * nk[1] * nk[2];
}

/* ----------------------------------------------------------------------
   real particle p takes the gap of its own body's boundary particle k (with
   kernel weight w), extrapolated by dt with its rate to the present
------------------------------------------------------------------------- */

inline void add_gap_sums(double *ap, double w, const double *qk, double dt)
{
  if (qk[Q_GAP] >= GAP_NONE) return;
  ap[A_GW] += w;
  ap[A_GG] += w * (qk[Q_GAP] + dt * qk[Q_GAPV]);
  ap[A_GV] += w * qk[Q_GAPV];
}

/* ----------------------------------------------------------------------
   boundary particles i and j of different bodies: gap candidate for both
   (the same number seen from either side), see esph_contact.h
------------------------------------------------------------------------- */

inline void bnd_gap_pair(double *ai, double *aj, const double *qi, const double *qj,
                         const double *dx, double eps, double reach2, int plane)
{
  const double xab[3] = {-dx[0], -dx[1], -dx[2]};
  const double vab[3] = {qj[Q_V] - qi[Q_V], qj[Q_V + 1] - qi[Q_V + 1], qj[Q_V + 2] - qi[Q_V + 2]};
  double c, g, gd;
  if (!contact_bnd_gap(qi + Q_N, qj + Q_N, xab, vab, eps, reach2, plane, c, g, gd)) return;
  contact_bnd_keep(ai + B_GAP, c, g, gd);
  if (aj) contact_bnd_keep(aj + B_GAP, c, g, gd);
}

/* ----------------------------------------------------------------------
   visc/recon: v_ij . x_ij of the velocities reconstructed to the midpoint
   of the pair (Frontiere, Raskin and Owen 2017; Rosswog 2020):
     v_ij* = v_ij - phi (D_i + D_j) x_ij / 2,
   with the strain rates D (Voigt) of the last force computation and the
   slope limiter phi of the rates along the pair a = x_ij . D x_ij, which
   is symmetric in i and j (the pair's result does not depend on which of
   the two the neighbour list holds): van Leer 4 a_i a_j / (a_i + a_j)^2,
   minmod min(a_i, a_j) / max(a_i, a_j); 0 where the rates have opposite
   signs (an extremum or a front). A linear field (a_i = a_j) has phi = 1
   and v_ij* . x_ij = 0.
------------------------------------------------------------------------- */

inline double recon_slope(const double *d, const double *x)
{
  return d[0] * x[0] * x[0] + d[1] * x[1] * x[1] + d[2] * x[2] * x[2] +
      2.0 * (d[3] * x[0] * x[1] + d[4] * x[0] * x[2] + d[5] * x[1] * x[2]);
}

inline double recon_vr(double vr, const double *di, const double *dj, const double *dx, int limiter)
{
  const double ai = recon_slope(di, dx);
  const double aj = recon_slope(dj, dx);
  const double p = ai * aj;
  if (p <= 0.0) return vr;
  // van Leer: phi = 4 p / (a_i + a_j)^2, and phi (a_i + a_j) / 2 = 2 p / (a_i + a_j)
  if (limiter == 1) return vr - 2.0 * p / (ai + aj);
  const double phi = std::min(fabs(ai), fabs(aj)) / std::max(fabs(ai), fabs(aj));
  return vr - 0.5 * phi * (ai + aj);
}

}    // namespace ESPHSolid

#endif
