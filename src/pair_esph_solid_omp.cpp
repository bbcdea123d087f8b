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
   pair esph/solid/omp: pair esph/solid with its per-atom passes and its pair
   loop in OpenMP threads (package omp N, or -sf omp -pk omp N). The pair
   loop runs on the half neighbour list, each thread on a contiguous chunk
   of it, adding the sums of the atoms of its chunk to the arrays directly
   and those of the other atoms it reaches (partners in other chunks,
   ghosts) to private rows, which are folded in after the loop in thread
   order: no atomics, no thread-sized copies of the whole arrays, and for a
   given number of threads the same answer in every run.
------------------------------------------------------------------------- */

#include "pair_esph_solid_omp.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "esph_state.h"
#include "esph_threads.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "suffix.h"

#include <cstring>

using namespace LAMMPS_NS;
using namespace ESPHSolid;

/* ---------------------------------------------------------------------- */

PairESPHSolidOMP::PairESPHSolidOMP(LAMMPS *lmp) :
    PairESPHSolid(lmp), rows_ncalls(-1), rows_nall(-1), rows_inum(-1), rows_nthreads(0),
    rows_acc(nullptr), rows_f(nullptr), rows_catom(nullptr)
{
  suffix_flag |= Suffix::OMP;
}

/* ---------------------------------------------------------------------- */

void PairESPHSolidOMP::init_style()
{
  PairESPHSolid::init_style();
  nthreads = comm->nthreads;
  rows_ncalls = -1;
}

/* ----------------------------------------------------------------------
   the rows must be rebuilt after a new neighbour list or when the arrays
   they point into have moved
------------------------------------------------------------------------- */

bool PairESPHSolidOMP::rows_stale() const
{
  const int nall = atom->nlocal + atom->nghost;
  if (rows_ncalls != neighbor->ncalls || rows_nall != nall || rows_inum != list->inum ||
      rows_nthreads != nthreads)
    return true;
  if (nall == 0) return false;
  return rows_acc != acc[0] || rows_f != atom->f[0] ||
      rows_catom != (atom_contact ? atom_contact[0] : nullptr);
}

/* ----------------------------------------------------------------------
   per thread: the atoms outside its chunk of the neighbour list that its
   pairs reach get a private row each
------------------------------------------------------------------------- */

void PairESPHSolidOMP::build_rows()
{
  const int nall = atom->nlocal + atom->nghost;
  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  double **f = atom->f;

  // chunks of about equal work: a listed pair of two real particles counts REAL_PAIR_COST,
  // one with a boundary particle 1, and each atom 1
  thr.resize(nthreads);
  const double *rmass = state->rmass;
  std::vector<bigint> work(inum);
  bigint total = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int *jlist = firstneigh[i];
    bigint w = 1;
    for (int jj = 0; jj < numneigh[i]; jj++)
      w += (rmass[i] > 0.0 && rmass[jlist[jj] & NEIGHMASK] > 0.0) ? REAL_PAIR_COST : 1;
    work[ii] = w;
    total += w;
  }
  bigint sum = 0;
  int ii = 0;
  for (int t = 0; t < nthreads; t++) {
    thr[t].from = ii;
    const bigint target = total * (t + 1) / nthreads;
    while (ii < inum && (sum < target || t == nthreads - 1)) sum += work[ii++];
    thr[t].to = ii;
  }
  // the thread whose chunk holds the atom, -1 for none
  std::vector<int> owner(nall, -1);
  ESPH::for_chunks(nthreads, inum, [&](int, int, int tid) {
    for (int ii = thr[tid].from; ii < thr[tid].to; ii++) owner[ilist[ii]] = tid;
  });
  ESPH::for_chunks(nthreads, inum, [&](int, int, int tid) {
    Thread &t = thr[tid];
    const int from = t.from, to = t.to;
    std::vector<int> slot(nall, -1);
    t.foreign.clear();
    for (int ii = from; ii < to; ii++) {
      const int i = ilist[ii];
      const int *jlist = firstneigh[i];
      for (int jj = 0; jj < numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if (owner[j] != tid && slot[j] < 0) {
          slot[j] = (int) t.foreign.size();
          t.foreign.push_back(j);
        }
      }
    }
    t.priv.resize(t.foreign.size() * PRIV_STRIDE);
    t.acc_rows.assign(nall, nullptr);
    t.f_rows.assign(nall, nullptr);
    t.c_rows.assign(nall, nullptr);
    for (int k = 0; k < nall; k++) {
      if (owner[k] == tid) {
        t.acc_rows[k] = acc[k];
        t.f_rows[k] = f[k];
        t.c_rows[k] = atom_contact ? atom_contact[k] : nullptr;
      } else if (slot[k] >= 0) {
        double *r = t.priv.data() + (size_t) slot[k] * PRIV_STRIDE;
        t.acc_rows[k] = r;
        t.f_rows[k] = r + PRIV_F;
        t.c_rows[k] = r + PRIV_C;
      }
    }
  });

  rows_ncalls = neighbor->ncalls;
  rows_nall = nall;
  rows_inum = inum;
  rows_nthreads = nthreads;
  rows_acc = nall ? acc[0] : nullptr;
  rows_f = nall ? f[0] : nullptr;
  rows_catom = (nall && atom_contact) ? atom_contact[0] : nullptr;
}

/* ----------------------------------------------------------------------
   run(thread) for every thread's chunk, in parallel; after all are done,
   fold(atom, private row) for the private rows of thread 0, 1, ... in turn
   (the atoms of one thread's rows are distinct: split over the team)
------------------------------------------------------------------------- */

template <class Run, class Fold> void PairESPHSolidOMP::threaded_rows(Run &&run, Fold &&fold)
{
#pragma omp parallel num_threads(nthreads)
  {
    const int team = ESPH::team_size();
    for (int tid = ESPH::thread_id(); tid < nthreads; tid += team) run(thr[tid]);

      // every thread's loop is done before any private row is read
#pragma omp barrier
    for (int s = 0; s < nthreads; s++) {
      const Thread &src = thr[s];
      const int n = (int) src.foreign.size();
#pragma omp for schedule(static)
      for (int e = 0; e < n; e++) fold(src.foreign[e], src.priv.data() + (size_t) e * PRIV_STRIDE);
    }
  }
}

/* ----------------------------------------------------------------------
   the pair loop in threads, then the private rows folded into the arrays
   (in thread order) and the tallies summed (in thread order)
------------------------------------------------------------------------- */

void PairESPHSolidOMP::pair_pass(int bnd)
{
  if (nthreads < 2) {
    PairESPHSolid::pair_pass(bnd);
    return;
  }
  if (rows_stale()) build_rows();

  const int ncol = nreverse;
  const int cflag = atom_contact_flag;
  const double *rmass = state->rmass;
  double **f = atom->f;
  for (auto &t : thr)
    for (auto &kv : t.tally) kv.second = {0.0, 0.0, 0.0};

  threaded_rows(
      [&](Thread &t) {
        const int nf = (int) t.foreign.size();
        for (int e = 0; e < nf; e++) {
          double *r = t.priv.data() + (size_t) e * PRIV_STRIDE;
          memset(r, 0, sizeof(double) * ncol);
          memset(r + PRIV_F, 0, sizeof(double) * (cflag ? 5 : 3));
        }
        LoopOut out{t.from, t.to, t.acc_rows.data(), t.f_rows.data(), t.c_rows.data(), &t.tally, 0,
                    0,      0.0};
        t.fric.clear();
        out.fric = &t.fric;
        run_pair_loop(bnd, out);
        // the thread's own particles' bulk pairs: their rows only
        if (simd_active) bulk_pass(out);
        t.ncontact = out.ncontact;
        t.ntouch = out.ntouch;
        t.fcontact = out.fcontact;
        t.dtcross = out.dtcross;
      },
      [&](int k, const double *r) {
        combine_acc_row(acc[k], r, 0, ncol, rmass[k] == 0.0);
        f[k][0] += r[PRIV_F];
        f[k][1] += r[PRIV_F + 1];
        f[k][2] += r[PRIV_F + 2];
        if (cflag) {
          atom_contact[k][0] += r[PRIV_C];
          atom_contact[k][1] += r[PRIV_C + 1];
        }
      });

  ncontact_pairs = ntouch_pairs = 0;
  fcontact = 0.0;
  for (auto &kv : body_tally) kv.second.fill(0.0);
  fric_pairs.clear();
  for (const auto &t : thr) {
    fric_pairs.insert(fric_pairs.end(), t.fric.begin(), t.fric.end());
    ncontact_pairs += t.ncontact;
    ntouch_pairs += t.ntouch;
    fcontact += t.fcontact;
    dt_cfl = std::min(dt_cfl, t.dtcross);
    for (const auto &kv : t.tally) {
      auto &b = tally_bodies(body_tally, kv.first.first, kv.first.second);
      for (int k = 0; k < NTALLY; k++) b[k] += kv.second[k];
    }
  }
}

/* ----------------------------------------------------------------------
   the correction sums of gradient bonet/lok (the 9 components of M of the
   real particles) in threads, on the rows of the pair loop: the same chunks,
   private rows folded in thread order
------------------------------------------------------------------------- */

void PairESPHSolidOMP::correction_pass()
{
  if (nthreads < 2) {
    PairESPHSolid::correction_pass();
    return;
  }
  if (rows_stale()) build_rows();

  threaded_rows(
      [&](Thread &t) {
        const int nf = (int) t.foreign.size();
        for (int e = 0; e < nf; e++)
          memset(t.priv.data() + (size_t) e * PRIV_STRIDE + A_M, 0, sizeof(double) * 9);
        run_correction_loop(t.from, t.to, t.acc_rows.data());
      },
      [&](int k, const double *r) {
        for (int c = A_M; c < A_M + 9; c++) acc[k][c] += r[c];
      });
}

/* ---------------------------------------------------------------------- */

double PairESPHSolidOMP::memory_usage()
{
  double bytes = PairESPHSolid::memory_usage();
  for (const auto &t : thr) {
    bytes += (double) (t.acc_rows.capacity() + t.f_rows.capacity() + t.c_rows.capacity()) *
        sizeof(double *);
    bytes += (double) t.foreign.capacity() * sizeof(int);
    bytes += (double) t.priv.capacity() * sizeof(double);
  }
  return bytes;
}
