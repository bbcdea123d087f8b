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
// The surface gap. Each body's surface is carried by its boundary particles (positions
// x_k, unit outward normals n_k). Two boundary particles a, b of different bodies face
// each other along nbar = (n_a - n_b) / |n_a - n_b| (only when their normals differ by
// more than 60 degrees, |n_a - n_b| > 1: side by side surfaces do not face); their gap
// is g_ab = (x_b - x_a).nbar, the same seen from a and from b. Each boundary particle
// keeps the gap to the partner that lies most nearly on that line, max |g_ab| / r_ab
// (ties: the smaller gap), with its rate (v_b - v_a).nbar: on two flat faces of any
// orientation that is their distance exactly; an edge or corner facing a face reads a
// smaller gap (its partners on the face lie sideways of the tilted nbar), which
// contact/gap plane bounds by the tangent planes (contact_bnd_gap).
// A real particle takes the kernel-weighted mean over the boundary particles of its own
// body (one force computation later, extrapolated with the rate to the time it is used);
// a pair of real particles of different bodies touches when either particle's gap is
// closed: gap_ij = min(g_i, g_j). The contact_gap_pair() result is GAP_NONE where neither
// particle has another body's surface within its kernel.
//
// Common normal: nc ~ w_i n_i - w_j n_j (coherence-weighted, see contact_normal), pointing
// from i into the other body; with contact/normal cone (an option of the solid rule; the
// default is this mean normal) turned into the direction common to both surfaces' cones of
// normals (contact_normal_cone), so that an edge meeting a face pushes along the face's
// normal.
// Rules:
//   PAPER : interact iff the particles approach along nc, (vij.nc)(xij.nc) < 0 (eq. 31).
//   SOLID : (default) the cross-body coupling is weighted by contact_pair_weight(), the
//           smoothed engagement of the particles (contact_engage): it rises over onset steps
//           once a particle's gap has closed and falls over as many once it has opened, and
//           is 0 across a gap larger than a cap; a pair whose normal force would not push
//           does not interact (no tension across contact).
// Either way only normal components couple: the force is projected on nc and the relative
// velocity entering the strain rate is (vij.nc) nc.

#ifndef LMP_ESPH_CONTACT_H
#define LMP_ESPH_CONTACT_H

#include "esph_strength.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

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

/* contact/normal cone (an option of the solid rule): the common normal as the
   direction that both surfaces admit. The cone of a real particle's surface is the second
   moment of its own body's boundary normals n_k around it, S = sum_k W_ik n_k n_k^T /
   sum_k W_ik (Voigt xx yy zz xy xz yz, trace 1), with every eigenvector counted fully
   whose eigenvalue is at least CONE_R0 of the largest, a smaller one in proportion:
     C = sum_a min(1, lambda_a / (CONE_R0 lambda_max)) v_a v_a^T.
   A flat face gives one direction (C = n n^T), an edge the plane of its two faces'
   normals, a corner all directions. CONE_R0 = sin^2(10 deg): normals that differ by more
   than about 10 degrees within the kernel make an edge; a face's scatter about its mean
   (a fitted staircase: ~1 degree) and the curvature of a body more than ~5 h in radius do
   not. */

static constexpr double CONE_R0 = 0.030153689607045803;    // sin^2(10 degrees)

inline void contact_cone(const double *s, double *cone)
{
  const Eigen::Matrix3d S = voigt_to_matrix(s);
  // the iterative solver: backward stable also for close eigenvalues (the closed form of
  // computeDirect() loses digits there, and decompositions would differ beyond round-off)
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(S);
  const Eigen::Vector3d lam = es.eigenvalues();    // increasing
  const Eigen::Matrix3d &V = es.eigenvectors();
  Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
  const double lmax = lam(2);
  if (lmax > 0.0)
    for (int a = 0; a < 3; a++) {
      const double g = std::min(1.0, std::max(0.0, lam(a) / (CONE_R0 * lmax)));
      if (g > 0.0) C += g * V.col(a) * V.col(a).transpose();
    }
  matrix_to_voigt(C, cone);
}

/* the common normal of a cross-body pair from the cones of both surfaces: the limit
   direction of M^k m, M = C_i + C_j + CONE_TIE m m^T, started at the mean normal m of
   contact_normal() (nc, in and out), which also breaks ties. An edge (a plane cone)
   against a face (one direction, in that plane) gives the face's normal, which the mean
   normal tilts towards the edge; two crossing edges the normal of both; two faces, or two
   curved surfaces, about their mean. M^k m is a continuous function of the cones (k =
   2^CONE_SQUARINGS, by repeated squaring with the trace scaled to 1): no eigenvector is
   chosen, nothing jumps when two directions compete. */

static constexpr double CONE_TIE = 0.05;
static constexpr int CONE_SQUARINGS = 5;

inline void contact_normal_cone(const double *ci, const double *cj, double *nc)
{
  Eigen::Matrix3d M = voigt_to_matrix(ci) + voigt_to_matrix(cj);
  const Eigen::Vector3d m(nc[0], nc[1], nc[2]);
  M += CONE_TIE * m * m.transpose();
  for (int k = 0; k < CONE_SQUARINGS; k++) {
    M = M * M;
    const double tr = M.trace();
    if (!(tr > 0.0)) return;
    M /= tr;
  }
  Eigen::Vector3d r = M * m;
  const double len = r.norm();
  if (!(len > 1.0e-12)) return;
  r /= len;
  nc[0] = r(0);
  nc[1] = r(1);
  nc[2] = r(2);
}

// no other body's surface in reach
static constexpr double GAP_NONE = 1.0e30;

/* candidate gap between boundary particles a and b of different bodies: xab = x_b - x_a,
   vab = v_b - v_a. Returns false when they do not face each other, or when b lies beyond
   the reach (reach2 = reach^2; 0: no limit); else the gap g, its rate gdot and the
   alignment score c = 1 + (|g| + eps) / (r + eps), larger is better: 2 for partners
   straight across, and for coincident ones. The length eps (a millionth of the smoothing
   length) makes the score continuous at r = 0: two boundary particles that coincide in
   exact arithmetic (touching faces) are a round-off distance apart in a rotated scene,
   where |g| / r alone would be 0 / 0.
   The reach is GAP_REACH boundary spacings, the kernel support at h = spacing: the gap is
   a property of the boundary particles, not of the smoothing length. Beyond it, with a
   larger h or hvar, an edge whose other body ends a spacing or more away sideways took
   the "gap" of oblique partners there (their sideways offset projected on the tilted
   difference of the normals: negative), and two blocks 0.32 spacings apart pushed each
   other from the first step. */

static constexpr double GAP_REACH = 2.0;

/* contact/gap touch (the default): two bodies interact only while they touch: the cells of
   two of their real particles meet, or two of their real particles within the kernel's
   reach are both engaged; and the real particles of a body have no surface gap until it
   touches another or has an engaged real particle. Where two bodies touch the projection
   decides, as from a touching start (their boundary
   particles keep their gaps all along, so the gaps have their rates and history when the
   touch comes). The cell of a particle is the cube of side s (the spacing) whose faces are
   normal to its nearest neighbours (lattice_frame(): the lattice cell of a simple cubic
   lattice in any orientation, turned and deformed with the body); two cells meet when no
   axis separates them (touch_cells()). On a lattice body that is where the faces, edges
   and corners of the bodies meet, at any lattice offset and orientation. A particle without
   three nearly normal neighbours near one spacing away (another lattice, an irregular
   distribution) has the cube aligned with the box. */

static constexpr double TOUCH_TOL = 0.02;
// a cell's neighbours lie TOUCH_SHELL_LO..TOUCH_SHELL_HI spacings away; two of them span
// different axes when |cos| < TOUCH_ORTHO, the third is normal to both when |cos| with
// their cross product is above TOUCH_NORMAL
static constexpr double TOUCH_SHELL_LO = 0.75, TOUCH_SHELL_HI = 1.25;
static constexpr double TOUCH_ORTHO = 0.3, TOUCH_NORMAL = 0.9;
// two cells can meet only while their centres are closer than this many spacings (the sum
// of the cubes' half diagonals, with the tolerance)
static constexpr double TOUCH_REACH = 1.7320508075688772 * (1.0 + TOUCH_TOL);

/* the frame of a particle's cell (three orthonormal rows f[0..2], f[3..5], f[6..8]) from
   the vectors d[3k..3k+2], k < n, to its neighbours of the same body, given in an order that
   does not depend on the ranks: of the neighbours TOUCH_SHELL_LO..HI spacings away, shortest
   first (ties in the given order), the first, the first nearly normal to it, and one nearly
   normal to both (in 2d the third axis is z), made orthonormal in that order. Shortest
   first keeps a compressed lattice's face diagonals out. Returns false, and the box's axes,
   without three such neighbours. */

inline bool lattice_frame(const double *d, int n, double s, int dim, double *f)
{
  const double lo2 = TOUCH_SHELL_LO * TOUCH_SHELL_LO * s * s;
  const double hi2 = TOUCH_SHELL_HI * TOUCH_SHELL_HI * s * s;
  std::vector<std::pair<double, int>> shell;
  for (int k = 0; k < n; k++) {
    const double *v = d + 3 * k;
    const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    if (v2 >= lo2 && v2 <= hi2) shell.emplace_back(v2, k);
  }
  std::stable_sort(shell.begin(), shell.end(),
                   [](const std::pair<double, int> &p, const std::pair<double, int> &q) {
                     return p.first < q.first;
                   });
  int a = -1, b = -1, c = -1;
  double e[9];
  for (const auto &sk : shell) {
    const double *v = d + 3 * sk.second;
    const double vl = sqrt(sk.first);
    if (a < 0) {
      a = sk.second;
      for (int q = 0; q < 3; q++) e[q] = v[q] / vl;
      continue;
    }
    const double ca = (v[0] * e[0] + v[1] * e[1] + v[2] * e[2]) / vl;
    if (b < 0) {
      if (fabs(ca) >= TOUCH_ORTHO) continue;
      const double u[3] = {v[0] - ca * vl * e[0], v[1] - ca * vl * e[1], v[2] - ca * vl * e[2]};
      const double ul = sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      b = sk.second;
      for (int q = 0; q < 3; q++) e[3 + q] = u[q] / ul;
      e[6] = e[1] * e[5] - e[2] * e[4];
      e[7] = e[2] * e[3] - e[0] * e[5];
      e[8] = e[0] * e[4] - e[1] * e[3];
      if (dim == 2) break;
      continue;
    }
    const double c3 = (v[0] * e[6] + v[1] * e[7] + v[2] * e[8]) / vl;
    if (fabs(c3) > TOUCH_NORMAL) {
      c = sk.second;
      break;
    }
  }
  const bool ok = (a >= 0 && b >= 0 && (c >= 0 || dim == 2));
  for (int q = 0; q < 9; q++) f[q] = ok ? e[q] : ((q % 4 == 0) ? 1.0 : 0.0);
  return ok;
}

/* two cells meet: cubes of sides (1 + TOUCH_TOL) si and (1 + TOUCH_TOL) sj (the spacings
   of the two particles' bodies; sj < 0: si) centred xij apart, with frames fi and fj
   (lattice_frame()), are not separated along any of the 15 axes of the separating axis
   theorem (the six face normals and the nine cross products of edges). With the box's
   frames on both: max(|x_ij|, |y_ij|, |z_ij|) <= (1 + TOUCH_TOL) (si + sj) / 2 */

inline bool touch_cells(const double *xij, const double *fi, const double *fj, double si,
                        double sj = -1.0)
{
  const bool same = !(sj >= 0.0) || sj == si;
  const double r = 0.5 * (1.0 + TOUCH_TOL) * si, rb = same ? r : 0.5 * (1.0 + TOUCH_TOL) * sj;
  auto separates = [&](const double *l) {
    double ri = 0.0, rj = 0.0;
    for (int a = 0; a < 3; a++) {
      ri += fabs(l[0] * fi[3 * a] + l[1] * fi[3 * a + 1] + l[2] * fi[3 * a + 2]);
      rj += fabs(l[0] * fj[3 * a] + l[1] * fj[3 * a + 1] + l[2] * fj[3 * a + 2]);
    }
    return fabs(l[0] * xij[0] + l[1] * xij[1] + l[2] * xij[2]) >
        (same ? r * (ri + rj) : r * ri + rb * rj);
  };
  for (int a = 0; a < 3; a++)
    if (separates(fi + 3 * a) || separates(fj + 3 * a)) return false;
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      const double *u = fi + 3 * a, *v = fj + 3 * b;
      const double l[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                           u[0] * v[1] - u[1] * v[0]};
      // (parallel edges: the face normals decide)
      if (l[0] * l[0] + l[1] * l[1] + l[2] * l[2] < 1.0e-12) continue;
      if (separates(l)) return false;
    }
  return true;
}

inline bool contact_bnd_gap(const double *na, const double *nb, const double *xab,
                            const double *vab, double eps, double reach2, int plane, double &c,
                            double &g, double &gdot)
{
  const double m[3] = {na[0] - nb[0], na[1] - nb[1], na[2] - nb[2]};
  const double m2 = m[0] * m[0] + m[1] * m[1] + m[2] * m[2];
  if (m2 <= 1.0) return false;
  const double r2 = xab[0] * xab[0] + xab[1] * xab[1] + xab[2] * xab[2];
  if (reach2 > 0.0 && r2 > reach2) return false;
  const double inv = 1.0 / sqrt(m2);
  g = (xab[0] * m[0] + xab[1] * m[1] + xab[2] * m[2]) * inv;
  gdot = (vab[0] * m[0] + vab[1] * m[1] + vab[2] * m[2]) * inv;
  c = 1.0 + (fabs(g) + eps) / (sqrt(r2) + eps);
  if (!plane) return true;
  // contact/gap plane: the tangent planes. b lies d_a = xab.n_a in front of a's plane, a
  // lies d_b = -xab.n_b in front of b's. A convex body lies behind each of its tangent
  // planes, so d_b > 0 is a lower bound of a's distance from b's body, d_a > 0 of b's from
  // a's (a negative one bounds nothing: a point beside a body lies behind the supporting
  // plane of an edge further along). The projection g is not where the normals differ in
  // direction (an edge or corner facing a face), where it turns a sideways offset into gap:
  // a cube's corner 0.32 spacings above a face reads -0.34. The gap is never below the
  // larger plane distance D, and a pair that a plane sees open is open: below 0 (a
  // projection that says closed) the candidate takes min(D, -g) > 0, continuous at g = 0.
  // Two faces have g = D: unchanged. The score stays the projection's (which partner lies
  // most nearly straight across); the candidate is the same seen from a and from b. What
  // is left of the early touch (0.06-0.21 spacings, bench/gap_lead) is that score: an edge
  // facing the other body's corner 1.5 spacings along it has both planes "penetrated" (D =
  // -0.32) and outranks the edge straight across (in.gap_edge at a gap of one spacing).
  // Not the default yet (pair_esph_solid.rst, bench/contact_offsets): on staircase normals
  // (a curved body with the generated normals and no fit) the steps' planes are not tangent
  // planes of a convex surface, and lattice spheres leave with 1.7 times the lateral
  // momentum
  const double da = xab[0] * na[0] + xab[1] * na[1] + xab[2] * na[2];
  const double db = -(xab[0] * nb[0] + xab[1] * nb[1] + xab[2] * nb[2]);
  double d = da, ddot = vab[0] * na[0] + vab[1] * na[1] + vab[2] * na[2];
  if (db > d) {
    d = db;
    ddot = -(vab[0] * nb[0] + vab[1] * nb[1] + vab[2] * nb[2]);
  }
  if (d > -g) {
    d = -g;
    ddot = -gdot;
  }
  if (d > g) {
    g = d;
    gdot = ddot;
  }
  return true;
}

/* the gap of a boundary particle is the mean over its candidates weighted by
   exp(KAPPA (c - c_max)): the candidate most nearly straight across decides, candidates
   whose score is within about 1/KAPPA of it share (two partners placed alike, e.g. by
   the symmetry of an edge). A continuous function of the candidates, unlike taking the
   best one: a near tie broken by round-off (a rotated scene, another MPI decomposition)
   moves the gap by round-off, not by the difference of the two candidates. On two flat
   faces every candidate has the same gap. The state best[4] = {c_max, sum w, sum w g,
   sum w gdot} (sum w = 0: no candidate) is updated one candidate at a time, and two
   partial states (other MPI ranks) merge, in any order, to the same result up to
   round-off. */

static constexpr double GAP_KAPPA = 200.0;
static constexpr int GAP_SLOTS = 4;

// scores further apart than this give weights below 4e-18, under the round-off of the
// leading weight: the worse side is dropped without evaluating the exponential
static constexpr double GAP_SCORE_CUT = 40.0 / GAP_KAPPA;

inline void contact_bnd_merge(double *best, const double *other)
{
  if (other[1] <= 0.0 || other[0] < best[0] - GAP_SCORE_CUT) return;
  if (best[1] <= 0.0 || best[0] < other[0] - GAP_SCORE_CUT) {
    for (int k = 0; k < GAP_SLOTS; k++) best[k] = other[k];
    return;
  }
  if (other[0] > best[0]) {
    const double s = exp(GAP_KAPPA * (best[0] - other[0]));
    best[0] = other[0];
    best[1] = best[1] * s + other[1];
    best[2] = best[2] * s + other[2];
    best[3] = best[3] * s + other[3];
  } else {
    const double s = exp(GAP_KAPPA * (other[0] - best[0]));
    best[1] += other[1] * s;
    best[2] += other[2] * s;
    best[3] += other[3] * s;
  }
}

inline void contact_bnd_keep(double *best, double c, double g, double gdot)
{
  const double one[GAP_SLOTS] = {c, 1.0, g, gdot};
  contact_bnd_merge(best, one);
}

/* the gap and its rate of a boundary particle from its state; false: no candidate */

inline bool contact_bnd_result(const double *best, double &g, double &gdot)
{
  if (best[1] <= 0.0) return false;
  g = best[2] / best[1];
  gdot = best[3] / best[1];
  return true;
}

/* gap of a pair of real particles of different bodies from their own gaps */

inline double contact_gap_pair(double gi, double gj)
{
  return gi < gj ? gi : gj;
}

/* engagement of a real particle with another body, from the gap it will have at the next
   force computation: it grows by 1/onset per step while that gap is closed and falls by
   as much while it is open (onset 0: 1 or 0 at once) */

inline double contact_engage(double eng, double gap_next, int onset)
{
  if (onset <= 0) return gap_next < 0.0 ? 1.0 : 0.0;
  const double e = (gap_next < 0.0) ? eng + 1.0 / onset : eng - 1.0 / onset;
  return e < 0.0 ? 0.0 : (e > 1.0 ? 1.0 : e);
}

/* weight of the cross-body coupling of a pair: the smoothed engagement S(e) =
   e^2 (3 - 2e) of the more engaged particle, so that a newly touching pair is coupled
   over onset steps and a separating one released over as many; never across a gap of
   more than cap (then 0) */

inline double contact_pair_weight(double gap, double cap, double ei, double ej)
{
  if (gap >= cap) return 0.0;
  const double e = ei > ej ? ei : ej;
  return e * e * (3.0 - 2.0 * e);
}

/* a boundary particle's normal n turned over a step dt by its spin, the antisymmetric part
   of its velocity gradient stored as (W_xy, W_xz, W_yz), i.e. omega = (-W_yz, W_xz, -W_xy)
   (eq. 17, dn/dt = W n = omega x n): Rodrigues' rotation by theta = |omega| dt, written
   with omega itself,
     n' = cos(theta) n + (sin(theta) / theta) dt omega x n
          + ((1 - cos(theta)) / theta^2) dt^2 omega (omega . n).
   A step turns a normal by a tiny angle (omega dt ~ 1e-5): below theta = 0.01 the series to
   theta^6 are exact to round-off (the next terms are theta^8 / 8! relative) and cost less
   than sin and cos. */

inline void rotate_by_spin(double *n, const double *spin, double dt)
{
  const double om[3] = {-spin[2], spin[1], -spin[0]};
  const double th2 = (om[0] * om[0] + om[1] * om[1] + om[2] * om[2]) * dt * dt;
  if (!(th2 > 0.0)) return;
  double ct, sinc, vers;
  if (th2 < 1.0e-4) {
    ct = 1.0 - th2 * (1.0 / 2.0 - th2 * (1.0 / 24.0 - th2 * (1.0 / 720.0)));
    sinc = 1.0 - th2 * (1.0 / 6.0 - th2 * (1.0 / 120.0 - th2 * (1.0 / 5040.0)));
    vers = 0.5 - th2 * (1.0 / 24.0 - th2 * (1.0 / 720.0 - th2 * (1.0 / 40320.0)));
  } else {
    const double theta = sqrt(th2);
    ct = cos(theta);
    sinc = sin(theta) / theta;
    vers = (1.0 - ct) / th2;
  }
  const double on = (om[0] * n[0] + om[1] * n[1] + om[2] * n[2]) * vers * dt * dt;
  const double oxn[3] = {om[1] * n[2] - om[2] * n[1], om[2] * n[0] - om[0] * n[2],
                         om[0] * n[1] - om[1] * n[0]};
  const double s = sinc * dt;
  for (int d = 0; d < 3; d++) n[d] = n[d] * ct + oxn[d] * s + om[d] * on;
}

/* paper rule: true when the particles approach along nc. vn = vij.nc, xn = xij.nc; tol,
   the round-off of the product (APPROACH_ROUNDOFF |vij| |xij|), keeps a pair that moves
   across nc from being decided by the rounding of vn, which depends on the order of sums
   (the number of ranks) */

static constexpr double APPROACH_ROUNDOFF = 1.0e-12;

inline bool contact_approach(double vn, double xn, double tol = 0.0)
{
  return vn * xn < -tol;
}

/* the contact history of one pair of bodies (or of all bodies together), updated once
   per time step from the step's sums: ntouch touching pairs, nint interacting pairs and
   the transmitted compressive normal force F. Contact begins with the first touching
   pair (tfirst, the start of that step; under the paper's rule, which measures no gap,
   an interacting pair is a touching one); it lasts while F exceeds
   FORCE_FRACTION of its peak so far. An episode is a period with F above that level;
   interruptions of up to HOLD_STEPS steps belong to the same episode; tlast is the end
   of the first episode. The impulse is the time integral of F. fnet is the net force
   (vector) on the body of the smaller ID from the other, friction included, and jnet its
   time integral by the trapezoid of the step (as velocity Verlet kicks): the momentum the
   other body gave it, exactly (F sums the magnitudes of the normal pair forces, which at
   edges and corners point in different directions). */

struct ContactRecord {
  static constexpr int HOLD_STEPS = 10;
  static constexpr double FORCE_FRACTION = 0.01;
  static constexpr int NVALUES = 16;    // values packed by pack()/unpack()
  static constexpr int NTALLY = 6;      // per-step sums: touching, interacting, F, fnet

  double tfirst = -1.0, tlast = -1.0;
  double force = 0.0, fpeak = 0.0, impulse = 0.0;
  double ntouch = 0.0, nint = 0.0;
  int nepisodes = 0, quiet = 0;
  double tlatest = -1.0;    // end of the last step with F above the level
  double fnet[3] = {0.0, 0.0, 0.0}, jnet[3] = {0.0, 0.0, 0.0};

  // s: the step's sums (NTALLY values: touching, interacting pairs, F, fnet)
  void update(double t, double dt, const double *s)
  {
    const double touch = s[0], inter = s[1], f = s[2];
    ntouch = touch;
    nint = inter;
    force = f;
    impulse += f * dt;
    // the momentum a velocity-Verlet step hands on: the mean of the forces at its ends
    for (int a = 0; a < 3; a++) {
      jnet[a] += 0.5 * (fnet[a] + s[3 + a]) * dt;
      fnet[a] = s[3 + a];
    }
    if (tfirst < 0.0 && touch > 0.0) tfirst = t - dt;
    if (f > fpeak) fpeak = f;
    if (f > 0.0 && f >= FORCE_FRACTION * fpeak) {
      if (nepisodes == 0 || quiet > HOLD_STEPS) nepisodes++;
      if (nepisodes == 1) tlast = t;
      tlatest = t;
      quiet = 0;
    } else {
      quiet++;
    }
  }
  // the state of a force computation outside a step (setup): no history
  void now(const double *s)
  {
    ntouch = s[0];
    nint = s[1];
    force = s[2];
    for (int a = 0; a < 3; a++) fnet[a] = s[3 + a];
  }
  void pack(double *buf) const
  {
    const double v[NVALUES] = {
        tfirst,         tlast,   force,   fpeak,   impulse, ntouch,  nint,    (double) nepisodes,
        (double) quiet, tlatest, fnet[0], fnet[1], fnet[2], jnet[0], jnet[1], jnet[2]};
    for (int k = 0; k < NVALUES; k++) buf[k] = v[k];
  }
  void unpack(const double *buf)
  {
    tfirst = buf[0];
    tlast = buf[1];
    force = buf[2];
    fpeak = buf[3];
    impulse = buf[4];
    ntouch = buf[5];
    nint = buf[6];
    nepisodes = (int) buf[7];
    quiet = (int) buf[8];
    tlatest = buf[9];
    for (int a = 0; a < 3; a++) {
      fnet[a] = buf[10 + a];
      jnet[a] = buf[13 + a];
    }
  }
};

}    // namespace ESPH

#endif
