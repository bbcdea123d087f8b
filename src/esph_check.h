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

// Start-of-run checks of the ESPH input: the per-atom state every real and boundary
// particle starts a run with, the particle arrangement seen through the neighbour
// list (coincident particles, particles off the line or plane of a lower kernel
// dimension), bodies without boundary particles under a contact rule, other
// time-integrating fixes, and the measured particle spacing against fix
// esph/boundary's. Each check is one pass at setup or init, nothing per step.
// Per-atom failures are reported collectively for the atom with the smallest ID, so
// the message is the same on any number of ranks.

#ifndef LMP_ESPH_CHECK_H
#define LMP_ESPH_CHECK_H

#include "lmptype.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace ESPH {
struct EOS;
struct Units;
}    // namespace ESPH

namespace LAMMPS_NS {
class LAMMPS;
class ESPHState;
class Fix;
class NeighList;

namespace ESPHCheck {

  // collective: every rank passes the ID of its first offending atom (0: none) and
  // its message; if any rank has one, all ranks stop with the message of the
  // smallest atom ID
  void first_error(LAMMPS *lmp, tagint tag, const std::string &msg);

  // collective: true if pred(i) holds for a local atom i on any rank
  bool any_atom(LAMMPS *lmp, const std::function<bool(int)> &pred);

  // union over all ranks of the values in v (sorted, unique)
  std::vector<int> global_set(LAMMPS *lmp, std::vector<int> v);
  std::vector<long long> global_set(LAMMPS *lmp, std::vector<long long> v);

  // number of real (mass > 0) particles per body among the atoms in groupbit, all ranks;
  // with boundary, of the boundary (zero-mass) particles
  std::map<int, bigint> body_counts(LAMMPS *lmp, ESPHState *state, int groupbit,
                                    bool boundary = false);
  // the shape of each body with real particles in groupbit, but those over more than half a
  // periodic box (ESPH::body_reference()): its mass and the eigenvalues of its second moment
  // about the centre of mass, ascending (SHAPE_NVAL values a body); bodies sorted (collective)
  static constexpr int SHAPE_NVAL = 4;
  void body_shapes(LAMMPS *lmp, ESPHState *state, int groupbit, std::vector<int> &bodies,
                   std::vector<double> &shape);
  // WARNING if a body of the same mass has another shape than at the end of the last run
  // (bodies_then, shape_then from body_shapes()): its positions were changed without its
  // state (change_box ... remap, displace_atoms ramp, set x). Rotations and translations
  // keep the shape; collective
  void check_shapes(LAMMPS *lmp, ESPHState *state, int groupbit,
                    const std::vector<int> &bodies_then, const std::vector<double> &shape_then);

  // a hint for an error on zero masses where the mass command set per-type masses ("" if
  // none was set)
  std::string type_mass_hint(LAMMPS *lmp);

  // "1: 64, 2: 64" (the first few bodies)
  std::string format_bodies(const std::map<int, bigint> &counts);

  // per-atom state at the start of a run: real particles need finite x, v, e and
  // stress, density and h > 0 and finite, and a positive sound speed from their EOS;
  // boundary particles finite x and v and a unit normal; hlimit: the largest h the
  // cutoff allows; units: of the pair style (the EOS works in internal units)
  void state(LAMMPS *lmp, ESPHState *state, const ESPH::EOS *eos, double hlimit,
             const ESPH::Units &units);

  // pass over the half neighbour list: coincident real particles (closer than
  // COINCIDENT x h0), and with a kernel dimension below the box dimension,
  // neighbouring real particles off the x axis (dimension 1) or the xy plane (2); with
  // the particle spacing of fix esph/boundary (> 0), a warning for real particles of
  // different bodies closer than OVERLAP x spacing (overlapping bodies)
  void pairs(LAMMPS *lmp, ESPHState *state, NeighList *list, double cutsq, double h0, int kdim,
             double spacing);

  // with a contact rule and more than one body: every body with real particles
  // needs boundary particles
  void contact_bodies(LAMMPS *lmp, ESPHState *state, const char *rule);

  // move yes: no other fix may integrate the motion of atoms of fix esph/integrate;
  // move no: some other fix should (a warning otherwise)
  void integrators(LAMMPS *lmp, Fix *fix_int, int move);

  // rigid types (pair_coeff ... rigid yes): their real particles must be outside the
  // group of fix esph/integrate (another fix or nothing moves them), and no body may
  // mix rigid and deformable real particles
  void rigid_bodies(LAMMPS *lmp, ESPHState *state, Fix *fix_int, const int *rigid);

  // deformable real particles (types without rigid yes) outside the group of fix
  // esph/integrate: nothing updates their density, stress and energy (said in the log);
  // those and rigid ones with a velocity that no fix applies (a warning each)
  void unintegrated(LAMMPS *lmp, ESPHState *state, Fix *fix_int, const int *rigid);

  // a fix that changes positions or velocities of real particles after fix esph/integrate
  // predicted the step (post_integrate, e.g. fix wall/reflect): warned, naming it
  void after_prediction(LAMMPS *lmp, ESPHState *state, Fix *fix_int);

  // median distance from each real particle of the group to its nearest real
  // neighbour of the same body, in units of spacing (capped at MAX_RATIO); -1 if the
  // group has no real particles, ISOLATED if most have no neighbour within MAX_RATIO
  double spacing_ratio(LAMMPS *lmp, ESPHState *state, int groupbit, double spacing);

  // warnings at the start of a run: real particles whose density is far from the rho0 of
  // their type (outside [1/DENSITY_OFF, DENSITY_OFF] x rho0: pair_coeff rho0 changed between
  // runs), and, with spacing > 0 (fix esph/boundary), whose reference volume m / rho0 is
  // not spacing^dim (outside [1/VOLUME_OFF, VOLUME_OFF]: a mass in the wrong unit, or
  // another material's: the stiffness scales with the mass, and the CFL step does not see it)
  void volumes(LAMMPS *lmp, ESPHState *state, const ESPH::EOS *eos,
               const std::function<double(int)> &spacing_of, int dim);

  // the smoothing length h0 of pair esph/solid and, with hvar, the largest h0 x hmax the
  // neighbour cutoff admits, against the particle spacing of fix esph/boundary (> 0): an
  // error beyond H_ERROR spacings (every particle would see thousands of neighbours, or
  // the cutoff spans the box), a warning for h0 beyond H_WARN spacings (1 to 2 is usual);
  // an error at or below H_NONE spacings (no neighbours), a warning below H_LOW
  void smoothing_length(LAMMPS *lmp, double h0, double hmax, int hvar_flag, double spacing);

  static constexpr double DENSITY_OFF = 1.5;
  static constexpr double VOLUME_OFF = 1.1;
  static constexpr double COINCIDENT = 1.0e-6;       // in units of h0
  static constexpr double OFF_DIMENSION = 1.0e-6;    // in units of h0
  // touching bodies are a spacing apart, bodies that overlap by half a spacing or more
  // have particles within 0.5 spacings (a lattice) or closer
  static constexpr double OVERLAP = 0.6;    // in units of the particle spacing
  static constexpr double MAX_RATIO = 3.0;
  static constexpr double ISOLATED = -2.0;
  static constexpr double H_NONE = 0.5;      // 2 h below one spacing: no neighbours (error)
  static constexpr double H_LOW = 0.95;      // below: a warning (1 to 2 is usual)
  static constexpr double H_WARN = 3.0;      // in units of the particle spacing
  static constexpr double H_ERROR = 10.0;    // in units of the particle spacing
}    // namespace ESPHCheck

}    // namespace LAMMPS_NS

#endif
