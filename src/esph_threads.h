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

/* ----------------------------------------------------------------------
   threads of the ESPH per-atom passes: [0, n) in contiguous chunks, one per
   thread, as LAMMPS's OPENMP styles split their loops (loop_setup_thr);
   one thread (the serial styles): the pass itself, no OpenMP involved
------------------------------------------------------------------------- */

#ifndef LMP_ESPH_THREADS_H
#define LMP_ESPH_THREADS_H

#if defined(_OPENMP)
#include <omp.h>
#endif

namespace ESPH {

/* the calling thread and the size of its team (0 and 1 outside OpenMP) */

inline int thread_id()
{
#if defined(_OPENMP)
  return omp_get_thread_num();
#else
  return 0;
#endif
}

inline int team_size()
{
#if defined(_OPENMP)
  return omp_get_num_threads();
#else
  return 1;
#endif
}

/* chunk tid of [0, n) split into nthreads contiguous chunks */

inline void thread_chunk(int n, int nthreads, int tid, int &from, int &to)
{
  const int delta = 1 + n / nthreads;
  from = tid * delta;
  to = from + delta;
  if (from > n) from = n;
  if (to > n) to = n;
}

/* fn(from, to, tid) for every chunk tid: in parallel with nthreads > 1 (a team smaller
   than asked for takes the chunks in turn, so that every chunk is done once) */

template <class F> void for_chunks(int nthreads, int n, F &&fn)
{
#if defined(_OPENMP)
  if (nthreads > 1) {
    // the threads share a copy: the caller's closure does not escape, so that in the
    // serial call below its captures can stay in registers
    const auto shared = fn;
#pragma omp parallel num_threads(nthreads)
    {
      const int team = team_size();
      for (int tid = thread_id(); tid < nthreads; tid += team) {
        int from, to;
        thread_chunk(n, nthreads, tid, from, to);
        shared(from, to, tid);
      }
    }
    return;
  }
#endif
  fn(0, n, 0);
}

}    // namespace ESPH

#endif
