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
   pair esph/solid: the per-particle passes around the pair loop. Before it,
   hoist() evaluates each particle's predicted state once (equation of
   state, sigma / rho^2, sound speed, the contact state it uses); after it,
   finalize() turns the loop's sums into the rates (continuity, Jaumann
   stress rate, energy, smoothing length) and interpolates the boundary
   particles' velocity and spin from their bodies.
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_bodies.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_prefetch.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "esph_threads.h"
#include "fix.h"
#include "fix_esph_integrate.h"
#include "force.h"
#include "group.h"
#include "info.h"
#include "math_special.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   per-particle work hoisted out of the pair loop: predicted state, EOS,
   sigma/rho^2, sound speed; local CFL estimate
------------------------------------------------------------------------- */

void PairESPHSolid::hoist()
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  double **v = atom->v;
  const double *rmass = state->rmass;
  // inside a step the integrator has predicted the state at its end
  double **pred = pred_valid ? fix_int->pred : nullptr;
  const int *mask = atom->mask;
  const int intbit = fix_int->groupbit;
  const double hlimit = cut_global / KERNEL_SUPPORT * (1.0 + 1.0e-12);
  // internal units from here on: sigma/rho^2, e and c (esph_units.h)
  const double ein = units.energy_in, pin = units.pressure_in;
  // the switched viscosity coefficient: the predicted or current alpha_i
  const double *alpha_now = vswitch_flag ? state->alpha : nullptr;
  // visc/recon: the strain rates of the last computation become the ones this one uses,
  // unless it re-evaluates the last computation (a continued run)
  double **drec = recon_flag ? state->drec : nullptr;
  double **drecu = recon_flag ? state->drecu : nullptr;
  const int recon_shift = drec && !recon_keep;
  const double visc_cfl = visc_cfl_factor();
  // the gap forecast of the boundary particles (add_gap_sums())
  const double dt = dt_step;
  // the vector pass runs in this computation: position, mass and body into the rows too
  const int pack = simd_active;
  double **x = atom->x;
  const int *body = state->body;

  recon_keep = 0;

  // per chunk of atoms: the smallest time step, the first atom whose h is too large
  std::vector<double> dtmin(nthreads, BIG_DT);
  std::vector<int> hbad(nthreads, -1);
  // per chunk: the first real particle whose state or pressure is not finite
  std::vector<int> nonfinite(nthreads, -1);
  int *const nonfinite_t = nonfinite.data();
  double *const dtmin_t = dtmin.data();
  int *const hbad_t = hbad.data();
  // (captures by value: the pointers in registers, as in a plain loop)
  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int tid) {
    double dtl = BIG_DT;
    int hb = -1, nf = -1;
    for (int i = from; i < to; i++) {
      if (i + ESPH::PREFETCH_AHEAD < to) {
        const int ip = i + ESPH::PREFETCH_AHEAD;
        ESPH::prefetch_write(hq[ip], Q_ENG + 1);
        if (pred) ESPH::prefetch_read(pred[ip], FixESPHIntegrate::P_V + 3);
        if (drec) {
          ESPH::prefetch_read(drec[ip], 6);
          ESPH::prefetch_write(drecu[ip], 6);
        }
      }
      if (recon_shift)
        for (int k = 0; k < 6; k++) drecu[i][k] = drec[i][k];
      double *q = hq[i];
      const double *p = pred ? pred[i] : nullptr;
      // the velocity at the end of the step: predicted by fix esph/integrate, or set by
      // another fix (move no, or a body outside its group moved by e.g. fix move)
      const double *vi = (p && fix_int->move && (mask[i] & intbit)) ? p + FixESPHIntegrate::P_V
                                                                    : v[i];
      q[Q_V] = vi[0];
      q[Q_V + 1] = vi[1];
      q[Q_V + 2] = vi[2];
      q[Q_N] = state->n[i][0];
      q[Q_N + 1] = state->n[i][1];
      q[Q_N + 2] = state->n[i][2];
      q[Q_GAP] = state->gap[i];
      q[Q_GAPV] = state->gapv[i];
      q[Q_ENG] = state->eng[i];
      if (pack) {
        // the slots only the vector pass reads (simd_pack() fills the ghosts' after the
        // communication)
        q[Q_X] = x[i][0];
        q[Q_X + 1] = x[i][1];
        q[Q_X + 2] = x[i][2];
        q[Q_M] = rmass[i];
        q[Q_BODY] = body ? body[i] : 0.0;
      }
      if (drec)
        for (int k = 0; k < 6; k++) q[qcol_d + k] = drecu[i][k];

      if (rmass[i] > 0.0) {
        const int itype = type[i];
        const double rho = p ? p[FixESPHIntegrate::P_RHO] : state->rho[i];
        const double e = (p ? p[FixESPHIntegrate::P_E] : state->e[i]) * ein;
        const double h = p ? p[FixESPHIntegrate::P_H] : state->h[i];
        const double *sp = p ? p + FixESPHIntegrate::P_S : state->s[i];
        double P, c2;
        eos[itype].compute(rho, e, P, c2);
        // a NaN or inf anywhere in the state shows here (one check per particle)
        if (nf < 0 &&
            !std::isfinite(P + c2 + e + h + sp[0] + sp[1] + sp[2] + sp[3] + sp[4] + sp[5]))
          nf = i;
        if (c2 < 0.0) c2 = 0.0;
        const double c = sqrt(c2);
        const double inv = 1.0 / (rho * rho);
        q[Q_RHO] = rho;
        q[Q_C] = c;
        q[Q_H] = h;
        q[Q_A] = (sp[0] * pin - P) * inv;
        q[Q_A + 1] = (sp[1] * pin - P) * inv;
        q[Q_A + 2] = (sp[2] * pin - P) * inv;
        q[Q_A + 3] = sp[3] * pin * inv;
        q[Q_A + 4] = sp[4] * pin * inv;
        q[Q_A + 5] = sp[5] * pin * inv;
        q[Q_E] = e;
        if (alpha_now) q[Q_ALPHA] = p ? p[FixESPHIntegrate::P_ALPHA] : alpha_now[i];
        // CFL with the longitudinal wave speed, and the viscous limit for a large alpha
        const double cl = long_speed(c2, rho, itype);
        const double vmag = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
        double dti = visc_cfl * h / (cl + vmag);
        if (heat_flag) {
          const double divv = p ? p[FixESPHIntegrate::P_DIVV] : -drho[i] / rho;
          q[Q_ZETA] = g1 * h * c + g2 * h * h * (fabs(divv) - divv);
          // explicit diffusion with diffusivity zeta: dt <= h^2 / (2 D zeta)
          if (q[Q_ZETA] > 0.0) dti = MIN(dti, h * h / (2.0 * dim * q[Q_ZETA]));
        } else {
          q[Q_ZETA] = 0.0;
        }
        if (dti < dtl) dtl = dti;
        if (hvar_flag && h > hlimit && hb < 0) hb = i;
      } else {
        q[Q_RHO] = q[Q_C] = q[Q_E] = q[Q_ZETA] = 0.0;
        q[Q_H] = state->h[i];
        // (no stress: the normal and gap terms of the vector pass, Q_BN .. Q_BGAPV)
        const double *n = state->n[i];
        const int hasgap = state->gap[i] < GAP_NONE;
        q[Q_BN] = n[0];
        q[Q_BN + 1] = n[1];
        q[Q_BN + 2] = n[2];
        q[Q_BGFLAG] = hasgap ? 1.0 : 0.0;
        q[Q_BGAP] = hasgap ? state->gap[i] + dt * state->gapv[i] : 0.0;
        q[Q_BGAPV] = hasgap ? state->gapv[i] : 0.0;
        if (alpha_now) q[Q_ALPHA] = 0.0;
      }
    }
    dtmin_t[tid] = dtl;
    hbad_t[tid] = hb;
    nonfinite_t[tid] = nf;
  });
  // contact/normal cone: the cones of the last computation become the ones this one uses
  // (unless it re-evaluates the last computation)
  if (qcol_n >= 0) {
    const int qcn = qcol_n;
    double **cone = state->cone;
    double **coneu = state->coneu;
    const int shift = !cone_keep;
    ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
      for (int i = from; i < to; i++) {
        if (shift)
          for (int k = 0; k < 6; k++) coneu[i][k] = cone[i][k];
        for (int k = 0; k < 6; k++) hq[i][qcn + k] = coneu[i][k];
      }
    });
  }
  cone_keep = 0;
  // friction: the static friction found by the last computation becomes the one this one
  // uses (unless it re-evaluates the last computation)
  if (state->fric && !fric_keep)
    ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
      for (int i = from; i < to; i++)
        for (int k = 0; k < 3; k++) state->fricu[i][k] = state->fric[i][k];
    });
  fric_keep = 0;
  dt_cfl = BIG_DT;
  for (int t = 0; t < nthreads; t++) {
    if (nonfinite[t] >= 0) {
      const int i = nonfinite[t];
      const double *p = pred ? pred[i] : nullptr;
      const double rho = p ? p[FixESPHIntegrate::P_RHO] : state->rho[i];
      const double e = p ? p[FixESPHIntegrate::P_E] : state->e[i];
      double P, c2;
      eos[atom->type[i]].compute(rho, e * ein, P, c2);
      const double *sp = p ? p + FixESPHIntegrate::P_S : state->s[i];
      double smax = 0.0;
      for (int k = 0; k < 6; k++)
        if (!(fabs(sp[k]) <= fabs(smax))) smax = sp[k];
      // (written out in words: a bare nan in the log reads like a thermo value)
      const auto val = [](double x) {
        return std::isfinite(x) ? fmt::format("{}", x) : std::string("not finite");
      };
      // a density of exactly 0: the state was never set up (the start of a run sets
      // d_esph_rho = 0 to rho0); rerun does not start a run
      if (rho == 0.0)
        error->one(FLERR, Error::NOLASTLINE,
                   "Pair esph/solid: atom {} (type {}) has density d_esph_rho = 0 at step {}: "
                   "the state of the particles is set up at the start of a run (a density of "
                   "0 becomes rho0 of the type), and this force computation comes before any "
                   "run (rerun as the first run?); give run 0 first",
                   atom->tag[i], atom->type[i], update->ntimestep);
      error->one(FLERR, Error::NOLASTLINE,
                 "Pair esph/solid: atom {} (type {}) has a non-finite state at step {}: "
                 "density {}, specific energy {}, pressure {} and squared bulk sound speed {} "
                 "from its equation of state, largest deviatoric stress component {}; the "
                 "run has gone unstable (a time step above the stable one: fix esph/integrate "
                 "cfl, vector element 3) or a material parameter is out of range (pair_coeff "
                 "eos, visc, artstress)",
                 atom->tag[i], atom->type[i], update->ntimestep, val(rho), val(e), val(P / pin),
                 val(c2), val(smax));
    }
    dt_cfl = MIN(dt_cfl, dtmin[t]);
    if (hbad[t] >= 0) {
      const double *p = pred ? pred[hbad[t]] : nullptr;
      error->one(FLERR, Error::NOLASTLINE,
                 "Smoothing length {} of atom {} exceeds the pair esph/solid limit hvar x h = {}",
                 p ? p[FixESPHIntegrate::P_H] : state->h[hbad[t]], atom->tag[hbad[t]], hlimit);
    }
  }
}

/* ----------------------------------------------------------------------
   Monaghan (2000) / Gray, Monaghan and Swift (2001) artificial stress of
   every owned and ghost real particle from its sigma / rho^2 (already
   communicated): in the principal frame R'_aa = -epsilon sigma'_aa / rho^2
   where sigma'_aa > 0 (tension), 0 otherwise; R = V R' V^T
------------------------------------------------------------------------- */

void PairESPHSolid::artificial_stress()
{
  const int nall = atom->nlocal + atom->nghost;
  const double *rmass = state->rmass;
  for (int i = 0; i < nall; i++) {
    const double *A = hq[i] + Q_A;
    double *R = hq[i] + Q_R;
    for (int k = 0; k < NHQ_AST; k++) R[k] = 0.0;
    // (a boundary particle has no stress, its Q_A slots hold its normal and gap)
    if (!(rmass[i] > 0.0)) continue;
    // compression in every direction (the common case in impact): nothing to do;
    // the largest eigenvalue is at most the largest Gershgorin bound
    const double g0 = A[0] + fabs(A[3]) + fabs(A[4]);
    const double g1 = A[1] + fabs(A[3]) + fabs(A[5]);
    const double g2 = A[2] + fabs(A[4]) + fabs(A[5]);
    if (g0 <= 0.0 && g1 <= 0.0 && g2 <= 0.0) continue;
    const Eigen::Matrix3d M = voigt_to_matrix(A);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
    es.computeDirect(M);
    const Eigen::Vector3d lam = es.eigenvalues();
    const Eigen::Matrix3d &V = es.eigenvectors();
    Eigen::Matrix3d Rm = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 3; a++)
      if (lam(a) > 0.0) Rm -= astress_eps * lam(a) * V.col(a) * V.col(a).transpose();
    matrix_to_voigt(Rm, R);
    hq[i][Q_RFLAG] = 1.0;    // some principal stress is tensile
  }
}

/* ----------------------------------------------------------------------
   turn accumulated sums into rates (per particle, after reverse comm)
------------------------------------------------------------------------- */

void PairESPHSolid::finalize(int eflag)
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  const double *rmass = state->rmass;
  double **v = atom->v;
  const int bnd = (nboundary > 0);
  const int qcn = qcol_n;

  std::vector<double> esum(nthreads, 0.0);
  double *const esum_t = esum.data();
  // per chunk: the boundary particles that lie less than SURFACE_LEFT spacings in front of
  // their body's real particles (left_behind()), the first of them and its depth
  const double shallow = SURFACE_LEFT * (boundary_spacing() > 0.0 ? boundary_spacing() : h0);
  std::vector<bigint> nleft(nthreads, 0);
  std::vector<tagint> left_tag(nthreads, MAXTAGINT);
  std::vector<double> left_depth(nthreads, 0.0);
  std::vector<int> left_body(nthreads, 0);
  bigint *const nleft_t = nleft.data();
  tagint *const left_tag_t = left_tag.data();
  double *const left_depth_t = left_depth.data();
  int *const left_body_t = left_body.data();
  const tagint *tag = atom->tag;
  double **pred = pred_valid ? fix_int->pred : nullptr;
  double **drec = recon_flag ? state->drec : nullptr;
  const int ncols = acc_cols;
  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int tid) {
    double es = 0.0;
    for (int i = from; i < to; i++) {
      if (i + ESPH::PREFETCH_AHEAD < to) {
        const int ip = i + ESPH::PREFETCH_AHEAD;
        ESPH::prefetch_read(acc[ip], ncols);
        ESPH::prefetch_read(hq[ip], Q_ENG + 1);
        if (pred) ESPH::prefetch_read(pred[ip] + FixESPHIntegrate::P_S, 6);
        ESPH::prefetch_write(ds[ip], 6);
        if (drec) ESPH::prefetch_write(drec[ip], 6);
      }
      const double *a = acc[i];
      const double *q = hq[i];
      if (rmass[i] > 0.0) {
        const double rho = q[Q_RHO];
        const double *sp = pred ? pred[i] + FixESPHIntegrate::P_S : state->s[i];
        Eigen::Matrix3d L;
        L << a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8];
        // continuity (eq. 1): drho_i = sum_j m_j (v_i - v_j).grad_i W = -tr G
        drho[i] = -(a[0] + a[4] + a[8]);
        // energy (eq. 3): de_i = sigma_i : G_i / rho_i^2, with the correction B_i : G_i (the
        // work of the corrected forces), plus viscous heating and heat transfer
        // (in energy/mass units per time, as d_esph_e is stored)
        double work;
        if (correct_flag >= CORRECT_BONETLOK) {
          const double *B = q + qcol_b;
          work = 0.0;
          for (int k = 0; k < 9; k++) work += B[k] * a[A_G + k];
        } else {
          const double *A = q + Q_A;
          work = A[0] * a[0] + A[1] * a[4] + A[2] * a[8] + A[3] * (a[1] + a[3]) +
              A[4] * (a[2] + a[6]) + A[5] * (a[5] + a[7]);
        }
        de[i] = (work + a[A_AVHEAT] + a[A_HEAT]) * units.energy;
        // velocity gradient L = G / rho (eqs. 15, 17), Jaumann-rate stress (eq. 18);
        // corrected: L = G Mm^-1, exact for linear velocity fields also at free surfaces
        Eigen::Matrix3d M, Minv;
        double beta;
        if (correct_flag && correction_inverse(a + A_M, rho, dim, M, Minv, beta))
          L = (beta < 1.0) ? Eigen::Matrix3d(beta * (L * Minv) + ((1.0 - beta) / rho) * L)
                           : Eigen::Matrix3d(L * Minv);
        else
          L /= rho;
        jaumann_rate(L, sp, shear[type[i]], ds[i]);
        // visc/recon: the strain rate D = sym(L) for the next computation's reconstruction;
        // none in a type with a yield stress, whose pairs keep the full viscosity (a
        // front's overshoot there would be locked in as plastic strain)
        if (recon_flag && yield[type[i]] > 0.0) {
          for (int k = 0; k < 6; k++) state->drec[i][k] = 0.0;
        } else if (recon_flag) {
          double *d = state->drec[i];
          d[0] = L(0, 0);
          d[1] = L(1, 1);
          d[2] = L(2, 2);
          d[3] = 0.5 * (L(0, 1) + L(1, 0));
          d[4] = 0.5 * (L(0, 2) + L(2, 0));
          d[5] = 0.5 * (L(1, 2) + L(2, 1));
        }
        if (xsph_flag)
          for (int d = 0; d < 3; d++) xsph[i][d] = xsph_eps * a[A_XSPH + d];
        // variable smoothing length (eq. 24): dh/dt = -h/(D rho) drho/dt
        dh[i] = hvar_flag ? -q[Q_H] / (dim * rho) * drho[i] : 0.0;
        // viscosity switch (Morris and Monaghan 1997): decay to alpha_min over
        // tau = h / (l c), rise towards alpha under compression, div v = -drho / rho
        if (vswitch_flag) {
          const double al = q[Q_ALPHA];
          const double compress = MAX(drho[i] / rho, 0.0);
          dalpha[i] = -(al - vswitch_min) * vswitch_l * q[Q_C] / q[Q_H] + compress * (alpha - al);
        }
        if (bnd) store_normal(i);
        if (qcn >= 0) store_cone(i);
        if (eflag) {
          // the internal energy at the end of the step, as the integrator will advance it
          // with the rate just computed (not the prediction q[Q_E], whose rate is the last
          // computation's)
          const double ei = rmass[i] * fix_int->end_energy(i, de[i]);
          es += ei;
          if (eflag_atom) eatom[i] += ei;
        }
      } else {
        // boundary particle: interpolated velocity and spin from the real particles (4.2)
        store_bnd_gap(i);
        drho[i] = de[i] = dh[i] = 0.0;
        for (int k = 0; k < 6; k++) ds[i][k] = 0.0;
        if (vswitch_flag) dalpha[i] = 0.0;
        if (recon_flag)
          for (int k = 0; k < 6; k++) state->drec[i][k] = 0.0;
        if (a[B_WSUM] > 0.0) {
          // interpolation from the real particles p of the body: with the Shepard means
          // vbar, xi = xbar - x_k, and the corrected velocity gradient
          //   L = (A - vbar (x) b) (M - xi (x) b)^-1,
          // exact for a linear velocity field where the kernel is one-sided (surface)
          const double inv = 1.0 / a[B_WSUM];
          const double vbar[3] = {a[B_VSUM] * inv, a[B_VSUM + 1] * inv, a[B_VSUM + 2] * inv};
          const double xi[3] = {a[B_XSUM] * inv, a[B_XSUM + 1] * inv, a[B_XSUM + 2] * inv};
          Eigen::Matrix3d Lk, M;
          for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
              Lk(r, c) = a[B_A + 3 * r + c] - vbar[r] * a[B_B + c];
              M(r, c) = a[B_M + 3 * r + c] - xi[r] * a[B_B + c];
            }
          for (int d = dim; d < 3; d++) M(d, d) = 1.0;
          if (fabs(M.determinant()) > 1.0e-6)
            Lk = Lk * M.inverse();
          else
            Lk.setZero();
          // the boundary particle moves with the Shepard mean corrected by the rotation
          // only: extrapolating the strain part would overshoot at impact fronts
          const Eigen::Matrix3d Wk = 0.5 * (Lk - Lk.transpose());
          double vk[3];
          for (int r = 0; r < 3; r++)
            vk[r] = vbar[r] - (Wk(r, 0) * xi[0] + Wk(r, 1) * xi[1] + Wk(r, 2) * xi[2]);
          // how far the Shepard mean of its real particles lies behind it along its normal
          const double *nk = state->n[i];
          const double depth = -(xi[0] * nk[0] + xi[1] * nk[1] + xi[2] * nk[2]);
          if (depth < shallow) {
            nleft_t[tid]++;
            if (tag[i] < left_tag_t[tid]) {
              left_tag_t[tid] = tag[i];
              left_depth_t[tid] = depth;
              left_body_t[tid] = state->body ? state->body[i] : 0;
            }
          }
          bvel[i][0] = vk[0];
          bvel[i][1] = vk[1];
          bvel[i][2] = vk[2];
          bspin[i][0] = 0.5 * (Lk(0, 1) - Lk(1, 0));
          bspin[i][1] = 0.5 * (Lk(0, 2) - Lk(2, 0));
          bspin[i][2] = 0.5 * (Lk(1, 2) - Lk(2, 1));
        } else {
          bvel[i][0] = v[i][0];
          bvel[i][1] = v[i][1];
          bvel[i][2] = v[i][2];
          bspin[i][0] = bspin[i][1] = bspin[i][2] = 0.0;
        }
      }
    }
    esum_t[tid] = es;
  });
  if (eflag_global)
    for (int t = 0; t < nthreads; t++) eng_vdwl += esum[t];
  // (with each new neighbour list: often enough, and the same step on every rank)
  if (bnd && neighbor->ago == 0) {
    bigint n = 0;
    tagint first = MAXTAGINT;
    double depth = 0.0;
    int lbody = 0;
    for (int t = 0; t < nthreads; t++) {
      n += nleft[t];
      if (left_tag[t] < first) {
        first = left_tag[t];
        depth = left_depth[t];
        lbody = left_body[t];
      }
    }
    left_behind(n, first, depth, lbody);
  }
  if (bnd) normals_valid = 1;
  if (bnd && turn_body) turn_with_bodies();
}

/* ----------------------------------------------------------------------
   a boundary particle lies about half a spacing in front of its body's
   real particles along its normal (on a face of a lattice body the Shepard
   mean of those in its support 0.52 spacings behind it; 0.44 and more in
   the examples, also on staircases, in impacts and spins). One with that
   mean less than SURFACE_LEFT spacings behind it was left behind: the
   real particles were moved without their boundary particles (fix
   recenter or displace_atoms on the real particles alone: the contact
   then acts at a surface off the body), or it lags where the body deforms
   strongly (measured 0.08-0.15 at the Taylor bar's impact face at 0.4 mm
   and in plastic impacts at 300-1000 m/s), or the run went unstable: a
   WARNING, once per run. n such particles on this rank, the first, its
   depth and body (collective)
------------------------------------------------------------------------- */

void PairESPHSolid::left_behind(bigint n, tagint first, double depth, int body)
{
  if (left_warned) return;
  bigint nall;
  MPI_Allreduce(&n, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nall == 0) return;
  tagint tfirst;
  MPI_Allreduce(&first, &tfirst, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  // (the body and depth of the first, from its rank; no atom map needed)
  double mine[2] = {-HUGE_VAL, -HUGE_VAL}, info[2];
  if (n > 0 && first == tfirst) {
    mine[0] = body;
    mine[1] = depth;
  }
  MPI_Allreduce(mine, info, 2, MPI_DOUBLE, MPI_MAX, world);
  left_warned = 1;
  const double s = boundary_spacing() > 0.0 ? boundary_spacing() : h0;
  if (comm->me == 0)
    error->warning(
        FLERR,
        "Pair esph/solid: at step {} {} boundary particles (e.g. atom {} of body {}, {:.3g} "
        "spacings) lie less than {} spacings in front of their body's real particles (a surface "
        "lies about half a spacing out), so the body's contact surface is not where its "
        "particles are. Either the real particles were moved without their boundary particles "
        "(e.g. fix recenter, displace_atoms, set or fix move on the real particles alone; apply "
        "such commands to all atoms of the body, boundary particles included: fix recenter ... "
        "shift all), their normals no longer point out of the body (displace_atoms rotate after "
        "fix esph/boundary: rotate before it), two pieces of one body met (fix esph/boundary "
        "warns of such bodies), or the body deforms so much that its boundary particles lag "
        "behind its surface (a surface stretching several-fold, e.g. the Taylor bar's impact "
        "face: a known limit), or the run went unstable (a time step above the CFL limit: see "
        "the warnings at its start). Warned once per run",
        update->ntimestep, nall, tfirst, (int) info[0], info[1] / s, SURFACE_LEFT);
}

/* ----------------------------------------------------------------------
   fix esph/boundary turn body: the spin of every boundary particle is the
   rigid spin of its body, omega = I^-1 L about the body's centre of mass,
   from the predicted velocities of its real particles (collective)
------------------------------------------------------------------------- */

void PairESPHSolid::turn_with_bodies()
{
  std::vector<double> sum;
  ESPH::body_sums(lmp, state, group->bitmask[0], turn_bodies, hq, Q_V, turn_ref, sum);
  const int nb = turn_bodies.size();
  std::vector<double> omega(3 * nb);
  for (int k = 0; k < nb; k++)
    ESPH::rigid_spin(ESPH::body_motion(sum.data() + ESPH::BODY_NSUM * k), dim, &omega[3 * k]);
  const double *rmass = state->rmass;
  const int *body = state->body;
  for (int i = 0; i < atom->nlocal; i++) {
    if (rmass[i] > 0.0) continue;
    const int k = ESPH::body_slot(turn_bodies, body[i]);
    if (k < 0) continue;
    // bspin holds W = [omega]x as W_xy, W_xz, W_yz
    const double *w = &omega[3 * k];
    bspin[i][0] = -w[2];
    bspin[i][1] = w[1];
    bspin[i][2] = -w[0];
  }
}
