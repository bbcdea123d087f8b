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
#include "esph_check.h"
#include "esph_state.h"

#include <algorithm>
#include <cmath>

using namespace LAMMPS_NS;

// per body: m, m x (3), m v (3), m x cross v (3), m x x^T (xx yy zz xy xz yz), m v.v / 2
static constexpr int NSUM = 17;

/* ---------------------------------------------------------------------- */

void ESPHSpinWatch::setup(LAMMPS *lmp, ESPHState *state, int groupbit)
{
  // the bodies with real particles in the group, on all ranks (sorted)
  bodies.clear();
  if (state->body)
    for (const auto &kv : ESPHCheck::body_counts(lmp, state, groupbit)) bodies.push_back(kv.first);
  refs.assign(bodies.size(), Ref());
  hit.clear();
}

/* ---------------------------------------------------------------------- */

void ESPHSpinWatch::step(LAMMPS *lmp, ESPHState *state, int groupbit, bigint ntimestep,
                         const char *fixid)
{
  if (ntimestep % SAMPLE != 0 || bodies.empty()) return;
  const int nb = bodies.size();
  std::vector<double> local(NSUM * nb, 0.0), sum(NSUM * nb);
  Atom *atom = lmp->atom;
  double **x = atom->x;
  double **v = atom->v;
  const imageint *image = atom->image;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  for (int i = 0; i < nlocal; i++) {
    const double m = state->rmass[i];
    if (!(mask[i] & groupbit) || !(m > 0.0)) continue;
    const auto it = std::lower_bound(bodies.begin(), bodies.end(), state->body[i]);
    if (it == bodies.end() || *it != state->body[i]) continue;
    double *s = local.data() + NSUM * (it - bodies.begin());
    double xu[3];
    lmp->domain->unmap(x[i], image[i], xu);
    const double *vi = v[i];
    s[0] += m;
    for (int d = 0; d < 3; d++) {
      s[1 + d] += m * xu[d];
      s[4 + d] += m * vi[d];
    }
    s[7] += m * (xu[1] * vi[2] - xu[2] * vi[1]);
    s[8] += m * (xu[2] * vi[0] - xu[0] * vi[2]);
    s[9] += m * (xu[0] * vi[1] - xu[1] * vi[0]);
    s[10] += m * xu[0] * xu[0];
    s[11] += m * xu[1] * xu[1];
    s[12] += m * xu[2] * xu[2];
    s[13] += m * xu[0] * xu[1];
    s[14] += m * xu[0] * xu[2];
    s[15] += m * xu[1] * xu[2];
    s[16] += 0.5 * m * (vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
  }
  MPI_Allreduce(local.data(), sum.data(), NSUM * nb, MPI_DOUBLE, MPI_SUM, lmp->world);

  for (int k = 0; k < nb; k++) {
    const double *s = sum.data() + NSUM * k;
    Ref &r = refs[k];
    const int body = bodies[k];
    const bool free = (hit.count(body) == 0);
    const double M = s[0];
    if (!(M > 0.0) || !free) {
      r.valid = false;
      continue;
    }
    double c[3], V[3], L[3];
    for (int d = 0; d < 3; d++) {
      c[d] = s[1 + d] / M;
      V[d] = s[4 + d] / M;
    }
    // about the centre of mass: L = sum m x x v - M c x V, trace of the second moment,
    // the kinetic energy of the motion relative to the centre of mass
    L[0] = s[7] - M * (c[1] * V[2] - c[2] * V[1]);
    L[1] = s[8] - M * (c[2] * V[0] - c[0] * V[2]);
    L[2] = s[9] - M * (c[0] * V[1] - c[1] * V[0]);
    const double trS =
        std::max(0.0, s[10] + s[11] + s[12] - M * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    const double V2 = V[0] * V[0] + V[1] * V[1] + V[2] * V[2];
    const double Kcm = std::max(0.0, s[16] - 0.5 * M * V2);
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
