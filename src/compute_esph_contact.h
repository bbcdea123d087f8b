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
ComputeStyle(esph/contact,ComputeESPHContact);
// clang-format on
#else

#ifndef LMP_COMPUTE_ESPH_CONTACT_H
#define LMP_COMPUTE_ESPH_CONTACT_H

#include "compute.h"

namespace LAMMPS_NS {

class ComputeESPHContact : public Compute {
 public:
  ComputeESPHContact(class LAMMPS *, int, char **);
  ~ComputeESPHContact() override;
  void init() override;
  void compute_array() override;
  double compute_scalar() override;
  int lock_length() override;

  static constexpr int NCOLS = 17;

 private:
  class FixESPHIntegrate *fix_int;
  int nrows_alloc;
};

}    // namespace LAMMPS_NS

#endif
#endif
