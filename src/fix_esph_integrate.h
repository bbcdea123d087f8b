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
FixStyle(esph/integrate,FixESPHIntegrate);
// clang-format on
#else

#ifndef LMP_FIX_ESPH_INTEGRATE_H
#define LMP_FIX_ESPH_INTEGRATE_H

#include "fix.h"

#include "esph_contact.h"
#include "esph_spin_watch.h"

#include <array>
#include <unordered_map>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class FixESPHIntegrate : public Fix {
 public:
  FixESPHIntegrate(class LAMMPS *, int, char **);
  ~FixESPHIntegrate() override;
  void post_constructor() override;
  int setmask() override;
  void init() override;
  void setup(int) override;
  void initial_integrate(int) override;
  void final_integrate() override;
  void end_of_step() override;
  void post_run() override;
  void reset_dt() override;
  double compute_vector(int) override;
  void write_restart(FILE *) override;
  void restart(char *) override;
  void grow_arrays(int) override;
  void copy_arrays(int, int, int) override;
  void set_arrays(int) override;
  int pack_exchange(int, double *) override;
  int unpack_exchange(int, double *) override;
  int pack_restart(int, double *) override;
  void unpack_restart(int, int) override;
  int size_restart(int) override;
  int maxsize_restart() override;
  double memory_usage() override;

  // what the last force computation was (havepred) and what resume_check() found: nothing to
  // continue, the computation of a completed step, or the setup computation of a run
  // without steps (run 0), re-evaluated from the state as is
  enum { RESUME_NONE = 0, RESUME_STEP = 1, RESUME_SETUP = 2 };
  // the state this run continues (RESUME_NONE: it starts afresh; see resume_check())
  int resume_check();
  bool moves_boundary(int i) const;
  // the specific internal energy (energy/mass units) real particle i has at the end of the
  // step of this force computation, given the rate de_i it just computed: what
  // final_integrate() will make of it inside a step, the state as is outside one (the
  // energy the pair style tallies, thermo pe)
  double end_energy(int i, double dei) const;

  // per atom, migrating with the atoms (exchange, sorting) and in restart files:
  // the predicted end-of-step state, made in initial_integrate and read by the pair during
  // the force computation; at the end of a run (and in restart files) the real-particle
  // normal, surface gap, gap rate and engagement that the last force computation used
  // (P_USED .. P_USED + 5), the fingerprint of the atom's state but its position (P_HASH),
  // the predicted switched viscosity coefficient (P_ALPHA, 0 without visc/switch), the
  // position the fingerprint belongs to (P_X .. P_X + 2, wrapped as the fingerprint), and
  // the rates of the force computation before the last one that the extrapolated
  // prediction needs (P_PREV .. P_PREV + NRATES - 1: force, drho, de, dh, dS, dalpha) with
  // a flag that they belong to this atom's trajectory (P_PREVOK)
  static constexpr int P_RHO = 0, P_E = 1, P_H = 2, P_S = 3, P_V = 9, P_DIVV = 12, P_USED = 13,
                       P_HASH = 19, P_ALPHA = 20, P_X = 21, P_PREV = 24, NRATES = 13, P_PREVOK = 37,
                       NPRED = 38;
  // extrapolated prediction: the rates of the predicted half step are
  // r^n + (EXTRAP_A - 1) (dt^n / dt^(n-1)) (r^n - r^(n-1)); 4/3 cancels the leading
  // (omega dt)^4 amplitude error of the predictor-corrector on an undamped mode
  static constexpr double EXTRAP_A = 4.0 / 3.0;
  double **pred;
  int move;        // 0: only the SPH state is integrated, motion comes from another fix
  int stepping;    // between initial_integrate() and final_integrate() of a step
  // the bodies whose boundary particles another fix moves or leaves at rest (sorted, the
  // same on every rank; check_boundary_motion())
  std::vector<int> moved_bodies;
  void check_boundary_motion();
  // scheme staggered: the force computation of a step first finds the rates at v^(n+1/2),
  // then (stagger_commit()) the state is advanced to n+1, then the forces are computed
  int staggered;
  int extrapolate;        // the prediction extrapolates the rates of the last two computations
  int extrapolate_set;    // the extrapolate keyword was given
  int extrap_on;          // extrapolate in this run (not with the paper's contact rule)

  // contact history per pair of bodies (I < J) that have touched, the same on every rank,
  // sorted by bodies (compute esph/contact)
  std::vector<std::pair<int, int>> body_pairs;
  std::vector<ESPH::ContactRecord> body_records;

 protected:
  double dtv, dtf, dth;
  double cfl;                         // CFL safety factor, 0 = fixed time step
  double dtmin, dtmax;                // bounds of the adaptive step
  ESPH::ContactRecord contact_all;    // contact history of all bodies together
  void update_body_pairs(double t, int setup = 0);
  ESPHSpinWatch spin_watch;        // angular momentum of free bodies (gradient corrected, plain)
  int spin_watch_on;               // watched in this run
  ESPHEnergyWatch energy_watch;    // internal energy of every body (every run)
  void contact_tallies(double *total);
  int havepred;        // RESUME_STEP: pred holds the prediction of a completed step;
                       // RESUME_SETUP: the last force computation was the setup of a run 0
  bigint fp_natoms;    // number of atoms when the fingerprints were stored
  bigint fp_step;      // step at which they were stored
  int time_pending;    // read_restart: restore the elapsed time at the next init
  double time_file;    // elapsed time and step when the restart file was written
  bigint step_file;
  double dt_used;         // time step of the last force computation, saved at post_run
  double time_run_end;    // the time at the end of the last run (-1: none in this process)
  // the simulation time now (as thermo's time keyword counts it)
  double elapsed() const;
  // a continued run: the normals, after the end-of-step turn, of the boundary particles
  // another fix moves (the setup's re-evaluation sees them as the last computation did)
  std::vector<double> turned_n;
  bool turns_at_end(int i) const;
  double dt_prev;    // time step between the rates stored in P_PREV and the last ones
  int nthreads;      // threads of the per-atom passes (1; esph/integrate/omp: package omp)
  class PairESPHSolid *pair;
  class ESPHState *state;

  void adapt_dt();
  void initial_integrate_staggered();
  void stagger_commit();
  void set_pred_from_state(int);
  void clear_pred(int);
  void advance_state(int, double, int);
  void rotate_normal(double *, const double *);
  void check_group();
  bool other_torques();
  void check_moved_velocities();
  int moved_warned;    // warned once
  // the bodies and their shapes at the end of the last run (ESPHCheck::body_shapes())
  std::vector<int> shape_bodies;
  std::vector<double> shape_then;
  bigint moved_step;                                               // step of moved_then
  std::unordered_map<tagint, std::array<double, 6>> moved_then;    // x, v by atom ID
  void check_average_forces();
  void check_deform();
  void check_rebuilds();
  void check_fixed_dt();
  double cfl_estimate(const class PairESPHSolid *) const;
  double dt_warned;       // the fixed time step last warned about (check_fixed_dt())
  double dtmin_warned;    // the dtmin last warned about (adapt_dt())
  // the largest cfl factor (and fixed step, in CFL estimates) without a warning
  static constexpr double CFL_SAFE = 0.6;
  // share of the squared velocities of a body's boundary particles that their difference
  // from the interpolated ones may reach (check_boundary_motion())
  static constexpr double BND_MOTION_SHARE = 0.25;
  static constexpr int FIXED_DT_CHECK = 100;    // steps between checks of a fixed step
  double fingerprint(int);
  void wrapped_position(int, double *);
  bool same_position(int, const double *);
  void save_normal_used(int, double *);
};

}    // namespace LAMMPS_NS

#endif
#endif
