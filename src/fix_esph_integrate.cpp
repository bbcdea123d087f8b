/* ----------------------------------------------------------------------
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
   Time integration of the ESPH state: velocity Verlet for x and v (the
   seed paper's leapfrog, eqs. 28-29, with variable step), trapezoidal
   half steps for density, energy, deviatoric stress and h (eqs. 25-27),
   and an optional CFL time step.
------------------------------------------------------------------------- */

#include "fix_esph_integrate.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_bodies.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_prefetch.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "esph_threads.h"
#include "fix_deform.h"
#include "force.h"
#include "group.h"
#include "input.h"
#include "memory.h"
#include "modify.h"
#include "neighbor.h"
#include "output.h"
#include "pair_esph_solid.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// the switched viscosity coefficient over a half step, kept within [amin, amax]
static inline double advance_alpha(double a, double rate, double dt, double amin, double amax)
{
  return MIN(MAX(a + dt * rate, amin), amax);
}

/* ---------------------------------------------------------------------- */

FixESPHIntegrate::FixESPHIntegrate(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), pred(nullptr), nthreads(1), pair(nullptr), state(nullptr)
{
  stepping = 0;
  time_integrate = 1;
  restart_global = 1;
  restart_peratom = 1;
  create_attribute = 1;
  vector_flag = 1;
  size_vector = 8;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector]{1, 0, 0, 0, 0, 0, 0, 0};    // internal energy is extensive

  cfl = 0.0;
  move = 1;
  havepred = RESUME_NONE;
  fp_natoms = -1;
  fp_step = -1;
  time_pending = 0;
  time_file = 0.0;
  step_file = -1;
  dt_used = 0.0;
  time_run_end = -1.0;
  dt_prev = 0.0;
  dt_warned = 0.0;
  dtmin_warned = 0.0;
  spin_watch_on = 0;
  moved_warned = 0;
  moved_step = -1;
  extrapolate = 1;
  extrapolate_set = 0;
  extrap_on = 0;
  dtmin = 0.0;
  dtmax = 0.0;
  staggered = 0;

  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "cfl") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate cfl", error);
      cfl = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (cfl <= 0.0 || cfl > 1.0)
        error->all(FLERR, iarg + 1, "Fix esph/integrate cfl factor must be in (0,1], got {}",
                   arg[iarg + 1]);
      if (cfl > CFL_SAFE && comm->me == 0)
        error->warning(FLERR,
                       "Fix esph/integrate cfl {} is above {}: the integration gains energy, "
                       "the faster the larger the step (two iron blocks at 50 m/s, 2000 steps: "
                       "+0.14 % at 0.5, +0.45 % at 0.6, nine-fold at 0.7, lost atoms at 1.0); "
                       "use 0.3 (the examples') or less",
                       arg[iarg + 1], CFL_SAFE);
      iarg += 2;
    } else if (strcmp(arg[iarg], "dtmax") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate dtmax", error);
      dtmax = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (dtmax <= 0.0)
        error->all(FLERR, iarg + 1, "Fix esph/integrate dtmax must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "move") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate move", error);
      move = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else if (strcmp(arg[iarg], "scheme") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate scheme", error);
      if (strcmp(arg[iarg + 1], "predicted") == 0)
        staggered = 0;
      else if (strcmp(arg[iarg + 1], "staggered") == 0)
        staggered = 1;
      else
        error->all(FLERR, iarg + 1,
                   "Fix esph/integrate scheme must be predicted or staggered, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "extrapolate") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate extrapolate", error);
      extrapolate = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      extrapolate_set = 1;
      iarg += 2;
    } else if (strcmp(arg[iarg], "dtmin") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate dtmin", error);
      dtmin = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (dtmin <= 0.0)
        error->all(FLERR, iarg + 1, "Fix esph/integrate dtmin must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, iarg,
                 "Unknown fix esph/integrate keyword: {} (expected cfl, dtmin, dtmax, move, "
                 "scheme or extrapolate)",
                 arg[iarg]);
    }
  }
  if (dtmax > 0.0 && dtmin > dtmax)
    error->all(FLERR, "Fix esph/integrate dtmin {} is larger than dtmax {}", dtmin, dtmax);
  if (staggered && !move)
    error->all(FLERR,
               "Fix esph/integrate scheme staggered needs move yes (its rate pass falls between "
               "the kick and the drift of the step)");
  if (staggered && extrapolate_set && extrapolate && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate extrapolate yes has no effect with scheme staggered "
                   "(its rates are those of the step itself): leave it out");
  if (cfl == 0.0 && (dtmin > 0.0 || dtmax > 0.0))
    error->all(FLERR, "Fix esph/integrate dtmin/dtmax need the cfl keyword");
  // with move no another fix (e.g. fix move) integrates the motion
  time_integrate = move;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
  atom->add_callback(Atom::RESTART);
  for (int i = 0; i < atom->nlocal; i++) clear_pred(i);
}

/* ----------------------------------------------------------------------
   the state fixes are created here, not in the constructor: Modify is still
   adding this fix while its constructor runs, and a fix added from there
   would take its slot
------------------------------------------------------------------------- */

void FixESPHIntegrate::post_constructor()
{
  state = new ESPHState(lmp);
}

/* ---------------------------------------------------------------------- */

FixESPHIntegrate::~FixESPHIntegrate()
{
  atom->delete_callback(id, Atom::GROW);
  atom->delete_callback(id, Atom::RESTART);
  memory->destroy(pred);
  delete state;
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::setmask()
{
  int mask = 0;
  mask |= INITIAL_INTEGRATE;
  mask |= FINAL_INTEGRATE;
  if (cfl > 0.0) mask |= END_OF_STEP;
  return mask;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::init()
{
  pair = dynamic_cast<PairESPHSolid *>(force->pair_match("^esph/solid", 0));
  if (!pair)
    error->all(FLERR, Error::NOLASTLINE, "Fix esph/integrate requires pair style esph/solid");
  // the paper's contact rule switches every cross-body pair on and off from one step to the
  // next (its approach criterion, eq. 31): rates extrapolated across such a switch overshoot,
  // and the overshoot feeds the next switch (the 3D rods gain energy without bound)
  const int paper = (pair->contact == ESPH::CONTACT_PAPER);
  extrap_on = extrapolate && !staggered && !paper;
  // rates stored by an earlier run do not belong to a later one that extrapolates again
  if (!extrap_on)
    for (int i = 0; i < atom->nlocal; i++) pred[i][P_PREVOK] = 0.0;
  if (extrapolate && extrapolate_set && !staggered && paper && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate extrapolate yes is not used with pair esph/solid contact "
                   "paper (the rule switches pairs on and off every step, and extrapolated rates "
                   "would pump energy): the prediction uses the last rates; leave the keyword "
                   "out or use contact solid");
  check_group();
  check_average_forces();
  check_deform();
  if (modify->get_fix_by_style("^esph/integrate").size() > 1)
    error->all(FLERR, Error::NOLASTLINE, "Only one fix esph/integrate may be defined");
  if (utils::strmatch(update->integrate_style, "^respa"))
    error->all(FLERR, Error::NOLASTLINE,
               "Fix esph/integrate does not support run_style {}: use run_style verlet",
               update->integrate_style);
  if (cfl > 0.0 && !modify->get_fix_by_style("^dt/reset").empty() && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate cfl and fix dt/reset both set the time step (fix "
                   "dt/reset wins): drop one of them");
  // a restart file written during a run with a fixed time step holds the elapsed time at
  // the start of that run, and Integrate::init() counts the time from the current step:
  // restore the time of the file's step, which this fix stored
  if (time_pending && update->ntimestep == step_file) {
    update->atime = time_file;
    update->atimestep = update->ntimestep;
  }
  time_pending = 0;
  // reset_timestep moves the time without steps: to 0 for an earlier step, forward by the
  // steps skipped for a later one, to T with its time keyword. The contact history keeps
  // the times of the old origin
  const double now = elapsed();
  double latest = std::max(contact_all.tfirst, contact_all.tlatest);
  for (const auto &r : body_records) latest = std::max(latest, std::max(r.tfirst, r.tlatest));
  const bool rerun = input->command && strcmp(input->command, "rerun") == 0;
  const double tol = 1.0e-12 * std::max(fabs(now), fabs(time_run_end)) + 1.0e-300;
  if (!rerun && latest >= 0.0 && comm->me == 0) {
    if (time_run_end >= 0.0 && fabs(now - time_run_end) > tol)
      error->warning(FLERR,
                     "Fix esph/integrate: the time went from {} at the end of the last run to "
                     "{} without a step (reset_timestep) while there is a contact history: its "
                     "first-touch and end times keep the old origin, so contact durations "
                     "across the reset are wrong: use reset_timestep before the bodies touch, "
                     "or keep the time with reset_timestep N time {}",
                     time_run_end, now, time_run_end);
    else if (latest > now * (1.0 + 1.0e-12) + 1.0e-300)
      error->warning(FLERR,
                     "Fix esph/integrate: the time ({}) is before the contact history's last "
                     "time ({}), reset by reset_timestep: the first-touch and end times keep "
                     "the old origin, so contact durations across the reset are wrong: use "
                     "reset_timestep before the bodies touch",
                     now, latest);
  }
  state->fetch();
  for (int t = 1; t <= atom->ntypes; t++)
    if (pair->yield[t] > 0.0 && !state->epsp)
      error->all(FLERR, Error::NOLASTLINE,
                 "Fix esph/integrate: atom type {} is plastic but the plastic-strain fix {} is "
                 "gone (it must not be deleted)",
                 t, ESPHState::FIX_ID_PLASTIC);
  reset_dt();
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::reset_dt()
{
  dtv = update->dt;
  dtf = 0.5 * update->dt * force->ftm2v;
  dth = 0.5 * update->dt;
}

/* ----------------------------------------------------------------------
   after the setup force computation: boundary particles take the velocity
   interpolated from their body; optionally pick the first CFL step
------------------------------------------------------------------------- */

void FixESPHIntegrate::setup(int /*vflag*/)
{
  // a continued run evaluated the setup forces at the prediction of the last step; force
  // computations outside a step (e.g. rerun) see the state as is
  pair->pred_valid = 0;
  stepping = 0;
  state->fetch();
  // bodies moved non-rigidly since the last run (not in a rerun, whose frames move them)
  const bool rerun = input->command && strcmp(input->command, "rerun") == 0;
  if (update->whichflag == 1 && !rerun)
    ESPHCheck::check_shapes(lmp, state, groupbit, shape_bodies, shape_then);
  shape_bodies.clear();
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // a continued run: the boundary particles another fix moves had turned at the end of the
  // last step, after its force computation; the setup's re-evaluation of it saw them as
  // it did (resume_check()), the next step sees them turned
  if (!turned_n.empty()) {
    for (int i = 0; i < nlocal; i++)
      if (turns_at_end(i))
        for (int d = 0; d < 3; d++) state->n[i][d] = turned_n[3 * i + d];
    turned_n.clear();
  }
  for (int i = 0; i < nlocal; i++)
    if (moves_boundary(i)) {
      // a run that starts afresh: the velocity its setup computation saw, for a next run that
      // re-evaluates that computation (after run 0, resume_check())
      if (havepred != RESUME_STEP)
        for (int d = 0; d < 3; d++) pred[i][P_V + d] = v[i][d];
      v[i][0] = pair->bvel[i][0];
      v[i][1] = pair->bvel[i][1];
      v[i][2] = pair->bvel[i][2];
    }
  // the contact force (vector element 8) is that of the last force computation, as the
  // pair counts (elements 2 and 7) are: the setup computation's, not the last step's of a
  // previous run (with another pair style or state); the contact history (elements 4 to 6,
  // compute esph/contact) is kept by the steps only
  if (pair->nboundary > 0) {
    double total[3];
    contact_tallies(total);
    contact_all.force = total[2];
    // the rows of the body pairs that touch now, with their forces (the start of the net
    // impulse's first step)
    update_body_pairs(0.0, 1);
  }
  if (cfl > 0.0)
    adapt_dt();
  else
    check_fixed_dt();
  check_rebuilds();

  // the angular momentum of free bodies, where the pair forces do not keep it and nothing
  // else may exert torques (esph_spin_watch.h)
  // (without boundary particles bodies are not told apart in contact: the watch then serves
  // a scene of one body; nboundary is a global count, so every rank asks alike)
  spin_watch_on = move && domain->dimension > 1 &&
      (pair->correct_flag == PairESPHSolid::CORRECT_PLAIN ||
       pair->correct_flag == PairESPHSolid::CORRECT_RATE) &&
      !other_torques() &&
      (pair->nboundary > 0 || ESPHCheck::body_counts(lmp, state, groupbit).size() == 1);
  if (spin_watch_on) spin_watch.setup(lmp, state, groupbit);
  energy_watch.setup(lmp, state, groupbit);
  // the bodies whose boundary particles this fix does not move (check_boundary_motion();
  // global_set() sorts and unites)
  std::vector<int> mine;
  for (int i = 0; i < nlocal; i++)
    if (turns_at_end(i) && state->body) mine.push_back(state->body[i]);
  moved_bodies = ESPHCheck::global_set(lmp, mine);
  // (positions may have been changed between runs: the motion check starts afresh)
  moved_step = -1;
  moved_then.clear();
}

/* ----------------------------------------------------------------------
   neigh_modify every N with check no rebuilds the lists every N steps
   (or at the first multiple of N after the delay) whatever the motion: a
   pair that closes by more than the skin between rebuilds comes within the
   cutoff unseen (two blocks closing at 200 m/s with every 200 check no
   touched at the rebuild, 0.005 us late, and ended 1.4 % off, silently;
   LAMMPS only says that dangerous builds were not checked). Warned at the
   start of a run from the spread of the real particles' velocities, the
   largest relative velocity at that time (collective)
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_rebuilds()
{
  if (neighbor->dist_check || (neighbor->every <= 1 && neighbor->delay <= 1)) return;
  int steps = neighbor->every;
  if (neighbor->delay > steps) steps = (neighbor->delay + steps - 1) / steps * steps;
  double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  double loall[3], hiall[3];
  double **v = atom->v;
  for (int i = 0; i < atom->nlocal; i++)
    if ((atom->mask[i] & groupbit) && state->rmass[i] > 0.0)
      for (int d = 0; d < 3; d++) {
        lo[d] = MIN(lo[d], v[i][d]);
        hi[d] = MAX(hi[d], v[i][d]);
      }
  MPI_Allreduce(lo, loall, 3, MPI_DOUBLE, MPI_MIN, world);
  MPI_Allreduce(hi, hiall, 3, MPI_DOUBLE, MPI_MAX, world);
  double vrel2 = 0.0;
  for (int d = 0; d < 3; d++)
    if (hiall[d] >= loall[d]) vrel2 += (hiall[d] - loall[d]) * (hiall[d] - loall[d]);
  const double travel = sqrt(vrel2) * steps * update->dt;
  if (travel > neighbor->skin && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate: neigh_modify check no rebuilds the neighbour lists "
                   "every {} steps, in which particles approach each other by up to {:.3g} x "
                   "the skin {} (relative velocity {:.4g}): pairs then come within the cutoff "
                   "unseen, and contact starts late. Use neigh_modify check yes, or every N "
                   "with N below {}",
                   steps, travel / neighbor->skin, neighbor->skin, sqrt(vrel2),
                   MAX(1, (int) (neighbor->skin / (sqrt(vrel2) * update->dt))));
}

/* ----------------------------------------------------------------------
   fix deform with remap x (its default) moves the atoms of its group with
   the box each step, without their velocities: the continuity and stress
   rates, made of velocity differences, miss that motion, so a body is
   stretched without stress (measured: +4 % on a rebound, silently). With
   remap v or none the box deforms alone, and a body periodic across it
   feels that through its images
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_deform()
{
  for (const auto &f : modify->get_fix_by_style("^deform")) {
    auto *fd = dynamic_cast<FixDeform *>(f);
    if (!fd || fd->remapflag != Domain::X_REMAP) continue;
    const int *mask = atom->mask;
    const int bits = groupbit, fbit = f->groupbit;
    const bool acts = ESPHCheck::any_atom(lmp, [&](int i) {
      return (mask[i] & bits) && (mask[i] & fbit);
    });
    if (acts && comm->me == 0)
      error->warning(FLERR,
                     "Fix deform {} remaps the positions of particles of fix esph/integrate {} "
                     "(remap x, the default) without their velocities: the solid does not feel "
                     "that motion (its density and stress rates come from velocities), so it is "
                     "deformed without stress. Use fix deform ... remap v or remap none, or "
                     "load the bodies through velocities or forces (fix move, fix setforce)",
                     f->id, id);
  }
}

/* ----------------------------------------------------------------------
   true if another fix may change the bodies' angular momentum: one that adds
   forces (but fix enforce2d, which adds no in-plane torque) or one that sets
   velocities (fix momentum ... angular, thermostats, fix recenter)
------------------------------------------------------------------------- */

bool FixESPHIntegrate::other_torques()
{
  for (const auto &ifix : modify->get_fix_list()) {
    if (ifix == this) continue;
    const std::string style = ifix->style;
    if ((modify->get_fix_mask(ifix) & FixConst::POST_FORCE) && style != "enforce2d") return true;
    if (utils::strmatch(style, "^momentum") || utils::strmatch(style, "^temp/") ||
        utils::strmatch(style, "^recenter") || utils::strmatch(style, "^langevin"))
      return true;
  }
  return false;
}

/* ----------------------------------------------------------------------
   the boundary particles of a body must move with it: a body with real
   particles in the group and boundary particles outside it would fly
   through the others (its surface stays where it was made)
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_group()
{
  state->fetch();
  if (!state->body) return;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  std::vector<int> mine;
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && state->rmass[i] > 0.0) mine.push_back(state->body[i]);
  const std::vector<int> bodies = ESPHCheck::global_set(lmp, mine);
  bigint out = 0, outall;
  tagint first = 0, firstall;
  for (int i = 0; i < nlocal; i++)
    if (!(mask[i] & groupbit) && state->rmass[i] == 0.0 &&
        std::binary_search(bodies.begin(), bodies.end(), state->body[i])) {
      if (!out) first = atom->tag[i];
      out++;
    }
  MPI_Allreduce(&out, &outall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (outall == 0) return;
  tagint mine_first = out ? first : MAXTAGINT;
  MPI_Allreduce(&mine_first, &firstall, 1, MPI_LMP_TAGINT, MPI_MIN, world);
  error->all(FLERR, Error::NOLASTLINE,
             "Fix esph/integrate group {} holds real particles of bodies whose {} boundary "
             "particles (zero mass, e.g. atom {}) it leaves out: they would not move with their "
             "bodies, which then meet no contact; use a group that holds them too (e.g. all, "
             "or the body's group defined before fix esph/boundary)",
             group->names[igroup], outall, firstall);
}

/* ----------------------------------------------------------------------
   fix aveforce on a group with boundary particles: it shares the force among
   all atoms of its group, and the share of the zero-mass boundary particles
   is lost (they move with their bodies, not by forces)
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_average_forces()
{
  state->fetch();
  for (const auto &f : modify->get_fix_by_style("^aveforce")) {
    bigint n = 0, nall;
    for (int i = 0; i < atom->nlocal; i++)
      if ((atom->mask[i] & f->groupbit) && state->rmass[i] == 0.0) n++;
    MPI_Allreduce(&n, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (nall > 0 && comm->me == 0)
      error->warning(FLERR,
                     "Fix {} ({}) acts on {} boundary particles (zero mass) of group {}: their "
                     "share of its force is lost, as they move with their bodies; use a group of "
                     "the real particles (mass > 0) only",
                     f->id, f->style, nall, group->names[f->igroup]);
    // (a group over several bodies: each particle gets the mean force of all of them, so
    // the bodies move as one along the fix's directions)
    const auto bodies = ESPHCheck::body_counts(lmp, state, f->groupbit);
    if (bodies.size() > 1 && comm->me == 0)
      error->warning(FLERR,
                     "Fix {} ({}) averages the forces of real particles of {} bodies ({}): "
                     "each gets the mean force of all of them, so the bodies move as one "
                     "along the fix's directions and their contact does nothing there; use one "
                     "fix per body",
                     f->id, f->style, bodies.size(), ESPHCheck::format_bodies(bodies));
  }
}

/* ----------------------------------------------------------------------
   the CFL time step estimate of the last force computation of pair p (all
   ranks; 0 without a pair style)
------------------------------------------------------------------------- */

double FixESPHIntegrate::cfl_estimate(const PairESPHSolid *p) const
{
  const double mine = p ? p->dt_cfl : 0.0;
  double dt;
  MPI_Allreduce(&mine, &dt, 1, MPI_DOUBLE, MPI_MIN, world);
  return dt;
}

/* ----------------------------------------------------------------------
   a fixed time step (no cfl keyword) larger than CFL_SAFE times the CFL
   estimate of the setup computation gets a warning, once per size
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_fixed_dt()
{
  const double dt = cfl_estimate(pair);
  if (dt >= 1.0e299 || dt <= 0.0) return;    // no real particles
  const double ratio = update->dt / dt;
  if (!(ratio > CFL_SAFE) || update->dt == dt_warned) return;
  if (comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate: at step {} the time step {} is {:.3g} times the CFL "
                   "estimate {:.4g} (vector element 3: the sound speed's limit, which falls "
                   "where the material stiffens under compression, or with pair esph/solid heat "
                   "the heat diffusion's, h^2 / (2 D zeta)); above {} the integration gains "
                   "energy, the faster the "
                   "larger the step (nine-fold in 2000 steps at 0.7, lost atoms at 1.0): use "
                   "fix esph/integrate cfl 0.3 or a time step of at most {:.4g}",
                   update->ntimestep, update->dt, ratio, dt, CFL_SAFE, 0.3 * dt);
  dt_warned = update->dt;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::initial_integrate(int /*vflag*/)
{
  state->fetch();
  if (staggered) {
    initial_integrate_staggered();
    return;
  }
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int nint = nlocal;
  if (igroup == atom->firstgroup) nint = atom->nfirst;

  const double *rmass = state->rmass;
  double *rho = state->rho, *e = state->e, *h = state->h;
  double **s = state->s, **n = state->n;
  const double *drho = pair->drho, *de = pair->de, *dh = pair->dh;
  double **ds = pair->ds, **bspin = pair->bspin;
  const int *type = atom->type;
  const double *yield = pair->yield, *hard = pair->hardening, *shear = pair->shear;
  double *epsp = state->epsp;
  double **xs = pair->xsph_flag ? pair->xsph : nullptr;
  // switched viscosity coefficient, kept within [alpha_min, alpha]
  double *alpha = pair->vswitch_flag ? state->alpha : nullptr;
  const double *dalpha = pair->dalpha;
  const double amin = pair->vswitch_min, amax = pair->alpha;
  // extrapolated prediction: weight of the change of the rates since the computation before
  // (per unit of that step), for atoms whose stored rates belong to their trajectory
  const double xw = (extrap_on && dt_prev > 0.0) ? (EXTRAP_A - 1.0) * update->dt / dt_prev : 0.0;
  const int xstore = extrap_on;

  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
    for (int i = from; i < to; i++) {
      if (i + ESPH::PREFETCH_AHEAD < to) {
        const int ip = i + ESPH::PREFETCH_AHEAD;
        ESPH::prefetch_write(pred[ip], NPRED);
        ESPH::prefetch_write(s[ip], 6);
        ESPH::prefetch_read(ds[ip], 6);
        ESPH::prefetch_read(f[ip], 3);
      }
      double *p = pred[i];
      if (i < nint && (mask[i] & groupbit)) {
        if (rmass[i] > 0.0) {
          // the rates of the predicted half step: the last computation's, or extrapolated
          // from the last two (then stored for the next step)
          const double *fx = f[i], *dsx = ds[i];
          double drx = drho[i], dex = de[i], dhx = dh[i], dax = alpha ? dalpha[i] : 0.0;
          double rx[NRATES];
          if (xstore) {
            const double r[NRATES] = {f[i][0],  f[i][1],  f[i][2],  drho[i],  de[i],
                                      dh[i],    ds[i][0], ds[i][1], ds[i][2], ds[i][3],
                                      ds[i][4], ds[i][5], dax};
            const double w = (p[P_PREVOK] > 0.0) ? xw : 0.0;
            double *rp = p + P_PREV;
            for (int k = 0; k < NRATES; k++) {
              rx[k] = (w != 0.0) ? r[k] + w * (r[k] - rp[k]) : r[k];
              rp[k] = r[k];
            }
            p[P_PREVOK] = 1.0;
            fx = rx;
            drx = rx[3];
            dex = rx[4];
            dhx = rx[5];
            dsx = rx + 6;
            dax = rx[12];
          }
          if (move) {
            const double dtfm = dtf / rmass[i];
            for (int d = 0; d < 3; d++) {
              v[i][d] += dtfm * f[i][d];
              x[i][d] += dtv * v[i][d];
              p[P_V + d] = v[i][d] + dtfm * fx[d];
            }
            // XSPH: the particle drifts with its velocity smoothed over its body
            if (xs)
              for (int d = 0; d < 3; d++) x[i][d] += dtv * xs[i][d];
          } else {
            for (int d = 0; d < 3; d++) p[P_V + d] = v[i][d];
          }
          // half step to n+1/2 (stored), prediction of the end of the step (for the pair)
          advance_state(i, dth, 1);
          const int t = type[i];
          p[P_RHO] = rho[i] + dth * drx;
          p[P_E] = e[i] + dth * dex;
          p[P_H] = h[i] + dth * dhx;
          for (int k = 0; k < 6; k++) p[P_S + k] = s[i][k] + dth * dsx[k];
          // the prediction does not commit plastic strain
          if (yield[t] > 0.0) ESPH::radial_return(p + P_S, yield[t], hard[t], shear[t], epsp[i]);
          p[P_DIVV] = -drho[i] / rho[i];
          if (alpha) p[P_ALPHA] = advance_alpha(alpha[i], dax, dth, amin, amax);
          continue;
        } else if (move) {
          // boundary particle: moves with its interpolated velocity, its normal
          // rotates with the spin tensor W (eq. 17): dn/dt = W n = omega x n
          for (int d = 0; d < 3; d++) x[i][d] += dtv * v[i][d];
          rotate_normal(n[i], bspin[i]);
        }
      }
      // not integrated here: the state as it is
      set_pred_from_state(i);
    }
  });
  pair->pred_valid = 1;
  stepping = 1;
  // the step between the rates just stored and those of the next computation
  if (extrap_on) dt_prev = update->dt;
}

/* ----------------------------------------------------------------------
   scheme staggered: kick to v^(n+1/2); the pair style's rate pass at x^n
   with v^(n+1/2) and the state of step n (stagger_commit() then advances
   density, h, stress and alpha to n+1); drift to x^(n+1). The force
   computation of the step sees x^(n+1), v^(n+1/2) and the state of n+1.
   The internal energy rate of the rate pass is the work rate of the
   stress forces of step n on v^(n+1/2), that of the force pass the one of
   the forces of n+1: their mean over the step is the work the kicks do.
------------------------------------------------------------------------- */

void FixESPHIntegrate::initial_integrate_staggered()
{
  double **x = atom->x;
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int nint = nlocal;
  if (igroup == atom->firstgroup) nint = atom->nfirst;
  const double *rmass = state->rmass;

  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
    for (int i = from; i < to; i++) {
      if (i < nint && (mask[i] & groupbit) && rmass[i] > 0.0) {
        const double dtfm = dtf / rmass[i];
        for (int d = 0; d < 3; d++) v[i][d] += dtfm * f[i][d];
      }
      set_pred_from_state(i);
    }
  });
  pair->pred_valid = 1;
  stepping = 1;
  pair->stagger_rates();
  stagger_commit();

  state->fetch();
  double **n = state->n;
  double **xs = pair->xsph_flag ? pair->xsph : nullptr;
  double **bvel = pair->bvel, **bspin = pair->bspin;
  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
    for (int i = from; i < to; i++) {
      if (!(i < nint && (mask[i] & groupbit))) continue;
      if (rmass[i] > 0.0) {
        for (int d = 0; d < 3; d++) x[i][d] += dtv * v[i][d];
        if (xs)
          for (int d = 0; d < 3; d++) x[i][d] += dtv * xs[i][d];
      } else {
        // boundary particle: the velocity and spin interpolated from v^(n+1/2)
        for (int d = 0; d < 3; d++) {
          v[i][d] = bvel[i][d];
          x[i][d] += dtv * v[i][d];
        }
        rotate_normal(n[i], bspin[i]);
        for (int d = 0; d < 3; d++) pred[i][P_V + d] = v[i][d];
      }
    }
  });
}

/* ----------------------------------------------------------------------
   advance the SPH state of real particle i by dt with the rates of the last
   force computation: density, internal energy (if with_e), smoothing
   length, deviatoric stress with its radial return (committing the plastic
   strain) and the switched viscosity coefficient
------------------------------------------------------------------------- */

void FixESPHIntegrate::advance_state(int i, double dt, int with_e)
{
  state->rho[i] += dt * pair->drho[i];
  if (with_e) state->e[i] += dt * pair->de[i];
  state->h[i] += dt * pair->dh[i];
  double *si = state->s[i];
  for (int k = 0; k < 6; k++) si[k] += dt * pair->ds[i][k];
  const int t = atom->type[i];
  if (pair->yield[t] > 0.0)
    state->epsp[i] +=
        ESPH::radial_return(si, pair->yield[t], pair->hardening[t], pair->shear[t], state->epsp[i]);
  if (pair->vswitch_flag)
    state->alpha[i] =
        advance_alpha(state->alpha[i], pair->dalpha[i], dt, pair->vswitch_min, pair->alpha);
}

/* ----------------------------------------------------------------------
   atom i is a boundary particle this fix moves (with the velocity
   interpolated from its body)
------------------------------------------------------------------------- */

bool FixESPHIntegrate::moves_boundary(int i) const
{
  return move && (atom->mask[i] & groupbit) && state->rmass[i] == 0.0;
}

/* ----------------------------------------------------------------------
   the boundary particles that this fix does not move must move with their
   body, as another fix moves it (fix move on the whole body) or not at
   all: per body, the rms difference of their velocities from the one the
   force computation interpolated from the body's real particles (bvel),
   against the rms of those velocities. A fix applied to the real
   particles alone leaves the boundary particles behind, and the contact
   then acts at a surface that stands still (collective; an ERROR)
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_boundary_motion()
{
  const int nb = moved_bodies.size();
  std::vector<double> sum(4 * nb, 0.0), all(4 * nb);
  double **v = atom->v;
  double **bvel = pair->bvel;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!turns_at_end(i)) continue;
    const int k = ESPH::body_slot(moved_bodies, state->body[i]);
    if (k < 0) continue;
    double *s = &sum[4 * k];
    for (int d = 0; d < 3; d++) {
      s[0] += (v[i][d] - bvel[i][d]) * (v[i][d] - bvel[i][d]);
      s[1] += bvel[i][d] * bvel[i][d];
      s[2] += v[i][d] * v[i][d];
    }
    s[3] += 1.0;
  }
  MPI_Allreduce(sum.data(), all.data(), 4 * nb, MPI_DOUBLE, MPI_SUM, world);
  for (int k = 0; k < nb; k++) {
    const double *a = &all[4 * k];
    // (rigid motion is interpolated exactly; a quarter of the squares leaves room for the
    // interpolation of other motions, a left-behind surface gives all of them)
    if (!(a[0] > BND_MOTION_SHARE * (a[1] + a[2]))) continue;
    // (the sums are the same on every rank: all call it)
    error->all(FLERR,
               "Fix esph/integrate: at step {} the boundary particles of body {} do not move "
               "with its real particles (their velocities differ by {:.4g} rms from those "
               "interpolated from the real particles, {:.4g} rms; their own {:.4g} rms): "
               "another fix moves the body's real particles but not its boundary particles, "
               "so the body's contact surface stays behind; apply that fix (e.g. fix move) "
               "to all atoms of the body, boundary particles included (a group of its "
               "i_esph_body or of its region, not of the real particles alone)",
               update->ntimestep, moved_bodies[k], sqrt(a[0] / a[3]), sqrt(a[1] / a[3]),
               sqrt(a[2] / a[3]));
  }
}

/* ----------------------------------------------------------------------
   the specific internal energy of real particle i at the end of this
   step, with the rate dei of its force computation: final_integrate()'s
   arithmetic (advance_state(), or the staggered scheme's mean of its two
   passes) for the particles it advances, the state as is otherwise and
   outside a step (the setup computation, also of a continued run, whose
   state is that of the end of the last step)
------------------------------------------------------------------------- */

double FixESPHIntegrate::end_energy(int i, double dei) const
{
  const int nint = (igroup == atom->firstgroup) ? atom->nfirst : atom->nlocal;
  if (!stepping || i >= nint || !(atom->mask[i] & groupbit)) return state->e[i];
  // scheme staggered: the mean rate of the two passes, the rate pass's through its
  // prediction e + dt de_1 (which migrates with the atom, unlike the pair's rates)
  if (staggered) return 0.5 * (state->e[i] + pred[i][P_E]) + dth * dei;
  return state->e[i] + dth * dei;
}

/* ----------------------------------------------------------------------
   the prediction of atom i is its state as it is
------------------------------------------------------------------------- */

void FixESPHIntegrate::set_pred_from_state(int i)
{
  double *p = pred[i];
  const double *vi = atom->v[i];
  for (int d = 0; d < 3; d++) p[P_V + d] = vi[d];
  p[P_RHO] = state->rho[i];
  p[P_E] = state->e[i];
  p[P_H] = state->h[i];
  for (int k = 0; k < 6; k++) p[P_S + k] = state->s[i][k];
  p[P_DIVV] = (state->rho[i] > 0.0) ? -pair->drho[i] / state->rho[i] : 0.0;
  p[P_ALPHA] = (pair->vswitch_flag && state->alpha) ? state->alpha[i] : 0.0;
}

/* ---------------------------------------------------------------------- */

double FixESPHIntegrate::elapsed() const
{
  return update->atime + (update->ntimestep - update->atimestep) * update->dt;
}

/* ----------------------------------------------------------------------
   true for a boundary particle that turns with its body's spin at the end
   of the step (final_integrate()): one that another fix moves, or that
   stays at rest
------------------------------------------------------------------------- */

bool FixESPHIntegrate::turns_at_end(int i) const
{
  // (a boundary particle the integrator does not move; in_group as final_integrate())
  if (state->rmass[i] != 0.0) return false;
  const int nint = (igroup == atom->firstgroup) ? atom->nfirst : atom->nlocal;
  return !(move && i < nint && (atom->mask[i] & groupbit));
}

/* ----------------------------------------------------------------------
   a boundary particle's normal rotated over one step by its spin tensor W
   (eq. 17): dn/dt = W n = omega x n
------------------------------------------------------------------------- */

void FixESPHIntegrate::rotate_normal(double *ni, const double *spin)
{
  ESPH::rotate_by_spin(ni, spin, dtv);
}

/* ----------------------------------------------------------------------
   staggered scheme, called by the pair style between its two passes: the
   rates of the first pass (velocity v^(n+1/2) at x^(n+1), state of step n)
   advance density, smoothing length, stress and the switched viscosity by
   a whole step; the prediction becomes that state (with the internal energy
   advanced by the first pass's rate, for the equation of state), which the
   force pass reads. The internal energy is advanced in final_integrate() by
   the mean of the two passes' rates.
------------------------------------------------------------------------- */

void FixESPHIntegrate::stagger_commit()
{
  state->fetch();
  const int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;
  const double *rmass = state->rmass;
  const double *rho = state->rho, *e = state->e, *h = state->h;
  double **s = state->s;
  const double *drho = pair->drho, *de = pair->de;
  const double *alpha = pair->vswitch_flag ? state->alpha : nullptr;

  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int) {
    for (int i = from; i < to; i++) {
      if (!(mask[i] & groupbit) || rmass[i] == 0.0) continue;
      double *p = pred[i];
      advance_state(i, dtv, 0);
      p[P_RHO] = rho[i];
      p[P_H] = h[i];
      p[P_E] = e[i] + dtv * de[i];
      for (int k = 0; k < 6; k++) p[P_S + k] = s[i][k];
      p[P_DIVV] = -drho[i] / rho[i];
      p[P_ALPHA] = alpha ? alpha[i] : 0.0;
    }
  });
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::final_integrate()
{
  state->fetch();
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  int nint = nlocal;
  if (igroup == atom->firstgroup) nint = atom->nfirst;

  const double *rmass = state->rmass;
  double *e = state->e;
  const double *de = pair->de;
  double **bvel = pair->bvel, **bspin = pair->bspin, **n = state->n;
  double **x = atom->x;
  // per chunk: the first boundary particle that another fix moved to a non-finite place
  std::vector<int> nonfinite(nthreads, -1);
  int *const nonfinite_t = nonfinite.data();

  double **s = state->s, **ds = pair->ds;
  ESPH::for_chunks(nthreads, nlocal, [=](int from, int to, int tid) {
    for (int i = from; i < to; i++) {
      if (i + ESPH::PREFETCH_AHEAD < to) {
        const int ip = i + ESPH::PREFETCH_AHEAD;
        ESPH::prefetch_write(s[ip], 6);
        ESPH::prefetch_read(ds[ip], 6);
        ESPH::prefetch_read(f[ip], 3);
      }
      const bool in_group = i < nint && (mask[i] & groupbit);
      if (turns_at_end(i)) {
        // a boundary particle that another fix moves (fix move on a rigid body, or move no)
        // or that stays at rest turns with its body's spin at the end of the step, from
        // the velocities that fix has set: exact for a rigid rotation, nothing at rest or
        // in translation
        rotate_normal(n[i], bspin[i]);
        if (nonfinite_t[tid] < 0 &&
            !(std::isfinite(x[i][0]) && std::isfinite(x[i][1]) && std::isfinite(x[i][2])))
          nonfinite_t[tid] = i;
      }
      if (!in_group) continue;
      if (rmass[i] > 0.0) {
        if (move) {
          const double dtfm = dtf / rmass[i];
          v[i][0] += dtfm * f[i][0];
          v[i][1] += dtfm * f[i][1];
          v[i][2] += dtfm * f[i][2];
        }
        if (staggered) {
          // density, stress, h and alpha are at n+1 already (stagger_commit()); the internal
          // energy as end_energy() (the one place of that rule, which the pair's energy
          // tally uses too)
          e[i] = end_energy(i, de[i]);
          continue;
        }
        advance_state(i, dth, 1);
      } else if (move) {
        v[i][0] = bvel[i][0];
        v[i][1] = bvel[i][1];
        v[i][2] = bvel[i][2];
      }
    }
  });
  // a fix that integrates forces (fix nve, fix move variable with NULL displacement and
  // velocity) divides by the zero mass of a boundary particle: caught in the step it happens
  for (int t = 0; t < nthreads; t++)
    if (nonfinite[t] >= 0) {
      const int i = nonfinite[t];
      error->one(FLERR, Error::NOLASTLINE,
                 "Boundary particle {} (zero mass) of body {} has a non-finite position after "
                 "step {}: a fix other than esph/integrate {} moves it by integrating forces, "
                 "which divides by its zero mass (e.g. fix move variable with NULL displacement "
                 "and velocity, or fix nve); prescribe the motion (fix move linear, wiggle, "
                 "rotate, or variable with displacement and velocity variables) for the whole "
                 "body, boundary particles included",
                 atom->tag[i], state->body ? state->body[i] : 0, update->ntimestep, id);
    }
  // force computations outside a step see the state as is, unless a run continues
  pair->pred_valid = 0;
  stepping = 0;
  if (!moved_bodies.empty()) check_boundary_motion();
  havepred = RESUME_STEP;

  // contact bookkeeping (ESPH::ContactRecord): the contact force F is the sum of the
  // compressive normal forces transmitted between bodies; contact begins with the first
  // touching pair and lasts while F exceeds a fraction of its peak so far, so that bodies
  // left resting against each other without load (a short striker that has stopped) or
  // a surface particle bouncing once at first touch do not change the contact time
  if (pair->nboundary > 0) {
    double total[3];
    contact_tallies(total);
    const double t = elapsed();
    // (no net force for all bodies together: it is per pair of bodies)
    const double sums[ESPH::ContactRecord::NTALLY] = {total[0], total[1], total[2], 0.0, 0.0, 0.0};
    contact_all.update(t, update->dt, sums);
    update_body_pairs(t);
  }
  if (spin_watch_on) spin_watch.step(lmp, state, groupbit, update->ntimestep, id);
  // a fixed time step against the CFL estimate during the run too (the estimate falls where
  // an impact compresses a stiffening material), every FIXED_DT_CHECK steps
  if (cfl <= 0.0 && update->ntimestep % FIXED_DT_CHECK == 0) check_fixed_dt();
  check_moved_velocities();
  energy_watch.step(lmp, state, groupbit, update->ntimestep, id);
}

/* ----------------------------------------------------------------------
   real particles outside the group that another fix moves must carry the
   velocities of their motion: the contact and the boundary normals read
   them. fix move variable with displacement variables and no velocity
   variables leaves them as they were (a turned body was seen at rest).
   Every FIXED_DT_CHECK steps the displacement over one step is compared
   with the mean of its end velocities (exact for a uniform motion,
   O(omega dt) relative for a rotation); warned once.
------------------------------------------------------------------------- */

void FixESPHIntegrate::check_moved_velocities()
{
  if (moved_warned) return;
  const bigint step = update->ntimestep;
  const int phase = step % FIXED_DT_CHECK;
  if (phase != FIXED_DT_CHECK - 1 && phase != 0) return;
  double **x = atom->x;
  double **v = atom->v;
  const int *mask = atom->mask;
  const tagint *tag = atom->tag;
  const int nlocal = atom->nlocal;
  const double *rmass = state->rmass;
  if (phase == FIXED_DT_CHECK - 1) {
    moved_then.clear();
    for (int i = 0; i < nlocal; i++)
      if (rmass[i] > 0.0 && !(mask[i] & groupbit))
        moved_then[tag[i]] = {x[i][0], x[i][1], x[i][2], v[i][0], v[i][1], v[i][2]};
    moved_step = step;
    return;
  }
  if (moved_step != step - 1) return;
  const double dt = update->dt;
  tagint bad = 0;
  double moved = 0.0, speed = 0.0;
  for (int i = 0; i < nlocal && !bad; i++) {
    if (!(rmass[i] > 0.0) || (mask[i] & groupbit)) continue;
    const auto it = moved_then.find(tag[i]);
    if (it == moved_then.end()) continue;
    const auto &s = it->second;
    double dx[3], err2 = 0.0, d2 = 0.0, v2 = 0.0;
    for (int d = 0; d < 3; d++) dx[d] = x[i][d] - s[d];
    domain->minimum_image(FLERR, dx);
    for (int d = 0; d < 3; d++) {
      const double vbar = 0.5 * (v[i][d] + s[3 + d]);
      err2 += (dx[d] - vbar * dt) * (dx[d] - vbar * dt);
      d2 += dx[d] * dx[d];
      v2 += v[i][d] * v[i][d];
    }
    if (d2 > 0.0 && err2 > 1.0e-4 * d2) {
      bad = tag[i];
      moved = sqrt(d2);
      speed = sqrt(v2);
    }
  }
  moved_then.clear();
  tagint any;
  MPI_Allreduce(&bad, &any, 1, MPI_LMP_TAGINT, MPI_MAX, world);
  if (!any) return;
  moved_warned = 1;
  // the values of the atom named, from its rank
  const double mine[2] = {bad == any ? moved : 0.0, bad == any ? speed : 0.0};
  double all[2];
  MPI_Allreduce(mine, all, 2, MPI_DOUBLE, MPI_MAX, world);
  moved = all[0];
  speed = all[1];
  if (comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/integrate: atom {} outside its group moved {} in step {} at a "
                   "speed of {}, not its velocity times the step: a fix moves it without "
                   "setting the velocities of the motion (fix move variable with displacement "
                   "variables but no velocity variables); the contact and the boundary normals "
                   "read the velocities and see the body otherwise: give velocity variables",
                   any, moved, step, speed);
}

/* ----------------------------------------------------------------------
   the pair style's touching and interacting cross-body pairs and contact
   force of its last force computation, summed over all ranks
------------------------------------------------------------------------- */

void FixESPHIntegrate::contact_tallies(double *total)
{
  double local[3] = {(double) pair->ntouch_pairs, (double) pair->ncontact_pairs, pair->fcontact};
  MPI_Allreduce(local, total, 3, MPI_DOUBLE, MPI_SUM, world);
}

/* ----------------------------------------------------------------------
   the contact history of every pair of bodies, from the pair style's
   tallies of this step: body pairs seen for the first time on any rank
   join the (sorted, global) list; then one sum over ranks
------------------------------------------------------------------------- */

void FixESPHIntegrate::update_body_pairs(double t, int setup)
{
  const auto &tally = pair->body_tally;
  std::vector<int> fresh;
  for (const auto &kv : tally)
    if (!std::binary_search(body_pairs.begin(), body_pairs.end(), kv.first)) {
      fresh.push_back(kv.first.first);
      fresh.push_back(kv.first.second);
    }
  int nfresh = fresh.size(), nfresh_all;
  MPI_Allreduce(&nfresh, &nfresh_all, 1, MPI_INT, MPI_SUM, world);
  if (nfresh_all > 0) {
    std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
    MPI_Allgather(&nfresh, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
    for (int p = 0, tot = 0; p < comm->nprocs; p++) {
      displs[p] = tot;
      tot += counts[p];
    }
    std::vector<int> all(nfresh_all);
    MPI_Allgatherv(fresh.data(), nfresh, MPI_INT, all.data(), counts.data(), displs.data(), MPI_INT,
                   world);
    for (int k = 0; k < nfresh_all; k += 2) {
      const std::pair<int, int> key(all[k], all[k + 1]);
      auto it = std::lower_bound(body_pairs.begin(), body_pairs.end(), key);
      if (it != body_pairs.end() && *it == key) continue;
      const auto pos = it - body_pairs.begin();
      body_pairs.insert(it, key);
      body_records.insert(body_records.begin() + pos, ESPH::ContactRecord());
    }
  }
  const int np = body_pairs.size();
  if (np == 0) return;
  constexpr int NT = ESPH::ContactRecord::NTALLY;
  static_assert(PairESPHSolid::NTALLY == NT, "the pair style's body tallies feed the records");
  std::vector<double> local(NT * np, 0.0), total(NT * np);
  for (const auto &kv : tally) {
    const auto pos =
        std::lower_bound(body_pairs.begin(), body_pairs.end(), kv.first) - body_pairs.begin();
    for (int k = 0; k < NT; k++) local[NT * pos + k] = kv.second[k];
  }
  MPI_Allreduce(local.data(), total.data(), NT * np, MPI_DOUBLE, MPI_SUM, world);
  for (int p = 0; p < np; p++) {
    if (setup) {
      body_records[p].now(total.data() + NT * p);
      continue;
    }
    body_records[p].update(t, update->dt, total.data() + NT * p);
    if (spin_watch_on && (total[NT * p] > 0.0 || total[NT * p + 1] > 0.0))
      spin_watch.touched(body_pairs[p].first, body_pairs[p].second);
  }
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::end_of_step()
{
  adapt_dt();
}

/* ----------------------------------------------------------------------
   CFL step: dt = cfl * min_i h_i / (c_L,i + |v_i|), c_L the longitudinal
   wave speed sqrt(c^2 + 4 G / (3 rho)); same logic as fix dt/reset
------------------------------------------------------------------------- */

void FixESPHIntegrate::adapt_dt()
{
  double dt = cfl_estimate(pair);
  if (dt >= 1.0e299) return;    // no real particles
  // dtmin is used as given: above CFL_SAFE of the estimate it holds the step where the
  // integration gains energy (checked where dtmin takes over; warned once per value)
  if (dtmin > 0.0 && dtmin > CFL_SAFE * dt && dtmin != dtmin_warned) {
    if (comm->me == 0)
      error->warning(FLERR,
                     "Fix esph/integrate: dtmin {} is {:.3g} times the CFL estimate {:.4g} "
                     "(vector element 3): where the cfl step falls below dtmin, the step is "
                     "held at dtmin, above {} of the estimate, where the integration gains "
                     "energy (lost atoms at 1.0); lower dtmin below {:.4g}, or leave it out",
                     dtmin, dtmin / dt, dt, CFL_SAFE, CFL_SAFE * dt);
    dtmin_warned = dtmin;
  }
  dt *= cfl;
  if (dtmin > 0.0) dt = MAX(dt, dtmin);
  if (dtmax > 0.0) dt = MIN(dt, dtmax);
  if (dt == update->dt) return;

  update->update_time();
  update->dt = dt;
  update->dt_default = 0;
  if (force->pair) force->pair->reset_dt();
  for (const auto &ifix : modify->get_fix_list()) ifix->reset_dt();
  output->reset_dt();
}

/* ----------------------------------------------------------------------
   1 = internal energy sum m e of the group, 2 = number of interacting
   cross-body (contact) pairs, 3 = CFL time step estimate (without factor),
   4 = time when the first contact began, 5 = time of the last interaction of
   the first contact episode (4 and 5 are -1 before any contact), 6 = number of
   contact episodes (separate periods with touching surfaces or interacting
   pairs), 7 = number of cross-body pairs whose surfaces touch
------------------------------------------------------------------------- */

double FixESPHIntegrate::compute_vector(int n)
{
  state->fetch();
  // (read between runs too: the pair style of now, which init() has not yet seen before the
  // first run or after a pair_style command; none: no contact pairs and no step estimate)
  auto *pnow = dynamic_cast<PairESPHSolid *>(force->pair_match("^esph/solid", 0));
  if (n == 0) {
    const int *mask = atom->mask;
    double local = 0.0, total;
    for (int i = 0; i < atom->nlocal; i++)
      if (mask[i] & groupbit) local += state->rmass[i] * state->e[i];
    MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
    return total;
  }
  if (n == 1) {
    int local = pnow ? pnow->ncontact_pairs : 0, total;
    MPI_Allreduce(&local, &total, 1, MPI_INT, MPI_SUM, world);
    return (double) total;
  }
  if (n == 2) return cfl_estimate(pnow);
  if (n == 3) return contact_all.tfirst;
  if (n == 4) return contact_all.tlast;
  if (n == 5) return (double) contact_all.nepisodes;
  if (n == 7) return contact_all.force;
  int local = pnow ? pnow->ntouch_pairs : 0, total;
  MPI_Allreduce(&local, &total, 1, MPI_INT, MPI_SUM, world);
  return (double) total;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::grow_arrays(int nmax)
{
  memory->grow(pred, nmax, NPRED, "esph/integrate:pred");
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::copy_arrays(int i, int j, int /*delflag*/)
{
  for (int k = 0; k < NPRED; k++) pred[j][k] = pred[i][k];
}

/* ----------------------------------------------------------------------
   a new atom (create_atoms, fix esph/boundary, read_data add) has no
   prediction, and the ESPH state of an atom in a fresh box
------------------------------------------------------------------------- */

void FixESPHIntegrate::set_arrays(int i)
{
  clear_pred(i);
  if (state) state->clear_atom(i);
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::clear_pred(int i)
{
  for (int k = 0; k < NPRED; k++) pred[i][k] = 0.0;
  pred[i][P_HASH] = -1.0;    // fingerprints are >= 0
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::pack_exchange(int i, double *buf)
{
  for (int k = 0; k < NPRED; k++) buf[k] = pred[i][k];
  return NPRED;
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::unpack_exchange(int nlocal, double *buf)
{
  for (int k = 0; k < NPRED; k++) pred[nlocal][k] = buf[k];
  return NPRED;
}

/* ---------------------------------------------------------------------- */

double FixESPHIntegrate::memory_usage()
{
  return (double) atom->nmax * NPRED * sizeof(double);
}
