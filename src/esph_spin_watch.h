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

// The angular momentum of bodies in free flight, watched (fix esph/integrate). Under
// pair_style esph/solid gradient corrected (the default) or plain the stress forces of a
// body are not torque-free where its kernel support is cut: a tumbling body's angular
// momentum drifts, and a small one (5-6 particles across) spins up without bound, its
// internal energy running negative (a 5^3 cube: omega x100 in 3000 steps). gradient
// torquefree and bonet/lok conserve it. Every SAMPLE steps the bodies integrated by the
// fix give their angular momentum about their centre of mass (one reduction of 16 values
// per body); a body that touched no other body since the previous sample is free, and a
// change of its angular momentum over free intervals beyond TOL of its scale is warned
// once per body, with the remedy. Not run where it cannot judge: without a contact rule,
// or with another fix that may exert torques (fix esph/integrate's other_torques(): one that
// adds forces, fix enforce2d excepted, or one that sets velocities: momentum, thermostats);
// nor for a body over more than half of a periodic box (esph_bodies.h: body_reference()).

#ifndef LMP_ESPH_SPIN_WATCH_H
#define LMP_ESPH_SPIN_WATCH_H

#include "lmptype.h"

#include <set>
#include <vector>

namespace LAMMPS_NS {
class LAMMPS;
class ESPHState;

class ESPHSpinWatch {
 public:
  static constexpr int SAMPLE = 100;     // steps between samples
  static constexpr double TOL = 0.05;    // relative change of the angular momentum warned

  // start of a run: the bodies of the real particles in groupbit (collective)
  void setup(LAMMPS *lmp, ESPHState *state, int groupbit);
  // the bodies of a pair in contact in this step
  void touched(int a, int b)
  {
    hit.insert(a);
    hit.insert(b);
  }
  // every step (collective every SAMPLE steps); the id of the fix for the message
  void step(LAMMPS *lmp, ESPHState *state, int groupbit, bigint ntimestep, const char *fixid);

 private:
  struct Ref {
    bool valid = false;
    double L[3] = {0.0, 0.0, 0.0};    // angular momentum at the start of the free flight
    double scale = 0.0;               // its scale (see step())
    bigint since = 0;                 // step of that sample
  };
  std::vector<int> bodies;       // sorted body IDs watched
  std::vector<double> points;    // a point of each, for the sums (esph_bodies.h)
  std::vector<Ref> refs;
  std::set<int> hit;       // bodies in contact since the last sample
  std::set<int> warned;    // bodies warned about in this run
};

}    // namespace LAMMPS_NS

#endif
