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

// The internal energy of every body, watched (fix esph/integrate, every run, any scene). A
// body's internal energy is its elastic energy and its heat, never below zero (or below
// where it started, if a user set it lower): one that falls below by TOL of the body's
// energy (the largest kinetic plus internal energy it had, at least 1e-6 of all bodies'
// together) is being given energy by forces that create it, an instability. Found: a copper
// block 3 particles across resting on a plate under gravity (gradient corrected, where the
// spin watch above does not look: gravity exerts torques, and the body is in contact) rose
// off the plate after 8000 steps, its internal energy at -3 times the scene's energy, total
// energy +87 %, without a message. Every SAMPLE steps one reduction of 2 values per body;
// warned once per body and run, with the remedies.
class ESPHEnergyWatch {
 public:
  static constexpr int SAMPLE = 100;
  static constexpr double TOL = 0.05;

  void setup(LAMMPS *lmp, ESPHState *state, int groupbit);
  void step(LAMMPS *lmp, ESPHState *state, int groupbit, bigint ntimestep, const char *fixid);

 private:
  // per body (sorted IDs) the kinetic and internal energy of its real particles in groupbit
  void sums(LAMMPS *lmp, ESPHState *state, int groupbit, std::vector<double> &out) const;
  std::vector<int> bodies;
  std::vector<double> floor_;    // the lowest internal energy allowed: min(0, start)
  std::vector<double> scale;     // the largest kinetic + |internal| energy seen
  std::set<int> warned;
};

}    // namespace LAMMPS_NS

#endif
