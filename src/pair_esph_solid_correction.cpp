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
   pair esph/solid: the gradient correction pass of gradient bonet/lok
   (Bonet and Lok 1999)
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "esph_threads.h"
#include "force.h"
#include "neigh_list.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <vector>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   the gradient correction, before the pair loop (Bonet and Lok 1999): for
   every real particle M_i = sum_j m_j (x_j - x_i) (x) grad_i W_ij over the
   pairs that couple in the pair loop (own body; other bodies weighted by the
   contact gate, which depends only on the geometry), then
   B_i = (sigma_i / rho_i) M_i^-T for owned and ghost particles. The pair
   loop's stress force m_i m_j (B_i + B_j) grad_i W has no torque on a body:
   sum_j m_j (x_j - x_i) (x) M_i^-T grad_i W = I leaves the symmetric
   sigma_i. Its work is B_i : G_i (the energy), and L = G M^-1 the velocity
   gradient, exact for linear fields
------------------------------------------------------------------------- */

void PairESPHSolid::correction()
{
  correction_pass();
  if (force->newton_pair) {
    comm_stage = COMM_CORR;
    comm->reverse_comm(this, 9);
  }
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const double *rmass = state->rmass;
  const int *type = atom->type;
  // per chunk of atoms: the smallest time step
  std::vector<double> dtmin(nthreads, dt_cfl);
  double *const dtmin_t = dtmin.data();
  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int tid) {
    double dtl = dtmin_t[tid];
    for (int i = from; i < to; i++) {
      const double *q = hq[i];
      const Eigen::Matrix3d A = voigt_to_matrix(q + Q_A);
      double *B = hq[i] + qcol_b;
      Eigen::Matrix3d M, Minv, Bm;
      double beta;
      if (rmass[i] > 0.0 && correction_inverse(acc[i] + A_M, q[Q_RHO], dim, M, Minv, beta)) {
        // a poorly conditioned M (beta < 1): the corrected B blended with the plain one, A
        // (both torque-free under torquefree, so the blend is)
        if (beta < 1.0) {
          Minv *= beta;
          for (int d = 0; d < 3; d++) Minv(d, d) += (1.0 - beta) / q[Q_RHO];
        }
        if (correct_flag == CORRECT_BONETLOK) {
          Bm = q[Q_RHO] * A * Minv.transpose();
          // the correction stiffens a particle whose kernel support is cut (a free surface,
          // by up to about 2 normal to it) by the gain kappa, the largest singular value of
          // rho M^-1: its CFL step shrinks by sqrt(kappa) (measured: the free bar's ends go
          // unstable at 0.3 h / c_L without this, stable at 0.25)
          const Eigen::Matrix3d K = q[Q_RHO] * Minv;
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
          es.computeDirect(K.transpose() * K, Eigen::EigenvaluesOnly);
          const double sqrt_kappa = sqrt(sqrt(std::max(es.eigenvalues()(2), 0.0)));
          if (sqrt_kappa > 1.0) {
            const double rho = q[Q_RHO];
            const double cl = long_speed(q[Q_C] * q[Q_C], rho, type[i]);
            const double *v = q + Q_V;
            const double vmag = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
            dtl = std::min(dtl, q[Q_H] / (cl * sqrt_kappa + vmag));
          }
        } else {
          // torquefree: B = S M^-T with S = sym(A M^T), i.e. the plain force's B = A less
          // its torque (B M^T is symmetric); B = A wherever A and M commute (a uniform bulk,
          // a flat face along the principal axes), so the free surfaces keep the plain
          // force and its stability
          const Eigen::Matrix3d AM = A * M.transpose();
          if (beta < 1.0) {
            // undo the blend of Minv: S M^-T needs the exact inverse
            const Eigen::Matrix3d Mi = M.inverse();
            Bm = beta * (0.5 * (AM + AM.transpose()) * Mi.transpose()) + (1.0 - beta) * A;
          } else {
            Bm = 0.5 * (AM + AM.transpose()) * Minv.transpose();
          }
        }
      } else if (rmass[i] > 0.0) {
        Bm = A;
      } else {
        // a boundary particle: no stress (its Q_A slots hold its normal and gap)
        Bm.setZero();
      }
      for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) B[3 * r + c] = Bm(r, c);
    }
    dtmin_t[tid] = dtl;
  });
  for (int t = 0; t < nthreads; t++) dt_cfl = std::min(dt_cfl, dtmin[t]);
  // the ghosts' partial sums are with their owners: the pair loop's reverse
  // communication must not add them again
  for (int i = nlocal; i < nall; i++)
    for (int k = A_M; k < A_M + 9; k++) acc[i][k] = 0.0;
  comm_stage = COMM_CORR;
  comm->forward_comm(this, 9);
}

/* ----------------------------------------------------------------------
   the correction sums of the whole neighbor list into acc (the serial pass)
------------------------------------------------------------------------- */

void PairESPHSolid::correction_pass()
{
  run_correction_loop(0, list->inum, acc);
}

void PairESPHSolid::run_correction_loop(int iifrom, int iito, double **accr)
{
  if (hvar_flag)
    correction_loop<1>(iifrom, iito, accr);
  else
    correction_loop<0>(iifrom, iito, accr);
}

/* ----------------------------------------------------------------------
   M_i of the atoms of [iifrom, iito) of the neighbor list and their partners,
   added to the rows accr (acc itself, or a thread's rows)
------------------------------------------------------------------------- */

template <int HVAR> void PairESPHSolid::correction_loop(int iifrom, int iito, double **acc)
{
  double **x = atom->x;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  const double gap_cap = gaptol * h0;
  const double dt = dt_step;
  // as in the pair loop: other bodies are coupled by the contact rule only with boundary
  // particles, rigid particles only with other bodies
  const int contact_on = (nboundary > 0) && (contact != CONTACT_OFF);
  const int solid = (contact == CONTACT_SOLID);

  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  for (int ii = iifrom; ii < iito; ii++) {
    const int i = ilist[ii];
    const double mi = rmass[i];
    if (mi == 0.0) continue;
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const int bi = body[i];
    const int ri = rigid_flag && rigid[type[i]];
    const double *qi = hq[i];
    double mci[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double mj = rmass[j];
      if (mj == 0.0) continue;
      const double dx[3] = {xi - x[j][0], yi - x[j][1], zi - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq_global) continue;
      const int cross = contact_on && (bi != body[j]);
      const int rj = rigid_flag && rigid[type[j]];
      if ((ri || rj) && (!cross || (ri && rj))) continue;
      const double *qj = hq[j];
      // another body: weighted by the solid rule's coupling weight (smooth in time); the
      // paper's rule switches pairs on and off from step to step, and a correction that
      // switched with them would kick the particles: there every neighbour counts
      double wgt = 1.0;
      if (cross && solid) {
        const double gap = touch_apart(bi, body[j]) ? GAP_NONE : solid_gap(qi, qj, dt);
        wgt = contact_pair_weight(gap, gap_cap, qi[Q_ENG], qj[Q_ENG]);
        if (wgt == 0.0) continue;
      }
      double norm = norm0, hinv = hinv0;
      if (HVAR) {
        const double hij = 0.5 * (qi[Q_H] + qj[Q_H]);
        hinv = 1.0 / hij;
        norm = kernel_norm(kernel, dim, hij);
      }
      double w, dw;
      if (!kernel_eval(kernel, dim, norm, hinv, sqrt(rsq), w, dw)) continue;
      dw *= wgt;
      const double g[3] = {dw * dx[0], dw * dx[1], dw * dx[2]};    // grad_i W_ij
      // across bodies of different materials the volume weights of the pair loop (w_j =
      // rho0_i m_j / rho0_j): the corrected forces s_i B_i + s_j B_j there balance the
      // torques of these sums
      double wj = mj, wi = mi, si, sj;
      if (cross && !(ri || rj) && volume_ratio(type[i], type[j], si, sj)) {
        wj = si * mj;
        wi = sj * mi;
      }
      // x_j - x_i = -dx for i; x_i - x_j = dx and grad_j W = -g for j
      add_outer(mci, -wj, dx, g);
      if (newton_pair || j < nlocal) add_outer(acc[j] + A_M, -wi, dx, g);
    }
    double *ai = acc[i] + A_M;
    for (int k = 0; k < 9; k++) ai[k] += mci[k];
  }
}
