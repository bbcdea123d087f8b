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
   pair esph/solid: contact geometry (normals and depths of the real
   particles, surface gaps of the boundary particles) and contact bookkeeping
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_grid.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_set>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   normal and depth of real particle i from its sums; the length of the
   normal is kept as the coherence |sum n_k W| / sum W <= 1
------------------------------------------------------------------------- */

void PairESPHSolid::store_normal(int i)
{
  const double *a = acc[i];
  const double n2 =
      a[A_NSUM] * a[A_NSUM] + a[A_NSUM + 1] * a[A_NSUM + 1] + a[A_NSUM + 2] * a[A_NSUM + 2];
  if (n2 > 0.0 && a[A_WSUM] > 0.0) {
    const double inv = 1.0 / a[A_WSUM];
    for (int d = 0; d < 3; d++) state->n[i][d] = a[A_NSUM + d] * inv;
    state->depth[i] = a[A_DSUM] * inv;
  } else {
    state->n[i][0] = state->n[i][1] = state->n[i][2] = 0.0;
    state->depth[i] = 0.0;
  }
  // the gap from the boundary particles of the own body, at the time of this computation
  // (contact/gap touch: none until the body touches another; its boundary particles keep
  // their gaps, so that the gap has its rate and history when the touch comes)
  if (contact == CONTACT_SOLID && a[A_GW] > 0.0 && (!touch_on_run || touch_body(state->body[i]))) {
    state->gap[i] = a[A_GG] / a[A_GW];
    state->gapv[i] = a[A_GV] / a[A_GW];
  } else {
    state->gap[i] = GAP_NONE;
    state->gapv[i] = 0.0;
  }
  // engagement for the next computation, from the gap it will see; the stored value is
  // the one this computation used until now (hoisted)
  state->eng[i] = (contact == CONTACT_SOLID)
      ? contact_engage(hq[i][Q_ENG], state->gap[i] + dt_step * state->gapv[i] - GAP_EPS * h0, onset)
      : 0.0;
}

/* ----------------------------------------------------------------------
   contact/normal cone: the cone of real particle i from its sums (for the
   next computation), where another body's surface is in range; else none
------------------------------------------------------------------------- */

void PairESPHSolid::store_cone(int i)
{
  const double *a = acc[i];
  double *cn = state->cone[i];
  if (a[A_WSUM] > 0.0 && state->gap[i] < GAP_NONE) {
    const double inv = 1.0 / a[A_WSUM];
    const double s[6] = {a[A_NN] * inv,     a[A_NN + 1] * inv, a[A_NN + 2] * inv,
                         a[A_NN + 3] * inv, a[A_NN + 4] * inv, a[A_NN + 5] * inv};
    contact_cone(s, cn);
  } else {
    for (int k = 0; k < 6; k++) cn[k] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   the entry of the pair of bodies a, b (in either order) in a tally
------------------------------------------------------------------------- */

std::array<double, PairESPHSolid::NTALLY> &PairESPHSolid::tally_bodies(BodyTally &tally, int a,
                                                                       int b)
{
  const auto key = (a < b) ? std::make_pair(a, b) : std::make_pair(b, a);
  auto it = tally.find(key);
  if (it == tally.end()) it = tally.emplace(key, std::array<double, NTALLY>{}).first;
  return it->second;
}

/* ----------------------------------------------------------------------
   gap of boundary particle i from its best facing partner of another body
------------------------------------------------------------------------- */

void PairESPHSolid::store_bnd_gap(int i)
{
  if (!contact_bnd_result(acc[i] + B_GAP, state->gap[i], state->gapv[i])) {
    state->gap[i] = GAP_NONE;
    state->gapv[i] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   contact/gap touch: the pairs of bodies that touch now, gathered on every
   rank: two of their real particles within the kernel's reach are both
   engaged (by the engagements this computation starts from, hq's on the
   ghosts too), or the cells of two of their real particles meet
   (touch_cells()). A body touches while it is in such a pair or has an
   engaged real particle. Called by
   compute_normals() at the start of a run and before the correction or
   the pair pass (split = 1: the split list of simd_split(), where the vector
   pass runs; else the whole half list): the same positions, the same
   bodies. The cells are looked at only where two real particles of a pair
   of bodies not touching by engagement are close enough for their cells to
   meet (touch_frames()): in flight and in contact nothing is done but the
   scan
------------------------------------------------------------------------- */

void PairESPHSolid::update_touch(int split)
{
  double **x = atom->x;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int nall = atom->nlocal + atom->nghost;
  const double sb = boundary_spacing();
  const double s = (sb > 0.0) ? sb : h0;
  const double reach2 = TOUCH_REACH * TOUCH_REACH * s * s;
  const double cutsq = cut_global * cut_global;
  // each particle's spacing, its body's, where bodies sit on lattices of different spacings
  // (nullptr: all s)
  std::vector<double> spv;
  const int uniform = (spacing_lo == spacing_hi);
  if (!uniform)
    for (int i = 0; i < nall; i++) spv.push_back(rmass[i] > 0.0 ? spacing_of(body[i]) : s);
  const double *sp = uniform ? nullptr : spv.data();

  // known: the engaged bodies (keys (b, b)) and the pairs of bodies with two engaged real
  // particles in reach; the rest, the cross-body pairs close enough for their cells to meet
  // (a handful of keys: each is added once, and the pairs of bodies known here already are
  // no candidates)
  std::vector<long long> known;
  auto add_known = [&known](long long k) {
    if (std::find(known.begin(), known.end(), k) == known.end()) known.push_back(k);
  };
  for (int i = 0; i < atom->nlocal; i++)
    if (rmass[i] > 0.0 && hq[i][Q_ENG] > 0.0) add_known(touch_key(body[i], body[i]));
  std::vector<int> near;
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (rmass[i] <= 0.0) continue;
    const int bi = body[i];
    const int *jlist = split ? simd_j.data() + simd_first[ii] : list->firstneigh[i];
    const int jnum = split ? simd_first[ii + 1] - simd_first[ii] : list->numneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (body[j] == bi || rmass[j] <= 0.0) continue;
      const double xij[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      const double r2 = xij[0] * xij[0] + xij[1] * xij[1] + xij[2] * xij[2];
      // (the sum of the two cells' half diagonals)
      const double sij = uniform ? s : 0.5 * (sp[i] + sp[j]);
      const double rch2 = uniform ? reach2 : TOUCH_REACH * TOUCH_REACH * sij * sij;
      if (r2 > rch2 && r2 >= cutsq) continue;
      const long long key = touch_key(bi, body[j]);
      if (hq[i][Q_ENG] > 0.0 && hq[j][Q_ENG] > 0.0 && r2 < cutsq) add_known(key);
      if (r2 <= rch2 && std::find(known.begin(), known.end(), key) == known.end()) {
        near.push_back(i);
        near.push_back(j);
      }
    }
  }
  known = ESPHCheck::global_set(lmp, known);
  std::vector<int> cand;
  for (size_t k = 0; k < near.size(); k += 2)
    if (!std::binary_search(known.begin(), known.end(),
                            touch_key(body[near[k]], body[near[k + 1]]))) {
      cand.push_back(near[k]);
      cand.push_back(near[k + 1]);
    }
  int any = !cand.empty(), any_all = 0;
  MPI_Allreduce(&any, &any_all, 1, MPI_INT, MPI_MAX, world);
  if (any_all) {
    touch_mark.assign(nall, 0.0);
    for (int i : cand) touch_mark[i] = 1.0;
    touch_frames(s, sp);
    std::vector<long long> found;
    for (size_t k = 0; k < cand.size(); k += 2) {
      const int i = cand[k], j = cand[k + 1];
      const double xij[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
      if (touch_cells(xij, &touch_frame[9 * (size_t) i], &touch_frame[9 * (size_t) j],
                      sp ? sp[i] : s, sp ? sp[j] : s))
        found.push_back(touch_key(body[i], body[j]));
    }
    found = ESPHCheck::global_set(lmp, found);
    known.insert(known.end(), found.begin(), found.end());
    std::sort(known.begin(), known.end());
  }
  touch_pairs.clear();
  touch_bodies.clear();
  for (long long k : known) {
    int a, b;
    unpack_key(k, a, b);
    touch_bodies.push_back(a);
    touch_bodies.push_back(b);
    if (a != b) touch_pairs.push_back(k);
  }
  std::sort(touch_bodies.begin(), touch_bodies.end());
  touch_bodies.erase(std::unique(touch_bodies.begin(), touch_bodies.end()), touch_bodies.end());
}

/* ----------------------------------------------------------------------
   the frames of the cells (lattice_frame()) of the real particles marked in
   touch_mark (on any rank), from their neighbours of the same body; the
   others keep the box's axes. A grid of the real particles, owned and
   ghosts, gives the neighbours in an order that does not depend on the ranks
------------------------------------------------------------------------- */

void PairESPHSolid::touch_frames(double s, const double *sp)
{
  double **x = atom->x;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int dim = domain->dimension;

  if (force->newton_pair) {
    comm_stage = COMM_TOUCH;
    comm->reverse_comm(this, 1);
  }
  // the box's axes on the owned atoms; the ghosts' frames come with the communication below
  touch_frame.assign(9 * (size_t) nall, 0.0);
  for (int i = 0; i < nlocal; i++)
    for (int a = 0; a < 3; a++) touch_frame[9 * (size_t) i + 4 * a] = 1.0;

  // the real particles in the grid cells around the marked ones (of the largest spacing)
  const double size = TOUCH_SHELL_HI * (sp ? spacing_hi : s);
  CellGrid grid(domain->boxlo, size);
  std::unordered_set<long long> around;
  for (int i = 0; i < nlocal; i++) {
    if (touch_mark[i] == 0.0 || rmass[i] <= 0.0) continue;
    long long c[3];
    grid.cell_of(x[i], c);
    for (int a = -1; a <= 1; a++)
      for (int b = -1; b <= 1; b++)
        for (int cc = -1; cc <= 1; cc++) {
          const long long cm[3] = {c[0] + a, c[1] + b, c[2] + cc};
          around.insert(CellGrid::key_of(cm));
        }
  }
  std::vector<int> real;
  for (int i = 0; i < nall; i++) {
    if (rmass[i] <= 0.0) continue;
    long long c[3];
    grid.cell_of(x[i], c);
    if (around.count(CellGrid::key_of(c))) real.push_back(i);
  }
  grid.build((int) real.size(),
             [&](int k) {
               return x[real[k]];
             },
             [&](int k) {
               return tag[real[k]];
             });
  std::vector<double> d;
  for (int i = 0; i < nlocal; i++) {
    if (touch_mark[i] == 0.0 || rmass[i] <= 0.0) continue;
    long long c[3];
    grid.cell_of(x[i], c);
    d.clear();
    for (int a = -1; a <= 1; a++)
      for (int b = -1; b <= 1; b++)
        for (int cc = -1; cc <= 1; cc++) {
          const std::vector<int> *cell = grid.at(c, a, b, cc);
          if (!cell) continue;
          for (int k : *cell) {
            const int j = real[k];
            if (j == i || body[j] != body[i]) continue;
            for (int q = 0; q < 3; q++) d.push_back(x[j][q] - x[i][q]);
          }
        }
    lattice_frame(d.data(), (int) d.size() / 3, sp ? sp[i] : s, dim, &touch_frame[9 * (size_t) i]);
  }
  comm_stage = COMM_TOUCH;
  comm->forward_comm(this, 9);
}

/* body b touches another body: its real particles take surface gaps */

bool PairESPHSolid::touch_body(int b) const
{
  return std::binary_search(touch_bodies.begin(), touch_bodies.end(), b);
}

/* ----------------------------------------------------------------------
   the real particles' surface sums (normal and depth, eq. 30; gap; cone)
   are needed in this computation. Under contact solid with the touch,
   what they give is used by the cross-body pairs of the next computation
   that interact, and a pair interacts only across a gap below the cap:
   one of its particles must have a gap, which a real particle takes only
   while its body touches another (store_normal()). So while no body
   touches (all in flight or apart, a scene of one body) the sums, 17 % of
   the vector pass, are skipped: normals and depths are 0 then and the
   gaps none, the engagements fall as they would, and no force changes
------------------------------------------------------------------------- */

int PairESPHSolid::surface_sums() const
{
  if (contact != CONTACT_SOLID || !gap_touch) return 1;
  return touch_bodies.empty() ? 0 : 1;
}

/* ----------------------------------------------------------------------
   normals (eq. 30) and depths of real particles from the boundary particles
   of their own body; used at the start of a run, later they come with the
   regular pair loop; with touch, the touch first (update_touch())
------------------------------------------------------------------------- */

void PairESPHSolid::compute_normals(int touch)
{
  double **x = atom->x;
  double **v = atom->v;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;
  const int solid = (contact == CONTACT_SOLID);

  // normals, h and velocities of the boundary particles must be known on ghosts (and the
  // engagements, for the touch)
  for (int i = 0; i < nlocal; i++) {
    for (int d = 0; d < 3; d++) {
      hq[i][Q_N + d] = state->n[i][d];
      hq[i][Q_V + d] = v[i][d];
    }
    hq[i][Q_H] = state->h[i];
    hq[i][Q_ENG] = state->eng[i];
  }
  comm_stage = COMM_NORMALS;
  comm->forward_comm(this, 8);
  if (touch) update_touch(0);
  surf_on = surface_sums();
  for (int i = 0; i < nall; i++) {
    for (int k = A_NSUM; k <= A_WSUM; k++) acc[i][k] = 0.0;
    if (qcol_n >= 0)
      for (int k = A_NN; k < A_NN + 6; k++) acc[i][k] = 0.0;
    for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
  }

  // pass 1: normal sums of real particles, gaps of boundary particles
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq_global) continue;
      if (rmass[i] == 0.0 && rmass[j] == 0.0) {
        if (solid && body[i] != body[j])
          bnd_gap_pair(acc[i], (newton_pair || j < nlocal) ? acc[j] : nullptr, hq[i], hq[j], dx,
                       GAP_EPS * h0, gap_reach2, gap_plane);
        continue;
      }
      if (rmass[i] > 0.0 && rmass[j] > 0.0) continue;
      if (body[i] != body[j]) continue;
      const double hij = hvar_flag ? 0.5 * (hq[i][Q_H] + hq[j][Q_H]) : h0;
      double w, dw;
      if (!kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw))
        continue;
      const int p = (rmass[i] > 0.0) ? i : j;
      const int k = (p == i) ? j : i;
      const double sgn = (k == i) ? 1.0 : -1.0;
      if (surf_on && (p < nlocal || newton_pair || p == i)) {
        add_normal_sums(acc[p], w, sgn, dx, hq[k] + Q_N);
        if (qcol_n >= 0) add_cone_sums(acc[p], w, hq[k] + Q_N);
      }
      // boundary particle k: sum_p W (x_p - x_k) = -sgn dx W in its (otherwise unused)
      // normal-sum slots, for the check of its normal below
      if (k < nlocal || newton_pair || k == i)
        for (int d = 0; d < 3; d++) acc[k][A_NSUM + d] -= w * sgn * dx[d];
    }
  }
  if (newton_pair) {
    comm_stage = COMM_NORMALS;
    comm->reverse_comm(this, (A_WSUM - A_NSUM + 1) + (GAP_END - A_GW) + (qcol_n >= 0 ? 6 : 0));
  }
  // a boundary normal should point away from its body's real particles nearby: one that is
  // more than 60 degrees off belongs to positions changed after fix esph/boundary made it
  // (displace_atoms rotate), which do not carry the normals along
  bigint nbad = 0, nchecked = 0;
  for (int i = 0; i < nlocal; i++) {
    if (rmass[i] == 0.0) {
      store_bnd_gap(i);
      hq[i][Q_GAP] = state->gap[i];
      hq[i][Q_GAPV] = state->gapv[i];
      const double *c = acc[i] + A_NSUM;
      const double *n = state->n[i];
      const double cc = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      if (cc > 0.0) {
        nchecked++;
        if (-(c[0] * n[0] + c[1] * n[1] + c[2] * n[2]) < NORMAL_CHECK_COS * cc) nbad++;
      }
    } else {
      for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
    }
  }
  bigint mine[2] = {nbad, nchecked}, all[2];
  MPI_Allreduce(mine, all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
  if (all[0] > NORMAL_CHECK_SHARE * all[1] && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid: {} of {} boundary particles have normals more than 60 "
                   "degrees off the direction away from their body's particles: positions "
                   "changed after fix esph/boundary (e.g. displace_atoms rotate) keep the old "
                   "normals; rotate a body before defining fix esph/boundary, or set the "
                   "normals (d2_esph_n) of its boundary particles",
                   all[0], all[1]);

  // pass 2: gaps of real particles from their own boundary particles
  if (solid && surf_on) {
    comm_stage = COMM_GAPS;
    comm->forward_comm(this, 2);
    for (int i = nlocal; i < nall; i++)
      for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if ((rmass[i] == 0.0) == (rmass[j] == 0.0)) continue;
        if (body[i] != body[j]) continue;
        const double dx[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
        const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
        if (rsq >= cutsq_global) continue;
        const double hij = hvar_flag ? 0.5 * (hq[i][Q_H] + hq[j][Q_H]) : h0;
        double w, dw;
        if (!kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw))
          continue;
        const int p = (rmass[i] > 0.0) ? i : j;
        const int k = (p == i) ? j : i;
        if (p >= nlocal && !newton_pair && p != i) continue;
        // the gaps are of this moment: no extrapolation
        add_gap_sums(acc[p], w, hq[k], 0.0);
      }
    }
    if (newton_pair) {
      comm_stage = COMM_GAPS;
      comm->reverse_comm(this, GAP_END - A_GW);
    }
  }
  for (int i = 0; i < nlocal; i++) {
    if (rmass[i] == 0.0) continue;
    store_normal(i);
    if (qcol_n >= 0) store_cone(i);
    // the force computation brings the gap forward by one step: it is of now
    if (state->gap[i] < GAP_NONE) state->gap[i] -= update->dt * state->gapv[i];
  }
  normals_valid = 1;
}

/* ----------------------------------------------------------------------
   normal, surface gap, gap rate and engagement (6 values) of owned atom i that the
   last force computation used (its hoisted copy; valid until the next
   computation); false before any computation
------------------------------------------------------------------------- */

bool PairESPHSolid::geometry_used(int i, double *out) const
{
  if (!hq) return false;
  const double *q = hq[i];
  for (int k = 0; k < 3; k++) out[k] = q[Q_N + k];
  out[3] = q[Q_GAP];
  out[4] = q[Q_GAPV];
  out[5] = q[Q_ENG];
  return true;
}

/* ----------------------------------------------------------------------
   per-atom contact output for compute esph/atom: zeroed for owned and
   ghost atoms before the pair loop, which adds to it for every interacting
   cross-body pair (count, transmitted compressive normal force)
------------------------------------------------------------------------- */

void PairESPHSolid::atom_contact_clear()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > atom_contact_nmax) {
    atom_contact_nmax = atom->nmax;
    memory->destroy(atom_contact);
    memory->create(atom_contact, atom_contact_nmax, 2, "pair:atom_contact");
  }
  if (nall > 0) memset(&atom_contact[0][0], 0, sizeof(double) * 2 * nall);
}

/* ----------------------------------------------------------------------
   friction (pair_style esph/solid friction mu): the recorded cross-body
   pairs of this computation get a tangential force of at most the Coulomb
   force mu |f_n|, the sum of
   - the static friction the pair held (its share f_c / F_i of the static
     friction its particle i held at the last computation, F_i the sum of
     the Coulomb forces of i's pairs (A_FSUM), the two particles' averaged),
   - a spring on the slip of this step: the pair's share of the force that
     would stop the slip of its reduced mass within SPRING_STEPS steps, kept
     as static friction for the next computation, and
   - a dashpot on the slip: the share of the force that would stop it within
     STICK_STEPS steps, of the particle with the larger F (against a rigid
     particle, which does not move, the deformable one's).
   The pairs of a particle together thus stop its slip without reversing it,
   and hold a tangential load once it has stopped (without the static part
   a held load was carried at a steady creep of 4 dt tau / (rho dx)). Where
   the Coulomb force caps the sum, the pair slides and the force it keeps is
   the capped one
------------------------------------------------------------------------- */

void PairESPHSolid::friction_pass()
{
  const int nlocal = atom->nlocal, nall = nlocal + atom->nghost;
  if (atom->nmax > fric_nmax) {
    fric_nmax = atom->nmax;
    memory->destroy(fric_held);
    memory->destroy(fric_found);
    memory->create(fric_held, fric_nmax, 3, "pair:fric_held");
    memory->create(fric_found, fric_nmax, 3, "pair:fric_found");
  }
  // the static friction the owned particles held (none where the state does not hold it)
  double **held = state->fricu;
  for (int i = 0; i < nlocal; i++)
    for (int k = 0; k < 3; k++) fric_held[i][k] = held ? held[i][k] : 0.0;
  for (int i = 0; i < nall; i++)
    for (int k = 0; k < 3; k++) fric_found[i][k] = 0.0;
  // the Coulomb sums of the owners, then theirs and the static friction at the ghosts
  comm_stage = COMM_FRIC;
  if (force->newton_pair) comm->reverse_comm(this, 1);
  comm->forward_comm(this, 4);

  double **f = atom->f;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int couple = couple_on;
  const double dt = dt_step;
  for (const FricPair &p : fric_pairs) {
    const int i = p.i, j = p.j;
    const double fsi = acc[i][A_FSUM], fsj = acc[j][A_FSUM];
    // the static friction held, the pair's shares of its particles', in the tangent plane
    double st[3];
    for (int a = 0; a < 3; a++) {
      const double si = p.fc / fsi * fric_held[i][a], sj = p.fc / fsj * fric_held[j][a];
      st[a] = (p.rig == 1) ? -sj : (p.rig == 2) ? si : 0.5 * (si - sj);
    }
    const double stn = st[0] * p.nc[0] + st[1] * p.nc[1] + st[2] * p.nc[2];
    // the force per unit slip velocity that stops the pair's share of the slip in one step
    const double fsum = (p.rig == 1) ? fsj : (p.rig == 2) ? fsi : std::max(fsi, fsj);
    const double cstop = p.fc * p.mred / (fsum * dt);
    double ft[3], fs[3];
    for (int a = 0; a < 3; a++) {
      fs[a] = st[a] - stn * p.nc[a] - cstop / SPRING_STEPS * p.vt[a];
      ft[a] = fs[a] - cstop / STICK_STEPS * p.vt[a];
    }
    // Coulomb: mu |f_n| at most; sliding, the capped force is what the pair keeps
    const double ft2 = ft[0] * ft[0] + ft[1] * ft[1] + ft[2] * ft[2];
    if (ft2 > p.fc * p.fc) {
      const double cap = p.fc / sqrt(ft2);
      for (int a = 0; a < 3; a++) fs[a] = ft[a] *= cap;
    }
    // the work of the friction on the slip heats the pair (acc's viscous heating slot: per
    // unit of m_i m_j): dissipated by the dashpot and the sliding, stored and returned by
    // the static part
    const double hw = -p.heat * (ft[0] * p.vt[0] + ft[1] * p.vt[1] + ft[2] * p.vt[2]) / p.mm;
    for (int a = 0; a < 3; a++) {
      f[i][a] += ft[a];
      fric_found[i][a] += fs[a];
    }
    acc[i][A_AVHEAT] += rmass[j] * hw;
    if (p.jown) {
      for (int a = 0; a < 3; a++) {
        f[j][a] -= ft[a];
        fric_found[j][a] -= fs[a];
      }
      acc[j][A_AVHEAT] += rmass[i] * hw;
    }
    if (couple) {
      double t[3];
      for (int a = 0; a < 3; a++)
        t[a] = -(p.dx[(a + 1) % 3] * ft[(a + 2) % 3] - p.dx[(a + 2) % 3] * ft[(a + 1) % 3]);
      add_couple(acc[i], p.jown ? acc[j] : nullptr, t);
    }
    auto &tb = tally_bodies(body_tally, body[i], body[j]);
    for (int a = 0; a < 3; a++) tb[3 + a] += p.wnet * ft[a];
  }
  // the static friction found, summed at the owners, for the next computation
  if (force->newton_pair) {
    comm_stage = COMM_FRIC_FOUND;
    comm->reverse_comm(this, 3);
  }
  if (state->fric)
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 3; k++) state->fric[i][k] = fric_found[i][k];
}
