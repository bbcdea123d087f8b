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

#ifdef COMPUTE_CLASS
// clang-format off
ComputeStyle(esph/atom,ComputeESPHAtom);
// clang-format on
#else

#ifndef LMP_COMPUTE_ESPH_ATOM_H
#define LMP_COMPUTE_ESPH_ATOM_H

#include "compute.h"

#include <vector>

namespace LAMMPS_NS {

class ComputeESPHAtom : public Compute {
 public:
  ComputeESPHAtom(class LAMMPS *, int, char **);
  ~ComputeESPHAtom() override;
  void init() override;
  void compute_peratom() override;
  double memory_usage() override;

  // the quantities, in the order of the default column set
  enum Value {
    PRESSURE,
    VONMISES,
    SXX,
    SYY,
    SZZ,
    SXY,
    SXZ,
    SYZ,
    STRAIN_VOL,
    SPEED_SOUND,
    STRAIN_PLASTIC,
    CONTACT,
    CONTACT_FORCE,
    NVALUES
  };

 private:
  std::vector<int> values;    // Value of each output column
  int contact_flag;           // some column needs the pair style's per-atom contact sums
  int nmax;
  double *vec;
  double **arr;
  class PairESPHSolid *pair;
  class ESPHState *state;
};

}    // namespace LAMMPS_NS

#endif
#endif
