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

#include "esph_spin_watch.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_bodies.h"
#include "esph_check.h"
#include "esph_state.h"
#include "force.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void ESPHSpinWatch::setup(LAMMPS *lmp, ESPHState *state, int groupbit)
{
  // the bodies with real particles in the group, on all ranks (sorted)
  bodies.clear();
  if (state->body)
    for (const auto &kv : ESPHCheck::body_counts(lmp, state, groupbit)) bodies.push_back(kv.first);
  hit.clear();
  // a body over more than half a periodic box has no angular momentum of its own (it
  // spans the box, or the minimum image cannot make it whole): not watched
  ESPH::body_reference(lmp, state, groupbit, bodies, points);
  refs.assign(bodies.size(), Ref());
}

/* ---------------------------------------------------------------------- */

void ESPHSpinWatch::step(LAMMPS *lmp, ESPHState *state, int groupbit, bigint ntimestep,
                         const char *fixid)
{
  if (ntimestep % SAMPLE != 0 || bodies.empty()) return;
  const int nb = bodies.size();
  std::vector<double> sum;
  ESPH::body_sums(lmp, state, groupbit, bodies, lmp->atom->v, 0, points, sum);

  for (int k = 0; k < nb; k++) {
    Ref &r = refs[k];
    const int body = bodies[k];
    const bool free = (hit.count(body) == 0);
    const ESPH::BodyMotion b = ESPH::body_motion(sum.data() + ESPH::BODY_NSUM * k);
    const double M = b.M;
    if (!(M > 0.0) || !free) {
      r.valid = false;
      continue;
    }
    // the trace of the second moment about the centre of mass, the kinetic energy of the
    // motion relative to it
    const double *L = b.L;
    const double trS = b.S[0] + b.S[1] + b.S[2];
    const double V2 = b.V[0] * b.V[0] + b.V[1] * b.V[1] + b.V[2] * b.V[2];
    const double Kcm = b.Kcm;
    const double Lnorm = sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    if (!r.valid) {
      // the scale of a change: the angular momentum itself, or, for a body that hardly
      // turns, the spin that would hold 1e-4 of its kinetic energy of translation or 1 %
      // of its energy relative to the centre of mass (vibration): smaller changes are
      // not warned
      r.valid = true;
      for (int d = 0; d < 3; d++) r.L[d] = L[d];
      r.scale = std::max({Lnorm, 0.01 * sqrt(M * trS * V2), 0.1 * sqrt(2.0 * Kcm * trS)});
      r.since = ntimestep;
      continue;
    }
    const double dL[3] = {L[0] - r.L[0], L[1] - r.L[1], L[2] - r.L[2]};
    const double change = sqrt(dL[0] * dL[0] + dL[1] * dL[1] + dL[2] * dL[2]);
    if (r.scale > 0.0 && change > TOL * r.scale && warned.count(body) == 0) {
      warned.insert(body);
      if (lmp->comm->me == 0) {
        const double L0 = sqrt(r.L[0] * r.L[0] + r.L[1] * r.L[1] + r.L[2] * r.L[2]);
        lmp->error->warning(
            FLERR,
            "Fix esph/integrate {}: the angular momentum of body {} changed by {:.3g} of its "
            "scale between steps {} and {} while it touched no other body (|L| {:.4g} -> "
            "{:.4g}): the stress forces of pair_style esph/solid gradient corrected (the "
            "default) and plain are not torque-free where a body's kernel support is cut, so "
            "a tumbling body drifts, and a small one (5-6 particles across) spins up without "
            "bound; use gradient torquefree or bonet/lok, which conserve it, or resolve the "
            "body with more particles",
            fixid, body, change / r.scale, r.since, ntimestep, L0, Lnorm);
      }
    }
  }
  hit.clear();
}

/* ---------------------------------------------------------------------- */

void ESPHEnergyWatch::sums(LAMMPS *lmp, ESPHState *state, int groupbit,
                           std::vector<double> &out) const
{
  const int nb = bodies.size();
  std::vector<double> mine(2 * nb, 0.0);
  const int *mask = lmp->atom->mask;
  double **v = lmp->atom->v;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || !(state->rmass[i] > 0.0)) continue;
    const auto it = std::lower_bound(bodies.begin(), bodies.end(), state->body[i]);
    if (it == bodies.end() || *it != state->body[i]) continue;
    const int k = it - bodies.begin();
    const double m = state->rmass[i];
    mine[2 * k] += 0.5 * m * (v[i][0] * v[i][0] + v[i][1] * v[i][1] + v[i][2] * v[i][2]);
    mine[2 * k + 1] += m * state->e[i];
  }
  out.assign(2 * nb, 0.0);
  MPI_Allreduce(mine.data(), out.data(), 2 * nb, MPI_DOUBLE, MPI_SUM, lmp->world);
}

/* ---------------------------------------------------------------------- */

void ESPHEnergyWatch::setup(LAMMPS *lmp, ESPHState *state, int groupbit)
{
  bodies.clear();
  state->fetch();
  if (state->body)
    for (const auto &kv : ESPHCheck::body_counts(lmp, state, groupbit)) bodies.push_back(kv.first);
  std::vector<double> s;
  sums(lmp, state, groupbit, s);
  const int nb = bodies.size();
  floor_.assign(nb, 0.0);
  scale.assign(nb, 0.0);
  for (int k = 0; k < nb; k++) {
    floor_[k] = std::min(0.0, s[2 * k + 1]);
    scale[k] = s[2 * k] + fabs(s[2 * k + 1]);
  }
}

/* ---------------------------------------------------------------------- */

void ESPHEnergyWatch::step(LAMMPS *lmp, ESPHState *state, int groupbit, bigint ntimestep,
                           const char *fixid)
{
  if (ntimestep % SAMPLE != 0 || bodies.empty()) return;
  state->fetch();
  std::vector<double> s;
  sums(lmp, state, groupbit, s);
  const int nb = bodies.size();
  double all = 0.0;
  for (int k = 0; k < nb; k++) {
    scale[k] = std::max(scale[k], s[2 * k] + fabs(s[2 * k + 1]));
    all += s[2 * k] + fabs(s[2 * k + 1]);
  }
  for (int k = 0; k < nb; k++) {
    const double ref = std::max(scale[k], 1.0e-6 * all);
    const double eint = s[2 * k + 1];
    if (!(ref > 0.0) || eint >= floor_[k] - TOL * ref || warned.count(bodies[k])) continue;
    warned.insert(bodies[k]);
    const double mvv2e = lmp->force->mvv2e;
    if (lmp->comm->me == 0)
      lmp->error->warning(
          FLERR,
          "Fix esph/integrate {}: body {} has a negative internal energy at step {} ({:.4g}, "
          "{:.3g} of the largest energy it had; its kinetic energy {:.4g}): a body's elastic "
          "energy and heat cannot be negative, so forces are creating energy, an instability. "
          "A body a few particles across under pair_style esph/solid gradient corrected (the "
          "default) or plain: use gradient torquefree or bonet/lok, or more particles across; "
          "otherwise a smaller time step (fix esph/integrate cfl)",
          fixid, bodies[k], ntimestep, eint * mvv2e, (floor_[k] - eint) / ref, s[2 * k] * mvv2e);
  }
}
