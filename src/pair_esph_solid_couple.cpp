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
   pair esph/solid contact/couple: the contact force of a cross-body pair
   acts at the contact point, not at the two particles
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"

#include <Eigen/Dense>
#include <cmath>
#include <mpi.h>
#include <vector>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   A cross-body pair force ff (on i, -ff on j) applied at x_i and x_j has the
   couple (x_i - x_j) x ff: unless ff lies along the pair's line, the contact
   changes the total angular momentum. Where the common normal is the face's
   while the pairs reach across the rim of the contact (an edge meeting a face,
   bodies off axis) these couples add up. Applied at the contact point x_c, the
   pair's midpoint, the force is ff at x_i plus the couple
   T = (x_c - x_i) x ff on i's body, and -ff at x_j plus the same couple on j's
   body (summed into acc[*][A_CT] by the pair loop). Particle p passes its
   couple T_p to the real particles k of its own body around it with forces
     f_k = W_pk u_p x (x_k - x_p),  -sum_k f_k on p,  u_p = J_p^-1 T_p,
     J_p = sum_k W_pk (|r_pk|^2 I - r_pk r_pk^T),
   which sum to no force and to the couple T_p exactly: momentum and angular
   momentum are conserved to round-off. Their power, sum_k f_k.(v_k - v_p),
   is taken from p's internal energy, so that the total energy is too.
------------------------------------------------------------------------- */

/* the moment J = sum_k W (|r|^2 I - r r^T) (Voigt xx yy zz xy xz yz) */

static void add_couple_moment(double *jv, double w, const double *r, double rsq)
{
  jv[0] += w * (rsq - r[0] * r[0]);
  jv[1] += w * (rsq - r[1] * r[1]);
  jv[2] += w * (rsq - r[2] * r[2]);
  jv[3] -= w * r[0] * r[1];
  jv[4] -= w * r[0] * r[2];
  jv[5] -= w * r[1] * r[2];
}

/* the force W u x r on a neighbour at r that carries a share of a couple */

static inline void couple_force(double w, const double *u, const double *r, double *fk)
{
  fk[0] = w * (u[1] * r[2] - u[2] * r[1]);
  fk[1] = w * (u[2] * r[0] - u[0] * r[2]);
  fk[2] = w * (u[0] * r[1] - u[1] * r[0]);
}

/* ----------------------------------------------------------------------
   u = J^-1 T: J is positive definite unless the particle's neighbours lie
   on one line. About an axis along which they (nearly) lie they have no
   lever: a direction of J below COUPLE_LEVER of the largest is left out,
   and only the part of T the neighbours can carry is passed on (else a
   body that is a row of particles gets forces without bound: measured, a
   row of 3 particles gained 1000 times its energy in 10 steps); in 2d T and
   u are along z
------------------------------------------------------------------------- */

static constexpr double COUPLE_LEVER = 0.05;

void PairESPHSolid::couple_rate(const double *jv, const double *t, double *u) const
{
  u[0] = u[1] = u[2] = 0.0;
  if (dim == 2) {
    if (jv[2] > 0.0) u[2] = t[2] / jv[2];
    return;
  }
  const Eigen::Vector3d T(t[0], t[1], t[2]);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(voigt_to_matrix(jv));
  const Eigen::Vector3d lam = es.eigenvalues();
  const Eigen::Matrix3d &V = es.eigenvectors();
  for (int a = 0; a < 3; a++)
    if (lam(a) > COUPLE_LEVER * lam(2)) {
      const double s = V.col(a).dot(T) / lam(a);
      for (int d = 0; d < 3; d++) u[d] += s * V(d, a);
    }
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::contact_couple()
{
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  double **x = atom->x;
  double **f = atom->f;

  const double cutsq = cut_global * cut_global;
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  const double fconv = units.force;
  // the kernel weight of real particles i, k of one body (false: out of reach)
  auto weight = [&](int i, int k, double rsq, double &w) {
    double dw;
    if (!hvar_flag) return kernel_eval(kernel, dim, norm0, hinv0, sqrt(rsq), w, dw);
    const double hij = 0.5 * (hq[i][Q_H] + hq[k][Q_H]);
    return kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw);
  };

  if (newton_pair && simd_flag && listfull) {
    // the full list holds every neighbour of an owned particle: each passes on its own
    // couple (forces on ghosts go to their owners with the forces' reverse communication)
    for (int i = 0; i < nlocal; i++) {
      const double *t = acc[i] + A_CT;
      if (rmass[i] == 0.0 || (t[0] == 0.0 && t[1] == 0.0 && t[2] == 0.0)) continue;
      const int *jlist = listfull->firstneigh[i];
      const int jnum = listfull->numneigh[i];
      double jv[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
      for (int pass = 0; pass < 2; pass++) {
        double u[3] = {0.0, 0.0, 0.0};
        if (pass == 1) couple_rate(jv, t, u);
        double fi[3] = {0.0, 0.0, 0.0}, pw = 0.0;
        const double *vi = hq[i] + Q_V;
        for (int jj = 0; jj < jnum; jj++) {
          const int k = jlist[jj] & NEIGHMASK;
          if (rmass[k] == 0.0 || body[k] != body[i]) continue;
          const double r[3] = {x[k][0] - x[i][0], x[k][1] - x[i][1], x[k][2] - x[i][2]};
          const double rsq = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
          double w;
          if (rsq >= cutsq || !weight(i, k, rsq, w)) continue;
          if (pass == 0) {
            add_couple_moment(jv, w, r, rsq);
            continue;
          }
          double fk[3];
          couple_force(w, u, r, fk);
          const double *vk = hq[k] + Q_V;
          for (int a = 0; a < 3; a++) {
            f[k][a] += fk[a];
            fi[a] -= fk[a];
            pw += fk[a] * (vk[a] - vi[a]);
          }
        }
        if (pass == 1) {
          for (int a = 0; a < 3; a++) f[i][a] += fi[a];
          acc[i][A_AVHEAT] -= pw / (fconv * rmass[i]);
        }
      }
    }
    return;
  }

  // any couple to pass on (acc holds the complete sums of owned particles here)
  int any = 0;
  for (int i = 0; i < nlocal && !any; i++)
    if (rmass[i] > 0.0 &&
        (acc[i][A_CT] != 0.0 || acc[i][A_CT + 1] != 0.0 || acc[i][A_CT + 2] != 0.0))
      any = 1;
  int anyall = 0;
  MPI_Allreduce(&any, &anyall, 1, MPI_INT, MPI_MAX, world);
  if (!anyall) return;

  // (made here: the path above needs no rows; grow_work() grows them once made)
  if (!cpl) memory->create(cpl, nmax, 10, "pair:cpl");
  for (int i = 0; i < nlocal; i++)
    for (int a = 0; a < 3; a++) cpl[i][a] = (rmass[i] > 0.0) ? acc[i][A_CT + a] : 0.0;
  comm_stage = COMM_COUPLE;
  couple_k0 = 0;
  couple_k1 = 3;
  comm->forward_comm(this);

  // (a byte per atom: the sweeps below look at every pair's flags)
  cflag.assign(nall, 0);
  for (int i = 0; i < nall; i++) {
    double *c = cpl[i];
    cflag[i] = (c[0] != 0.0 || c[1] != 0.0 || c[2] != 0.0);
    // J and the power: only the flagged rows are written, read and communicated
    if (cflag[i])
      for (int k = 3; k < 10; k++) c[k] = 0.0;
  }
  const char *const has = cflag.data();

  // the real pairs of one body around a particle with a couple: visit(i, k, r = x_k - x_i, W);
  // the first sweep looks at every entry of the half list and keeps the rows it visited, the
  // second sweep goes over those
  std::vector<int> rows;
  int first = 1;
  auto pairs = [&](auto &&visit) {
    const int nrows = first ? list->inum : (int) rows.size();
    for (int e = 0; e < nrows; e++) {
      const int ii = first ? e : rows[e];
      const int i = list->ilist[ii];
      if (rmass[i] == 0.0) continue;
      int hit = 0;
      const int *jlist = list->firstneigh[i];
      const char hi = has[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int k = jlist[jj] & NEIGHMASK;
        if (!(hi | has[k]) || rmass[k] == 0.0 || body[k] != body[i]) continue;
        const double r[3] = {x[k][0] - x[i][0], x[k][1] - x[i][1], x[k][2] - x[i][2]};
        const double rsq = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (rsq >= cutsq) continue;
        double w;
        if (!weight(i, k, rsq, w)) continue;
        visit(i, k, r, rsq, w);
        hit = 1;
      }
      if (first && hit) rows.push_back(ii);
    }
    first = 0;
  };

  // J of the particles with a couple
  pairs([&](int i, int k, const double *r, double rsq, double w) {
    double jv[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    add_couple_moment(jv, w, r, rsq);
    if (has[i])
      for (int q = 0; q < 6; q++) cpl[i][3 + q] += jv[q];
    if (has[k] && (newton_pair || k < nlocal))
      for (int q = 0; q < 6; q++) cpl[k][3 + q] += jv[q];
  });
  if (newton_pair) {
    couple_k0 = 3;
    couple_k1 = 9;
    comm->reverse_comm(this);
  }
  // u = J^-1 T (in 2d the couple is along z, with J's zz entry)
  for (int i = 0; i < nlocal; i++) {
    double *c = cpl[i];
    if (!has[i]) continue;
    double u[3];
    couple_rate(c + 3, c, u);
    for (int a = 0; a < 3; a++) c[a] = u[a];
  }
  couple_k0 = 0;
  couple_k1 = 3;
  comm->forward_comm(this);

  // the forces that carry the couples, and their power
  pairs([&](int i, int k, const double *r, double, double w) {
    const double *vi = hq[i] + Q_V;
    const double *vk = hq[k] + Q_V;
    const double dv[3] = {vk[0] - vi[0], vk[1] - vi[1], vk[2] - vi[2]};
    const int kown = newton_pair || k < nlocal;
    // from i's couple: f on k, -f on i
    const double *ui = cpl[i];
    const double *uk = cpl[k];
    double fk[3], fi[3];
    couple_force(w, ui, r, fk);
    // from k's couple, r_ki = -r: f on i, -f on k
    couple_force(-w, uk, r, fi);
    for (int a = 0; a < 3; a++) f[i][a] += fi[a] - fk[a];
    if (kown)
      for (int a = 0; a < 3; a++) f[k][a] += fk[a] - fi[a];
    if (has[i]) cpl[i][9] += fk[0] * dv[0] + fk[1] * dv[1] + fk[2] * dv[2];
    if (has[k] && kown) cpl[k][9] -= fi[0] * dv[0] + fi[1] * dv[1] + fi[2] * dv[2];
  });
  if (newton_pair) {
    couple_k0 = 9;
    couple_k1 = 10;
    comm->reverse_comm(this);
  }
  // the power (in force units times velocity) out of the particle's internal energy,
  // in the units of the heating sums (per unit mass, internal units)
  for (int i = 0; i < nlocal; i++)
    if (has[i]) acc[i][A_AVHEAT] -= cpl[i][9] / (fconv * rmass[i]);
}
