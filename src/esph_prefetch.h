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
   software prefetch for the per-atom passes. A pass over the atoms reads
   and writes rows of a dozen per-atom arrays at once; with that many
   streams the hardware prefetcher falls behind and each row's first
   touch waits for memory (measured: a third of finalize()'s samples sat
   on the load of one row of the predicted state). The passes ask for the
   rows of the atom PREFETCH_AHEAD places ahead while they work on this
   one. A hint: nothing changes but the time, and an address past an
   array's end is never dereferenced (the callers stay within [from, to))
------------------------------------------------------------------------- */

#ifndef LMP_ESPH_PREFETCH_H
#define LMP_ESPH_PREFETCH_H

namespace ESPH {

static constexpr int PREFETCH_AHEAD = 6;

/* the cache lines of row[0 .. n) on their way into the cache, to be read */

inline void prefetch_read(const double *row, int n)
{
  for (int k = 0; k < n; k += 8) __builtin_prefetch(row + k, 0);
  __builtin_prefetch(row + n - 1, 0);
}

/* the same for a row that will be written */

inline void prefetch_write(double *row, int n)
{
  for (int k = 0; k < n; k += 8) __builtin_prefetch(row + k, 1);
  __builtin_prefetch(row + n - 1, 1);
}

}    // namespace ESPH

#endif
