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
   pair esph/solid: the pair loop and its compile-time dispatch
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "force.h"
#include "math_special.h"
#include "neigh_list.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   the pair loop: one pass over the half neighbour list
   real-real same body (or contact off): full SPH coupling (eqs. 1-7, 8, 15, 17)
   real-real other body: contact rule (section 4.3), normal components only
   real-boundary same body: interpolation to the boundary particle (4.2) and
     the real particle's normal sums (eq. 30)
------------------------------------------------------------------------- */

template <int BND, int HVAR, int HEAT, int CORR, int EXTRA>
void PairESPHSolid::pair_loop(LoopOut &out)
{
  double **x = atom->x;
  // the rows this pass adds to (LoopOut)
  double **const f = out.f;
  double **const acc = out.acc;
  double **const catom = out.catom;
  BodyTally &tally = *out.tally;
  int ncontact = 0, ntouch = 0;
  double fcont = 0.0;
  double dtcross = BIG_DT;    // the step the pairs across bodies allow (cross_dt())
  const tagint *tag = atom->tag;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;

  // constant h: kernel normalisation once
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  const double gap_cap = gaptol * h0;
  const double gap_eps = GAP_EPS * h0;
  const double dt = dt_step;
  // pair forces in force units (atom->f, the contact force); all else internal
  const double fconv = units.force;
  const int solid = (contact == CONTACT_SOLID);
  // artificial stress: 1 / W(dp) at constant h
  double wdp_inv0 = 0.0;
  constexpr int AST = EXTRA & EXTRA_ASTRESS;
  constexpr int XSPH = EXTRA & EXTRA_XSPH;
  constexpr int FRIC = BND && (EXTRA & EXTRA_FRICTION);
  constexpr int RIG = BND && (EXTRA & EXTRA_RIGID);
  // the switched (visc/switch) or reconstructed (visc/recon) viscosity, either or both
  constexpr int VEXT = EXTRA & EXTRA_VISC;
  const int vswitch = VEXT && vswitch_flag;
  // switched viscosity: beta_ij keeps the ratio beta / alpha of the visc keyword
  const double beta_ratio = (vswitch && alpha > 0.0) ? beta / alpha : 0.0;
  // visc/recon: the limiter, and the column of the strain rates it reconstructs with
  const int recon = VEXT ? recon_flag : 0;
  const int qd = qcol_d;
  // contact/normal cone: compiled into its own variant and into those with friction or rigid
  // bodies (which test it at run time), out of the plain loop
  constexpr int CONE = BND && (EXTRA & (EXTRA_CONE | EXTRA_FRICTION | EXTRA_RIGID));
  const int qcn = CONE ? qcol_n : -1;
  const int couple = BND && couple_on;
  // the real particles' surface sums (surface_sums())
  const int surf = surf_on;
  if (AST) {
    double wdp, dwdp;
    kernel_eval(kernel, dim, norm0, hinv0, astress_dp, wdp, dwdp);
    wdp_inv0 = 1.0 / wdp;
  }

  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  // the bulk pairs (real-real, not across bodies) are the vector pass's (bulk_pass()): this
  // loop then takes the other pairs from the split list (simd_split())
  const int *const split_first = simd_active ? simd_first.data() : nullptr;
  const int *const split_j = simd_active ? simd_j.data() : nullptr;

  const int iifrom = out.iifrom, iito = out.iito;
  // x is one contiguous array (memory->create): atom j's position at 3 j
  const double *const xflat = x ? x[0] : nullptr;
  struct {
    int j[NBLOCK];
    double dx[NBLOCK][3], rsq[NBLOCK], w[NBLOCK], dw[NBLOCK];
    bool in[NBLOCK];
  } blk;
  for (int ii = iifrom; ii < iito; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double mi = rmass[i];
    const int bi = body[i];
    const double *qi = hq[i];
    // sums for i in registers (acc[i] and acc[j] could alias for the compiler)
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    double gi[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double mci[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double avhi = 0.0, heati = 0.0;
    double xsi[3] = {0.0, 0.0, 0.0};
    const int *jlist = split_first ? split_j + split_first[ii] : firstneigh[i];
    const int jnum = split_first ? split_first[ii + 1] - split_first[ii] : numneigh[i];

    // the neighbours in blocks of NBLOCK: first the pairs within the cutoff and, at
    // constant h, their kernel values, then the physics of each pair. The square root and
    // the division of the kernel of many pairs then overlap, instead of heading the chain
    // of dependent operations of each pair (the same operations: the same results)
    for (int j0 = 0; j0 < jnum; j0 += NBLOCK) {
      const int jend = std::min(jnum, j0 + NBLOCK);
      int nb = 0;
      for (int jj = j0; jj < jend; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        const double *xj = xflat + 3 * j;
        const double d0 = xi - xj[0], d1 = yi - xj[1], d2 = zi - xj[2];
        const double rsq = d0 * d0 + d1 * d1 + d2 * d2;
        if (rsq >= cutsq_global) continue;
        blk.j[nb] = j;
        blk.dx[nb][0] = d0;
        blk.dx[nb][1] = d1;
        blk.dx[nb][2] = d2;
        blk.rsq[nb] = rsq;
        nb++;
      }
      if (!HVAR)
        for (int b = 0; b < nb; b++)
          blk.in[b] = kernel_eval(kernel, dim, norm0, hinv0, sqrt(blk.rsq[b]), blk.w[b], blk.dw[b]);

      for (int b = 0; b < nb; b++) {
        const int j = blk.j[b];
        const double *dx = blk.dx[b];
        const double rsq = blk.rsq[b];
        const double mj = rmass[j];
        if (BND && mi == 0.0 && mj == 0.0) {
          // two boundary particles: the surface gap between different bodies
          if (solid && bi != body[j])
            bnd_gap_pair(acc[i], (newton_pair || j < nlocal) ? acc[j] : nullptr, qi, hq[j], dx,
                         gap_eps, gap_reach2, gap_plane);
          continue;
        }
        const double *qj = hq[j];

        double hij, norm, hinv;
        if (HVAR) {
          hij = 0.5 * (qi[Q_H] + qj[Q_H]);
          hinv = 1.0 / hij;
          norm = kernel_norm(kernel, dim, hij);
        } else {
          hij = h0;
          hinv = hinv0;
          norm = norm0;
        }
        double w, dw;
        if (HVAR) {
          if (!kernel_eval(kernel, dim, norm, hinv, sqrt(rsq), w, dw)) continue;
        } else {
          if (!blk.in[b]) continue;
          w = blk.w[b];
          dw = blk.dw[b];
        }
        const double g[3] = {dw * dx[0], dw * dx[1], dw * dx[2]};    // grad_i W_ij
        const int jown = (newton_pair || j < nlocal);

        if (BND && (mi == 0.0 || mj == 0.0)) {
          // boundary particle k and real particle p of the same body
          if (bi != body[j]) continue;
          int k, p;
          double sgn;
          if (mi == 0.0) {
            k = i;
            p = j;
            sgn = 1.0;
          } else {
            k = j;
            p = i;
            sgn = -1.0;
          }
          const double *qp = hq[p];
          const double *qk = hq[k];
          if (k < nlocal || newton_pair || k == i) {
            // grad_k W_kp = sgn * g
            double *ak = acc[k];
            const double Vp = rmass[p] / qp[Q_RHO];
            const double gk[3] = {sgn * g[0], sgn * g[1], sgn * g[2]};
            for (int a = 0; a < 3; a++) {
              const double va = Vp * qp[Q_V + a];
              ak[B_A + 3 * a] += va * gk[0];
              ak[B_A + 3 * a + 1] += va * gk[1];
              ak[B_A + 3 * a + 2] += va * gk[2];
              ak[B_B + a] += Vp * gk[a];
              ak[B_VSUM + a] += Vp * w * qp[Q_V + a];
              // x_p - x_k = -sgn * dx
              const double xa = -sgn * Vp * dx[a];
              ak[B_M + 3 * a] += xa * gk[0];
              ak[B_M + 3 * a + 1] += xa * gk[1];
              ak[B_M + 3 * a + 2] += xa * gk[2];
              ak[B_XSUM + a] += xa * w;
            }
            ak[B_WSUM] += Vp * w;
          }
          if (surf && (p < nlocal || newton_pair || p == i)) {
            add_normal_sums(acc[p], w, sgn, dx, qk + Q_N);
            if (solid) {
              add_gap_sums(acc[p], w, qk, dt);
              if (qcn >= 0) add_cone_sums(acc[p], w, qk + Q_N);
            }
          }
          continue;
        }

        // two real particles
        const int cross = BND && (contact != CONTACT_OFF) && (bi != body[j]);
        // a rigid particle (pair_coeff ... rigid yes) meets only deformable ones of other
        // bodies, as the mirror image of its partner: stress, sound speed and density of the
        // partner, twice the normal relative velocity (below): the reaction of a rigid wall
        const int ri = RIG && rigid[type[i]], rj = RIG && rigid[type[j]];
        if ((ri || rj) && (!cross || (ri && rj))) continue;
        // across bodies of different materials the sums of i weigh j by its volume at i's
        // density, w_j = rho0_i V_j = s_i m_j (s_i = rho0_i / rho0_j, the reference
        // densities), and the stress force takes s_i A_i + s_j A_j, so that the work of the
        // force stays the internal energies' (de_i = A_i : G_i): with the masses (s = 1) a
        // light particle against a heavy one took the heavy one's mass into its density
        // rate, a stiffness the time step does not see (iron on a foam 78 times lighter
        // gained 400 times its energy). One material: s = 1, the paper's sums exactly
        double wj = mj, wi = mi, si = 1.0, sj = 1.0;
        int vol = 0;
        if (cross && !(ri || rj)) {
          if (volume_ratio(type[i], type[j], si, sj)) {
            vol = 1;
            wj = si * mj;
            wi = sj * mi;
          }
          if (mi != mj) dtcross = std::min(dtcross, cross_dt(i, j, mi, mj));
        }
        const double *qa = ri ? qj : qi;
        const double *qb = rj ? qi : qj;
        double vij[3] = {qi[Q_V] - qj[Q_V], qi[Q_V + 1] - qj[Q_V + 1], qi[Q_V + 2] - qj[Q_V + 2]};
        // stress force per m_i m_j: (sigma_i / rho_i^2 + sigma_j / rho_j^2) grad_i W, or with
        // the correction (B_i + B_j) grad_i W, B = (sigma / rho) M^-T (Bonet and Lok 1999)
        double Tg[3];
        if (CORR == 2) {
          const double *Bi = qa + qcol_b;
          const double *Bj = qb + qcol_b;
          if (vol)
            for (int r = 0; r < 3; r++)
              Tg[r] = (si * Bi[3 * r] + sj * Bj[3 * r]) * g[0] +
                  (si * Bi[3 * r + 1] + sj * Bj[3 * r + 1]) * g[1] +
                  (si * Bi[3 * r + 2] + sj * Bj[3 * r + 2]) * g[2];
          else
            for (int r = 0; r < 3; r++)
              Tg[r] = (Bi[3 * r] + Bj[3 * r]) * g[0] + (Bi[3 * r + 1] + Bj[3 * r + 1]) * g[1] +
                  (Bi[3 * r + 2] + Bj[3 * r + 2]) * g[2];
        } else {
          const double *Ai = qa + Q_A;
          const double *Aj = qb + Q_A;
          double T[6] = {Ai[0] + Aj[0], Ai[1] + Aj[1], Ai[2] + Aj[2],
                         Ai[3] + Aj[3], Ai[4] + Aj[4], Ai[5] + Aj[5]};
          if (vol)
            for (int k = 0; k < 6; k++) T[k] = si * Ai[k] + sj * Aj[k];
          Tg[0] = T[0] * g[0] + T[3] * g[1] + T[4] * g[2];
          Tg[1] = T[3] * g[0] + T[1] * g[1] + T[5] * g[2];
          Tg[2] = T[4] * g[0] + T[5] * g[1] + T[2] * g[2];
        }
        double nc[3] = {0.0, 0.0, 0.0};
        double vn = 0.0, xn = 0.0, vx2 = 0.0;
        double vt[3] = {0.0, 0.0, 0.0};
        if (cross) {
          contact_normal(qi + Q_N, qj + Q_N, dx, nc);
          if (qcn >= 0) contact_normal_cone(qi + qcn, qj + qcn, nc);
          vn = vij[0] * nc[0] + vij[1] * nc[1] + vij[2] * nc[2];
          xn = dx[0] * nc[0] + dx[1] * nc[1] + dx[2] * nc[2];
          // |v_ij|^2 r^2, for the round-off tolerance of the approach test (vxtol())
          vx2 = (vij[0] * vij[0] + vij[1] * vij[1] + vij[2] * vij[2]) * rsq;
          // the slip velocity (of i against j) for friction
          if (FRIC)
            for (int a = 0; a < 3; a++) vt[a] = vij[a] - vn * nc[a];
          if (RIG && (ri || rj)) vn *= 2.0;
          // only the normal relative velocity couples across the interface
          vij[0] = vn * nc[0];
          vij[1] = vn * nc[1];
          vij[2] = vn * nc[2];
        }

        // Monaghan-Gingold artificial viscosity (eqs. 4-7)
        const double vr = vij[0] * dx[0] + vij[1] * dx[1] + vij[2] * dx[2];
        double pi_ij = 0.0;
        if (vr < 0.0) {
          // visc/recon: the velocities reconstructed to the pair's midpoint with the limited
          // strain rates of both particles, v_i - D_i x_ij / 2 and v_j + D_j x_ij / 2, so that
          // a linear velocity field has no viscosity (approaching pairs of one body only)
          double vrv = vr;
          if (VEXT && recon && !cross)
            vrv = std::min(recon_vr(vr, qi + qd, qj + qd, dx, recon), 0.0);
          const double mu = hij * vrv / (rsq + eps * hij * hij);
          double al = alpha, be = beta;
          if (vswitch) {
            // Morris-Monaghan switch: the mean of the two particles' alpha
            al = 0.5 * (qa[Q_ALPHA] + qb[Q_ALPHA]);
            be = beta_ratio * al;
          }
          pi_ij = (-al * 0.5 * (qa[Q_C] + qb[Q_C]) * mu + be * mu * mu) /
              (0.5 * (qa[Q_RHO] + qb[Q_RHO]));
        }
        // heating by the artificial viscosity and stress, half to each particle
        double avh = 0.5 * pi_ij * (vij[0] * g[0] + vij[1] * g[1] + vij[2] * g[2]);
        if (AST && !cross && (qi[Q_RFLAG] + qj[Q_RFLAG] > 0.0)) {
          // Monaghan (2000) artificial stress f_ij^n (R_i + R_j): a repulsion between
          // particles in tension, R = -epsilon sigma'/rho^2 in the principal frame
          double wdp_inv = wdp_inv0;
          if (HVAR) {
            double wdp, dwdp;
            kernel_eval(kernel, dim, norm, hinv, astress_dp, wdp, dwdp);
            wdp_inv = 1.0 / wdp;
          }
          const double fn = MathSpecial::powint(w * wdp_inv, astress_n);
          const double *Ri = qi + Q_R;
          const double *Rj = qj + Q_R;
          const double R[6] = {fn * (Ri[0] + Rj[0]), fn * (Ri[1] + Rj[1]), fn * (Ri[2] + Rj[2]),
                               fn * (Ri[3] + Rj[3]), fn * (Ri[4] + Rj[4]), fn * (Ri[5] + Rj[5])};
          const double Rg[3] = {R[0] * g[0] + R[3] * g[1] + R[4] * g[2],
                                R[3] * g[0] + R[1] * g[1] + R[5] * g[2],
                                R[4] * g[0] + R[5] * g[1] + R[2] * g[2]};
          Tg[0] += Rg[0];
          Tg[1] += Rg[1];
          Tg[2] += Rg[2];
          avh -= 0.5 * (vij[0] * Rg[0] + vij[1] * Rg[1] + vij[2] * Rg[2]);
        }
        const double mm = mi * mj * fconv;
        double ff[3] = {mm * (Tg[0] - pi_ij * g[0]), mm * (Tg[1] - pi_ij * g[1]),
                        mm * (Tg[2] - pi_ij * g[2])};

        if (cross) {
          double fn = ff[0] * nc[0] + ff[1] * nc[1] + ff[2] * nc[2];
          // with newton off a pair with a ghost partner is on two ranks: count it once
          const int count_pair = newton_pair || j < nlocal || tag[i] < tag[j];
          double phi = 1.0;
          int touching;
          if (solid) {
            // (contact/gap touch: only bodies that touch each other)
            const double gap = touch_apart(bi, body[j]) ? GAP_NONE : solid_gap(qi, qj, dt);
            // touching: closed, or open by no more than round-off (faces that coincide in exact
            // arithmetic are a round-off distance apart in a rotated scene); counted before
            // the gate
            touching = (gap <= gap_eps);
            phi = contact_pair_weight(gap, gap_cap, qi[Q_ENG], qj[Q_ENG]);
          } else {
            // the paper's rule measures no gap: an interacting pair is a touching one
            touching = contact_approach(vn, xn, APPROACH_ROUNDOFF * sqrt(vx2));
          }
          if (touching && count_pair) {
            ntouch++;
            tally_bodies(tally, bi, body[j])[0] += 1.0;
          }
          // contact/couple: the pair's couple about the contact point, half to each particle
          // (add_couple()). With the gradient corrections of B (bonet/lok, torquefree) the
          // bodies' own forces balance the torque of the full pair force, weighted as in
          // their M (correction()): the couple is the torque of that force less the torque
          // of the force applied (none for a pair that does not interact)
          double tcpl[3] = {0.0, 0.0, 0.0};
          if (couple && CORR == 2 && phi > 0.0) {
            const double s = phi * mm;
            for (int a = 0; a < 3; a++)
              tcpl[a] = s * (dx[(a + 1) % 3] * Tg[(a + 2) % 3] - dx[(a + 2) % 3] * Tg[(a + 1) % 3]);
          }
          // solid: no tension across contact, a pair that would pull (or not push) does not
          // interact at all (also not in the strain rate and energy, which would otherwise see
          // work that no force does); paper: only approaching pairs interact
          // (a pair with no force at all, e.g. stress-free bodies that touch at the start
          // without artificial viscosity, interacts while it approaches: its strain rate
          // builds the stress that pushes; without it the bodies would pass through).
          // A normal force of round-off size against the pair's stress scale rho c^2 counts
          // as none: between stress-free bodies its sign is that of the round-off of sums
          // whose order depends on the number of ranks, and must not decide
          // (fn rho compared with the tolerance times rho: no division; the approach's
          // tolerance, a square root, only where the force does not decide)
          const double cbar = 0.5 * (qa[Q_C] + qb[Q_C]);
          const double fn_rho = fn * 0.5 * (qa[Q_RHO] + qb[Q_RHO]);
          const double fn_tol =
              FN_ROUNDOFF * mm * (fabs(g[0]) + fabs(g[1]) + fabs(g[2])) * cbar * cbar;
          const int pulls = fn_rho > fn_tol, pushes = fn_rho < -fn_tol;
          if (solid ? (phi == 0.0 || pulls ||
                       (!pushes && !contact_approach(vn, xn, APPROACH_ROUNDOFF * sqrt(vx2))))
                    : !touching) {
            if (couple && CORR == 2) add_couple(acc[i], jown ? acc[j] : nullptr, tcpl);
            continue;
          }
          // the coupling weight scales force, strain rate and heating alike, so that the
          // work of the force is what the internal energy receives
          fn *= phi;
          avh *= phi;
          for (int a = 0; a < 3; a++) vij[a] *= phi;
          ff[0] = fn * nc[0];
          ff[1] = fn * nc[1];
          ff[2] = fn * nc[2];
          if (FRIC) {
            // Coulomb friction mu |f_n| against the slip: recorded, and applied by
            // friction_pass() once the Coulomb forces of every particle's pairs are summed
            const double fc = -friction * fn;
            if (fc > 0.0) {
              // (the pair's reduced mass; against a rigid particle, which does not move,
              // the deformable one's mass; the friction work heats the deformable one alone
              // against a rigid body, which has no internal energy)
              const int rig = RIG ? (ri ? 1 : (rj ? 2 : 0)) : 0;
              const double mred = rig ? (ri ? mj : mi) * fconv : mm / (mi + mj);
              const double wnet =
                  ((newton_pair || j < nlocal) ? 1.0 : 0.5) * ((bi < body[j]) ? 1.0 : -1.0);
              FricPair fp{i, j, jown, rig, fc, mred, mm, rig ? 1.0 : 0.5, wnet, {}, {}, {}};
              for (int a = 0; a < 3; a++) {
                fp.vt[a] = vt[a];
                fp.dx[a] = dx[a];
                fp.nc[a] = nc[a];
              }
              out.fric->push_back(fp);
              acc[i][A_FSUM] += fc;
              if (jown) acc[j][A_FSUM] += fc;
            }
          }
          if (couple) {
            for (int a = 0; a < 3; a++)
              tcpl[a] -= dx[(a + 1) % 3] * ff[(a + 2) % 3] - dx[(a + 2) % 3] * ff[(a + 1) % 3];
            add_couple(acc[i], jown ? acc[j] : nullptr, tcpl);
          }
          // transmitted compressive normal force; with newton off a pair with a ghost
          // partner is seen by two ranks
          const double fpair = (newton_pair || j < nlocal) ? -fn : -0.5 * fn;
          fcont += fpair;
          auto &tb = tally_bodies(tally, bi, body[j]);
          tb[2] += fpair;
          // the net force on the body of the smaller ID (ff acts on i), friction included
          const double wnet =
              ((newton_pair || j < nlocal) ? 1.0 : 0.5) * ((bi < body[j]) ? 1.0 : -1.0);
          for (int a = 0; a < 3; a++) tb[3 + a] += wnet * ff[a];
          if (count_pair) {
            ncontact++;
            tb[1] += 1.0;
          }
          // per-atom contact output of compute esph/atom, only when one asks for it
          if (atom_contact_flag) {
            catom[i][0] += 1.0;
            catom[i][1] -= fn;
            if (jown) {
              catom[j][0] += 1.0;
              catom[j][1] -= fn;
            }
          }
        }

        fxi += ff[0];
        fyi += ff[1];
        fzi += ff[2];

        // G = sum_j w_j (v_j - v_i) (x) grad_i W (w_j = m_j, across bodies s_i m_j), for i
        // and j alike
        for (int a = 0; a < 3; a++) {
          const double wa = -wj * vij[a];
          gi[3 * a] += wa * g[0];
          gi[3 * a + 1] += wa * g[1];
          gi[3 * a + 2] += wa * g[2];
        }
        avhi += mj * avh;
        // x_j - x_i = -dx
        if (CORR == 1) add_outer(mci, -wj, dx, g);
        double heat = 0.0;
        if (HEAT && !cross) {
          // artificial heat transfer (eqs. 8-10), conservative pairwise form
          const double zbar = 0.5 * (qi[Q_ZETA] + qj[Q_ZETA]);
          const double rbar = 0.5 * (qi[Q_RHO] + qj[Q_RHO]);
          heat = 2.0 * zbar / rbar * (qi[Q_E] - qj[Q_E]) * dw * rsq / (rsq + eps * hij * hij);
          heati += mj * heat;
        }

        // XSPH (Monaghan 1989): particles move with the velocity smoothed over their
        // own body, xsph_i = sum_j m_j / rhobar_ij (v_j - v_i) W_ij
        double wx = 0.0;
        if (XSPH && !cross) {
          wx = w / (0.5 * (qi[Q_RHO] + qj[Q_RHO]));
          xsi[0] -= mj * wx * vij[0];
          xsi[1] -= mj * wx * vij[1];
          xsi[2] -= mj * wx * vij[2];
        }

        if (jown) {
          double *aj = acc[j];
          if (XSPH && !cross)
            for (int a = 0; a < 3; a++) aj[A_XSPH + a] += mi * wx * vij[a];
          f[j][0] -= ff[0];
          f[j][1] -= ff[1];
          f[j][2] -= ff[2];
          for (int a = 0; a < 3; a++) {
            const double wa = -wi * vij[a];
            aj[A_G + 3 * a] += wa * g[0];
            aj[A_G + 3 * a + 1] += wa * g[1];
            aj[A_G + 3 * a + 2] += wa * g[2];
          }
          aj[A_AVHEAT] += mi * avh;
          if (HEAT) aj[A_HEAT] -= mi * heat;
          if (CORR == 1) add_outer(aj + A_M, -wi, dx, g);
        }
      }
    }
    f[i][0] += fxi;
    f[i][1] += fyi;
    f[i][2] += fzi;
    if (mi > 0.0) {
      double *ai = acc[i];
      for (int k = 0; k < 9; k++) ai[A_G + k] += gi[k];
      ai[A_AVHEAT] += avhi;
      if (HEAT) ai[A_HEAT] += heati;
      if (XSPH)
        for (int a = 0; a < 3; a++) ai[A_XSPH + a] += xsi[a];
      if (CORR == 1)
        for (int k = 0; k < 9; k++) ai[A_M + k] += mci[k];
    }
  }
  out.ncontact += ncontact;
  out.dtcross = std::min(out.dtcross, dtcross);
  out.ntouch += ntouch;
  out.fcontact += fcont;
}

/* ----------------------------------------------------------------------
   the time step a pair of real particles of different bodies and masses
   mi != mj allows: the lighter particle l sits against the heavier body's
   stiffness, rho_h c_L,h^2, on its own mass (its frequency c_L,h / h x
   sqrt(m_h / m_l)), which its own sound speed does not see. Measured
   (2026-12-06, a 5 x 4 x 4 iron cube at 50 m/s on a foam block and a foam
   cube on iron, density ratios r = 3 to 200, foam sound speed fixed or
   falling with r): the largest stable step falls as 1 / sqrt(r) on the
   heavy body's own step (about 1.25 / sqrt(r) of h / c_L,iron for the
   light cube); CROSS_DT_K = 0.6 keeps cfl 0.3 two and a half times inside
   it (and cfl 0.6 stable to 0.2 % energy). Materials of similar density
   (iron / aluminum, r = 2.9) are not touched: the light particle's own
   step is the smaller
------------------------------------------------------------------------- */

double PairESPHSolid::cross_dt(int i, int j, double mi, double mj) const
{
  const int l = (mi < mj) ? i : j, hv = (mi < mj) ? j : i;
  const double *ql = hq[l], *qh = hq[hv];
  const double clh = long_speed(qh[Q_C] * qh[Q_C], qh[Q_RHO], atom->type[hv]);
  const double ceff = CROSS_DT_K * clh * sqrt(std::max(mi, mj) / std::min(mi, mj));
  const double vl = sqrt(ql[Q_V] * ql[Q_V] + ql[Q_V + 1] * ql[Q_V + 1] + ql[Q_V + 2] * ql[Q_V + 2]);
  return visc_cfl_factor() * ql[Q_H] / (ceff + vl);
}

/* ----------------------------------------------------------------------
   dispatch: optional physics switched off is compiled out of the pair loop
------------------------------------------------------------------------- */

template <int BND, int HVAR, int HEAT, int CORR> void PairESPHSolid::pair_loop_extra(LoopOut &out)
{
  const int extra = (astress_flag ? EXTRA_ASTRESS : 0) | (xsph_flag ? EXTRA_XSPH : 0) |
      ((vswitch_flag || recon_flag) ? EXTRA_VISC : 0);
  // friction and rigid bodies act between bodies only: with boundary particles
  if constexpr (BND) {
    const int fric = (friction > 0.0 && contact != CONTACT_OFF);
    if (qcol_n >= 0 && !fric && !rigid_flag) {
      pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_CONE>(extra, out);
      return;
    }
    switch ((fric ? EXTRA_FRICTION : 0) | (rigid_flag ? EXTRA_RIGID : 0)) {
      case EXTRA_FRICTION:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_FRICTION>(extra, out);
        return;
      case EXTRA_RIGID:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_RIGID>(extra, out);
        return;
      case EXTRA_FRICTION | EXTRA_RIGID:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_FRICTION | EXTRA_RIGID>(extra, out);
        return;
      default:
        break;
    }
  }
  pair_loop_select<BND, HVAR, HEAT, CORR, 0>(extra, out);
}

template <int BND, int HVAR, int HEAT, int CORR, int CONTACT_EXTRA>
void PairESPHSolid::pair_loop_select(int extra, LoopOut &out)
{
  switch (extra) {
    case 0:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA>(out);
      break;
    case EXTRA_ASTRESS:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_ASTRESS>(out);
      break;
    case EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_XSPH>(out);
      break;
    case EXTRA_ASTRESS | EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_ASTRESS | EXTRA_XSPH>(out);
      break;
    case EXTRA_VISC:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VISC>(out);
      break;
    case EXTRA_VISC | EXTRA_ASTRESS:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VISC | EXTRA_ASTRESS>(out);
      break;
    case EXTRA_VISC | EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VISC | EXTRA_XSPH>(out);
      break;
    default:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VISC | EXTRA_ASTRESS | EXTRA_XSPH>(
          out);
      break;
  }
}

template <int BND, int HVAR, int HEAT> void PairESPHSolid::run_corr(LoopOut &out)
{
  if (correct_flag >= CORRECT_BONETLOK)
    pair_loop_extra<BND, HVAR, HEAT, 2>(out);
  else if (correct_flag == CORRECT_RATE)
    pair_loop_extra<BND, HVAR, HEAT, 1>(out);
  else
    pair_loop_extra<BND, HVAR, HEAT, 0>(out);
}

template <int BND, int HVAR> void PairESPHSolid::run_heat(LoopOut &out)
{
  if (heat_flag)
    run_corr<BND, HVAR, 1>(out);
  else
    run_corr<BND, HVAR, 0>(out);
}

template <int BND> void PairESPHSolid::run_hvar(LoopOut &out)
{
  if (hvar_flag)
    run_heat<BND, 1>(out);
  else
    run_heat<BND, 0>(out);
}

void PairESPHSolid::run_pair_loop(int bnd, LoopOut &out)
{
  if (bnd)
    run_hvar<1>(out);
  else
    run_hvar<0>(out);
}
