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

// The motion of whole bodies (sets of real particles with one i_esph_body): mass, centre of
// mass, its velocity, the angular momentum and second moment about it, and the rigid spin
// omega = I^-1 L. Used by the angular momentum watch of fix esph/integrate
// (esph_spin_watch.h) and by the boundary normals that turn with their body (fix
// esph/boundary turn body).

#ifndef LMP_ESPH_BODIES_H
#define LMP_ESPH_BODIES_H

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class ESPHState;
}    // namespace LAMMPS_NS

namespace ESPH {

// sums per body: m, m r (3), m v (3), m r cross v (3), m r r^T (xx yy zz xy xz yz),
// m v.v / 2, with r = x - ref_B taken by the minimum image
static constexpr int BODY_NSUM = 17;

// one particle (mass m, position r from the body's reference point, velocity v) added to
// its body's BODY_NSUM sums s
inline void add_body_sum(double *s, double m, const double *r, const double *v)
{
  s[0] += m;
  for (int d = 0; d < 3; d++) {
    s[1 + d] += m * r[d];
    s[4 + d] += m * v[d];
  }
  s[7] += m * (r[1] * v[2] - r[2] * v[1]);
  s[8] += m * (r[2] * v[0] - r[0] * v[2]);
  s[9] += m * (r[0] * v[1] - r[1] * v[0]);
  s[10] += m * r[0] * r[0];
  s[11] += m * r[1] * r[1];
  s[12] += m * r[2] * r[2];
  s[13] += m * r[0] * r[1];
  s[14] += m * r[0] * r[2];
  s[15] += m * r[1] * r[2];
  s[16] += 0.5 * m * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// the index of a body ID in the sorted bodies, or -1
inline int body_slot(const std::vector<int> &bodies, int id)
{
  const auto it = std::lower_bound(bodies.begin(), bodies.end(), id);
  return (it == bodies.end() || *it != id) ? -1 : (int) (it - bodies.begin());
}

// a reference point of each of the sorted bodies (one of its real particles in groupbit,
// 3 per body), its particles taken to it by the minimum image (collective). A body that
// extends over more than half of a periodic box length (it spans the box, or the minimum
// image cannot make it whole) has no motion of its own: it is removed from bodies and
// returned
std::vector<int> body_reference(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::ESPHState *state, int groupbit,
                                std::vector<int> &bodies, std::vector<double> &ref);

// the sums over the owned real particles in groupbit of each of the sorted bodies, on all
// ranks (one MPI_Allreduce; collective), positions relative to ref, which then moves to
// the centre of mass (the same on every rank); the velocity of atom i is
// vel[i][voff..voff+2]
void body_sums(LAMMPS_NS::LAMMPS *lmp, LAMMPS_NS::ESPHState *state, int groupbit,
               const std::vector<int> &bodies, double *const *vel, int voff,
               std::vector<double> &ref, std::vector<double> &sum);

struct BodyMotion {
  double M;       // mass
  double c[3];    // centre of mass (from the reference point of the sums)
  double V[3];    // its velocity
  double L[3];    // angular momentum about it
  double S[6];    // second moment about it, sum m r r^T (xx yy zz xy xz yz)
  double Kcm;     // kinetic energy of the motion relative to the centre of mass
};

// the motion of a body from its BODY_NSUM sums (M = 0: no particles)
inline BodyMotion body_motion(const double *s)
{
  BodyMotion b{};
  b.M = s[0];
  if (!(b.M > 0.0)) {
    b.M = 0.0;
    return b;
  }
  const double M = b.M;
  double *c = b.c, *V = b.V;
  for (int d = 0; d < 3; d++) {
    c[d] = s[1 + d] / M;
    V[d] = s[4 + d] / M;
  }
  // about the centre of mass: L = sum m x cross v - M c cross V, S = sum m x x^T - M c c^T
  b.L[0] = s[7] - M * (c[1] * V[2] - c[2] * V[1]);
  b.L[1] = s[8] - M * (c[2] * V[0] - c[0] * V[2]);
  b.L[2] = s[9] - M * (c[0] * V[1] - c[1] * V[0]);
  b.S[0] = std::max(0.0, s[10] - M * c[0] * c[0]);
  b.S[1] = std::max(0.0, s[11] - M * c[1] * c[1]);
  b.S[2] = std::max(0.0, s[12] - M * c[2] * c[2]);
  b.S[3] = s[13] - M * c[0] * c[1];
  b.S[4] = s[14] - M * c[0] * c[2];
  b.S[5] = s[15] - M * c[1] * c[2];
  b.Kcm = std::max(0.0, s[16] - 0.5 * M * (V[0] * V[0] + V[1] * V[1] + V[2] * V[2]));
  return b;
}

// the spin of the rigid motion with the body's angular momentum, omega = I^-1 L with
// I = tr(S) 1 - S; directions of a vanishing moment of inertia (a body that is a line
// or one particle) do not turn; in 2d only about z, in 1d never
inline void rigid_spin(const BodyMotion &b, int dimension, double omega[3])
{
  omega[0] = omega[1] = omega[2] = 0.0;
  if (!(b.M > 0.0) || dimension < 2) return;
  const double *S = b.S;
  if (dimension == 2) {
    const double Izz = S[0] + S[1];
    if (Izz > 0.0) omega[2] = b.L[2] / Izz;
    return;
  }
  const double tr = S[0] + S[1] + S[2];
  Eigen::Matrix3d I;
  I << tr - S[0], -S[3], -S[4], -S[3], tr - S[1], -S[5], -S[4], -S[5], tr - S[2];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(I);
  const Eigen::Vector3d lam = es.eigenvalues();
  const Eigen::Vector3d L(b.L[0], b.L[1], b.L[2]);
  // a principal moment below 1e-10 of the largest is a direction the body cannot turn
  // about (the axis of a line of particles)
  Eigen::Vector3d w = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; k++)
    if (lam[k] > 1.0e-10 * lam[2]) {
      const Eigen::Vector3d e = es.eigenvectors().col(k);
      w += (e.dot(L) / lam[k]) * e;
    }
  for (int d = 0; d < 3; d++) omega[d] = w[d];
}

}    // namespace ESPH

#endif
