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
#include "error.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "force.h"
#include "memory.h"
#include "modify.h"
#include "output.h"
#include "pair_esph_solid.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace FixConst;

// contact interruptions up to this many steps belong to the same contact episode
static constexpr int HOLD_STEPS = 10;
// contact is on while the contact force exceeds this fraction of its peak
static constexpr double FORCE_FRACTION = 0.01;

/* ---------------------------------------------------------------------- */

FixESPHIntegrate::FixESPHIntegrate(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), pred(nullptr), pair(nullptr), state(nullptr)
{
  time_integrate = 1;
  vector_flag = 1;
  size_vector = 8;
  global_freq = 1;
  extvector = -1;
  extlist = new int[size_vector]{1, 0, 0, 0, 0, 0, 0, 0};    // internal energy is extensive

  cfl = 0.0;
  move = 1;
  quiet = 0;
  nepisodes = 0;
  fcontact = fpeak = 0.0;
  tfirst = tlast = -1.0;
  dtmin = 0.0;
  dtmax = 0.0;

  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "cfl") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate cfl", error);
      cfl = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (cfl <= 0.0 || cfl > 1.0)
        error->all(FLERR, iarg + 1, "Fix esph/integrate cfl factor must be in (0,1], got {}",
                   arg[iarg + 1]);
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
    } else if (strcmp(arg[iarg], "dtmin") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/integrate dtmin", error);
      dtmin = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (dtmin <= 0.0)
        error->all(FLERR, iarg + 1, "Fix esph/integrate dtmin must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, iarg, "Unknown fix esph/integrate keyword: {}", arg[iarg]);
    }
  }
  if (dtmax > 0.0 && dtmin > dtmax)
    error->all(FLERR, "Fix esph/integrate dtmin {} is larger than dtmax {}", dtmin, dtmax);
  if (cfl == 0.0 && (dtmin > 0.0 || dtmax > 0.0))
    error->all(FLERR, "Fix esph/integrate dtmin/dtmax need the cfl keyword");
  // with move no another fix (e.g. fix move) integrates the motion
  time_integrate = move;

  grow_arrays(atom->nmax);
  atom->add_callback(Atom::GROW);
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
  if (modify->get_fix_by_style("^esph/integrate$").size() > 1)
    error->all(FLERR, Error::NOLASTLINE, "Only one fix esph/integrate may be defined");
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
  state->fetch();
  double **v = atom->v;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++)
    if (move && (mask[i] & groupbit) && state->rmass[i] == 0.0) {
      v[i][0] = pair->bvel[i][0];
      v[i][1] = pair->bvel[i][1];
      v[i][2] = pair->bvel[i][2];
    }
  if (cfl > 0.0) adapt_dt();
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::initial_integrate(int /*vflag*/)
{
  state->fetch();
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

  for (int i = 0; i < nlocal; i++) {
    double *p = pred[i];
    if (i < nint && (mask[i] & groupbit)) {
      if (rmass[i] > 0.0) {
        if (move) {
          const double dtfm = dtf / rmass[i];
          for (int d = 0; d < 3; d++) {
            v[i][d] += dtfm * f[i][d];
            x[i][d] += dtv * v[i][d];
            p[P_V + d] = v[i][d] + dtfm * f[i][d];
          }
          // XSPH: the particle drifts with its velocity smoothed over its body
          if (xs)
            for (int d = 0; d < 3; d++) x[i][d] += dtv * xs[i][d];
        } else {
          for (int d = 0; d < 3; d++) p[P_V + d] = v[i][d];
        }
        // half step to n+1/2 (stored), prediction of the end of the step (for the pair)
        rho[i] += dth * drho[i];
        e[i] += dth * de[i];
        h[i] += dth * dh[i];
        for (int k = 0; k < 6; k++) s[i][k] += dth * ds[i][k];
        const int t = type[i];
        if (yield[t] > 0.0)
          epsp[i] += ESPH::radial_return(s[i], yield[t], hard[t], shear[t], epsp[i]);
        p[P_RHO] = rho[i] + dth * drho[i];
        p[P_E] = e[i] + dth * de[i];
        p[P_H] = h[i] + dth * dh[i];
        for (int k = 0; k < 6; k++) p[P_S + k] = s[i][k] + dth * ds[i][k];
        // the prediction does not commit plastic strain
        if (yield[t] > 0.0) ESPH::radial_return(p + P_S, yield[t], hard[t], shear[t], epsp[i]);
        p[P_DIVV] = -drho[i] / rho[i];
        continue;
      }
      if (move) {
        // boundary particle: moves with its interpolated velocity, its normal
        // rotates with the spin tensor W (eq. 17): dn/dt = W n = omega x n
        for (int d = 0; d < 3; d++) x[i][d] += dtv * v[i][d];
        const double om[3] = {-bspin[i][2], bspin[i][1], -bspin[i][0]};
        const double wmag = sqrt(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]);
        const double theta = wmag * dtv;
        if (theta > 0.0) {
          const double k[3] = {om[0] / wmag, om[1] / wmag, om[2] / wmag};
          double *ni = n[i];
          const double kn = k[0] * ni[0] + k[1] * ni[1] + k[2] * ni[2];
          const double kxn[3] = {k[1] * ni[2] - k[2] * ni[1], k[2] * ni[0] - k[0] * ni[2],
                                 k[0] * ni[1] - k[1] * ni[0]};
          const double ct = cos(theta), st = sin(theta);
          for (int d = 0; d < 3; d++) ni[d] = ni[d] * ct + kxn[d] * st + k[d] * kn * (1.0 - ct);
        }
      }
    }
    // not integrated here: the state as it is
    for (int d = 0; d < 3; d++) p[P_V + d] = v[i][d];
    p[P_RHO] = rho[i];
    p[P_E] = e[i];
    p[P_H] = h[i];
    for (int k = 0; k < 6; k++) p[P_S + k] = s[i][k];
    p[P_DIVV] = (rho[i] > 0.0) ? -drho[i] / rho[i] : 0.0;
  }
  pair->pred_valid = 1;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::final_integrate()
{
  state->fetch();
  double **v = atom->v;
  double **f = atom->f;
  const int *mask = atom->mask;
  int nlocal = atom->nlocal;
  if (igroup == atom->firstgroup) nlocal = atom->nfirst;

  const double *rmass = state->rmass;
  double *rho = state->rho, *e = state->e, *h = state->h;
  double **s = state->s;
  const double *drho = pair->drho, *de = pair->de, *dh = pair->dh;
  double **ds = pair->ds, **bvel = pair->bvel;
  const int *type = atom->type;
  const double *yield = pair->yield, *hard = pair->hardening, *shear = pair->shear;
  double *epsp = state->epsp;

  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (rmass[i] > 0.0) {
      if (move) {
        const double dtfm = dtf / rmass[i];
        v[i][0] += dtfm * f[i][0];
        v[i][1] += dtfm * f[i][1];
        v[i][2] += dtfm * f[i][2];
      }
      rho[i] += dth * drho[i];
      e[i] += dth * de[i];
      h[i] += dth * dh[i];
      for (int k = 0; k < 6; k++) s[i][k] += dth * ds[i][k];
      const int t = type[i];
      if (yield[t] > 0.0)
        epsp[i] += ESPH::radial_return(s[i], yield[t], hard[t], shear[t], epsp[i]);
    } else if (move) {
      v[i][0] = bvel[i][0];
      v[i][1] = bvel[i][1];
      v[i][2] = bvel[i][2];
    }
  }
  // force computations outside a step (run setup, run pre no) see the state as is
  pair->pred_valid = 0;

  // contact bookkeeping. The contact force F is the sum of the compressive normal forces
  // transmitted between bodies. Contact begins with the first touching or interacting
  // pair; it lasts while F exceeds FORCE_FRACTION of its peak so far, so that bodies left
  // resting against each other without load (a short striker that has stopped) or a
  // surface particle bouncing once at first touch do not change the contact time.
  // An episode is a period with F above that level; interruptions of up to HOLD_STEPS
  // steps belong to the same episode.
  if (pair->nboundary > 0) {
    double local[3] = {(double) pair->ntouch_pairs, (double) pair->ncontact_pairs, pair->fcontact};
    double total[3];
    MPI_Allreduce(local, total, 3, MPI_DOUBLE, MPI_SUM, world);
    const double t = update->atime + (update->ntimestep - update->atimestep) * update->dt;
    if (tfirst < 0.0 && (total[0] > 0.0 || total[1] > 0.0)) tfirst = t - update->dt;
    fcontact = total[2];
    if (fcontact > fpeak) fpeak = fcontact;
    if (fcontact > 0.0 && fcontact >= FORCE_FRACTION * fpeak) {
      if (nepisodes == 0 || quiet > HOLD_STEPS) nepisodes++;
      if (nepisodes == 1) tlast = t;
      quiet = 0;
    } else {
      quiet++;
    }
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
  double dt;
  MPI_Allreduce(&pair->dt_cfl, &dt, 1, MPI_DOUBLE, MPI_MIN, world);
  if (dt >= 1.0e299) return;    // no real particles
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
  if (n == 0) {
    const int *mask = atom->mask;
    double local = 0.0, total;
    for (int i = 0; i < atom->nlocal; i++)
      if (mask[i] & groupbit) local += state->rmass[i] * state->e[i];
    MPI_Allreduce(&local, &total, 1, MPI_DOUBLE, MPI_SUM, world);
    return total;
  }
  if (n == 1) {
    int local = pair->ncontact_pairs, total;
    MPI_Allreduce(&local, &total, 1, MPI_INT, MPI_SUM, world);
    return (double) total;
  }
  if (n == 2) {
    double dt;
    MPI_Allreduce(&pair->dt_cfl, &dt, 1, MPI_DOUBLE, MPI_MIN, world);
    return dt;
  }
  if (n == 3) return tfirst;
  if (n == 4) return tlast;
  if (n == 5) return (double) nepisodes;
  if (n == 7) return fcontact;
  int local = pair->ntouch_pairs, total;
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
