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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(esph/solid/omp,PairESPHSolidOMP);
// clang-format on
#else

#ifndef LMP_PAIR_ESPH_SOLID_OMP_H
#define LMP_PAIR_ESPH_SOLID_OMP_H

#include "pair_esph_solid.h"

#include <vector>

namespace LAMMPS_NS {

class PairESPHSolidOMP : public PairESPHSolid {
 public:
  PairESPHSolidOMP(class LAMMPS *);
  void init_style() override;
  double memory_usage() override;

 protected:
  void pair_pass(int) override;
  void correction_pass() override;

 private:
  // a thread's private row: its sums of acc (NACC), atom->f (3) and atom_contact (2)
  static constexpr int PRIV_F = NACC, PRIV_C = NACC + 3, PRIV_STRIDE = NACC + 5;
  // cost of a pair of two real particles against one with a boundary particle (the
  // chunks are balanced with it; measured on the 3D rods at 0.1 mm: with 1 the first
  // thread waits 10 % of the loop time at the fold, with 3 it waits 4.5 %)
  static constexpr int REAL_PAIR_COST = 3;
  struct Thread {
    int from, to;    // its chunk of the neighbour list
    // per atom the row the thread adds to: the array's own row for the atoms of its chunk
    // of the neighbour list, a private row for the others it reaches (nullptr: none)
    std::vector<double *> acc_rows, f_rows, c_rows;
    std::vector<int> foreign;    // the atoms of the private rows, in row order
    std::vector<double> priv;    // private rows, PRIV_STRIDE each
    BodyTally tally;
    std::vector<FricPair> fric;    // its cross-body pairs with friction (friction_pass())
    int ncontact, ntouch;
    double fcontact, dtcross;
  };
  std::vector<Thread> thr;
  // what the rows were built for: neighbour list build, atom counts, array addresses
  bigint rows_ncalls;
  int rows_nall, rows_inum, rows_nthreads;
  const double *rows_acc, *rows_f, *rows_catom;
  bool rows_stale() const;
  void build_rows();
  template <class Run, class Fold> void threaded_rows(Run &&, Fold &&);
};

}    // namespace LAMMPS_NS

#endif
#endif
