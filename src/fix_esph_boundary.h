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

#ifdef FIX_CLASS
// clang-format off
FixStyle(esph/boundary,FixESPHBoundary);
// clang-format on
#else

#ifndef LMP_FIX_ESPH_BOUNDARY_H
#define LMP_FIX_ESPH_BOUNDARY_H

#include "fix.h"

#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace LAMMPS_NS {

class FixESPHBoundary : public Fix {
 public:
  FixESPHBoundary(class LAMMPS *, int, char **);
  ~FixESPHBoundary() override;
  void post_constructor() override;
  void set_arrays(int) override;
  int setmask() override;
  void init() override;
  double compute_scalar() override;
  // the particle spacing the boundary particles were placed for
  double get_spacing() const { return spacing; }
  // the boundary normals turn with the rigid spin of their body (turn body), not with the
  // spin interpolated from the real particles around them (turn spin, eq. 17)
  int turns_with_body() const { return turn_body; }
  // the last generation found the bodies on another lattice than simple cubic (square)
  int off_lattice() const { return noncubic_found; }

 protected:
  int noncubic_found;
  double spacing;    // particle spacing of the bodies
  double smooth;     // smoothing length of the normal kernel, in spacings
  double fit;        // radius of the surface fit of the normals, in spacings (0: off)
  int btype;         // type of generated boundary particles (0: type of the source particle)
  int mode;          // GENERATE or GIVEN
  int turn_body;     // 1: normals turn with their body's rigid spin (turn body)
  bigint ncreated;
  class ESPHState *state;
  // real particles per body the boundary particles were generated (or found) for
  std::map<int, bigint> made_for;
  // the boundary particles per body when the fix was defined (made or found)
  std::map<int, bigint> bnd_for;
  bigint reused;    // boundary particles found at the definition and used (none made)
  // regions whose surfaces give the normals of the boundary particles of their bodies
  std::vector<std::string> region_ids;

  void generate();
  void find_surface(std::vector<double> &, std::vector<double> &, std::vector<int> &);
  void check_pieces(std::unordered_map<tagint, tagint> &, const double *, const double *, double);
  void check_counts();
  void fit_normals(const std::vector<double> &, std::vector<double> &, const std::vector<int> &);
  void region_normals(const std::vector<double> &, std::vector<double> &, const std::vector<int> &);
  std::vector<double> halo_exchange(const std::vector<double> &, int, const double *,
                                    const double *, double);
};

}    // namespace LAMMPS_NS

#endif
#endif
