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
#include "force.h"
#include "neigh_list.h"

#include <Eigen/Dense>
#include <cmath>
#include <mpi.h>

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

void PairESPHSolid::contact_couple()
{
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  double **x = atom->x;
  double **f = atom->f;

  // any couple to pass on (acc holds the complete sums of owned particles here)
  int any = 0;
  for (int i = 0; i < nlocal && !any; i++)
    if (rmass[i] > 0.0 &&
        (acc[i][A_CT] != 0.0 || acc[i][A_CT + 1] != 0.0 || acc[i][A_CT + 2] != 0.0))
      any = 1;
  int anyall = 0;
  MPI_Allreduce(&any, &anyall, 1, MPI_INT, MPI_MAX, world);
  if (!anyall) return;

  for (int i = 0; i < nall; i++) {
    double *c = cpl[i];
    for (int k = 0; k < 10; k++) c[k] = 0.0;
    if (i < nlocal && rmass[i] > 0.0)
      for (int a = 0; a < 3; a++) c[a] = acc[i][A_CT + a];
  }
  comm_stage = COMM_COUPLE;
  couple_k0 = 0;
  couple_k1 = 3;
  comm->forward_comm(this);

  const double cutsq = cut_global * cut_global;
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  auto has = [&](int p) {
    return cpl[p][0] != 0.0 || cpl[p][1] != 0.0 || cpl[p][2] != 0.0;
  };
  // the real pairs of one body around a particle with a couple: visit(i, k, r = x_k - x_i, W)
  auto pairs = [&](auto &&visit) {
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      if (rmass[i] == 0.0) continue;
      const int *jlist = list->firstneigh[i];
      const int hi = has(i);
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int k = jlist[jj] & NEIGHMASK;
        if (rmass[k] == 0.0 || body[k] != body[i] || !(hi || has(k))) continue;
        const double r[3] = {x[k][0] - x[i][0], x[k][1] - x[i][1], x[k][2] - x[i][2]};
        const double rsq = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
        if (rsq >= cutsq) continue;
        double w, dw;
        if (hvar_flag) {
          const double hij = 0.5 * (hq[i][Q_H] + hq[k][Q_H]);
          if (!kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw))
            continue;
        } else if (!kernel_eval(kernel, dim, norm0, hinv0, sqrt(rsq), w, dw)) {
          continue;
        }
        visit(i, k, r, rsq, w);
      }
    }
  };

  // J of the particles with a couple
  pairs([&](int i, int k, const double *r, double rsq, double w) {
    const double jv[6] = {w * (rsq - r[0] * r[0]), w * (rsq - r[1] * r[1]), w * (rsq - r[2] * r[2]),
                          -w * r[0] * r[1],        -w * r[0] * r[2],        -w * r[1] * r[2]};
    if (has(i))
      for (int q = 0; q < 6; q++) cpl[i][3 + q] += jv[q];
    if (has(k) && (newton_pair || k < nlocal))
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
    if (!has(i)) continue;
    Eigen::Matrix3d J;
    J << c[3], c[6], c[7], c[6], c[4], c[8], c[7], c[8], c[5];
    const Eigen::Vector3d T(c[0], c[1], c[2]);
    Eigen::Vector3d u = Eigen::Vector3d::Zero();
    if (dim == 2) {
      if (J(2, 2) > 0.0) u(2) = T(2) / J(2, 2);
    } else {
      const Eigen::LDLT<Eigen::Matrix3d> ldlt(J);
      if (ldlt.info() == Eigen::Success && ldlt.isPositive()) u = ldlt.solve(T);
    }
    for (int a = 0; a < 3; a++) c[a] = u(a);
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
    const double fk[3] = {w * (ui[1] * r[2] - ui[2] * r[1]), w * (ui[2] * r[0] - ui[0] * r[2]),
                          w * (ui[0] * r[1] - ui[1] * r[0])};
    // from k's couple, r_ki = -r: f on i, -f on k
    const double fi[3] = {-w * (uk[1] * r[2] - uk[2] * r[1]), -w * (uk[2] * r[0] - uk[0] * r[2]),
                          -w * (uk[0] * r[1] - uk[1] * r[0])};
    for (int a = 0; a < 3; a++) f[i][a] += fi[a] - fk[a];
    if (kown)
      for (int a = 0; a < 3; a++) f[k][a] += fk[a] - fi[a];
    cpl[i][9] += fk[0] * dv[0] + fk[1] * dv[1] + fk[2] * dv[2];
    if (kown) cpl[k][9] -= fi[0] * dv[0] + fi[1] * dv[1] + fi[2] * dv[2];
  });
  if (newton_pair) {
    couple_k0 = 9;
    couple_k1 = 10;
    comm->reverse_comm(this);
  }
  // the power (in force units times velocity) out of the particle's internal energy,
  // in the units of the heating sums (per unit mass, internal units)
  const double fconv = units.force;
  for (int i = 0; i < nlocal; i++)
    if (rmass[i] > 0.0 && cpl[i][9] != 0.0) acc[i][A_AVHEAT] -= cpl[i][9] / (fconv * rmass[i]);
}
