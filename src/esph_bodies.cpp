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

#include "esph_bodies.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "esph_state.h"

#include <algorithm>
#include <cfloat>
#include <mpi.h>

using namespace LAMMPS_NS;

static constexpr double BIG = DBL_MAX;

/* ----------------------------------------------------------------------
   the index of atom i's body in the sorted bodies, or -1 (a boundary particle, outside
   groupbit or of another body)
------------------------------------------------------------------------- */

static int body_index(ESPHState *state, const int *mask, int groupbit,
                      const std::vector<int> &bodies, int i)
{
  if (!(mask[i] & groupbit) || !(state->rmass[i] > 0.0)) return -1;
  return ESPH::body_slot(bodies, state->body[i]);
}

/* ---------------------------------------------------------------------- */

std::vector<int> ESPH::body_reference(LAMMPS *lmp, ESPHState *state, int groupbit,
                                      std::vector<int> &bodies, std::vector<double> &ref)
{
  const int nb = bodies.size();
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  const int me = lmp->comm->me, nprocs = lmp->comm->nprocs;
  // the first particle of each body on the lowest rank that has one
  std::vector<int> first(nb, -1), mine(nb, nprocs), owner(nb, nprocs);
  for (int i = 0; i < nlocal; i++) {
    const int k = body_index(state, mask, groupbit, bodies, i);
    if (k >= 0 && first[k] < 0) {
      first[k] = i;
      mine[k] = me;
    }
  }
  if (nb) MPI_Allreduce(mine.data(), owner.data(), nb, MPI_INT, MPI_MIN, lmp->world);
  std::vector<double> local(3 * nb, 0.0);
  ref.assign(3 * nb, 0.0);
  for (int k = 0; k < nb; k++)
    if (owner[k] == me)
      for (int d = 0; d < 3; d++) local[3 * k + d] = x[first[k]][d];
  if (nb) MPI_Allreduce(local.data(), ref.data(), 3 * nb, MPI_DOUBLE, MPI_SUM, lmp->world);
  // the extent of each body along the periodic directions, its particles taken to the
  // reference by the minimum image: above half the box length a body spans (or may fold)
  std::vector<double> ext(6 * nb, -BIG), gext(6 * nb);
  for (int i = 0; i < nlocal; i++) {
    const int k = body_index(state, mask, groupbit, bodies, i);
    if (k < 0) continue;
    double r[3] = {x[i][0] - ref[3 * k], x[i][1] - ref[3 * k + 1], x[i][2] - ref[3 * k + 2]};
    domain->minimum_image(FLERR, r);
    for (int d = 0; d < 3; d++) {
      ext[6 * k + d] = std::max(ext[6 * k + d], r[d]);
      ext[6 * k + 3 + d] = std::max(ext[6 * k + 3 + d], -r[d]);
    }
  }
  if (nb) MPI_Allreduce(ext.data(), gext.data(), 6 * nb, MPI_DOUBLE, MPI_MAX, lmp->world);
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  const double prd[3] = {domain->xprd, domain->yprd, domain->zprd};
  std::vector<int> kept, wide;
  std::vector<double> kref;
  for (int k = 0; k < nb; k++) {
    double span = 0.0;
    for (int d = 0; d < 3; d++)
      if (per[d] && gext[6 * k + d] > -BIG)
        span = std::max(span, (gext[6 * k + d] + gext[6 * k + 3 + d]) / prd[d]);
    if (span > 0.5) {
      wide.push_back(bodies[k]);
      continue;
    }
    kept.push_back(bodies[k]);
    kref.insert(kref.end(), ref.begin() + 3 * k, ref.begin() + 3 * k + 3);
  }
  bodies.swap(kept);
  ref.swap(kref);
  return wide;
}

/* ---------------------------------------------------------------------- */

void ESPH::body_sums(LAMMPS *lmp, ESPHState *state, int groupbit, const std::vector<int> &bodies,
                     double *const *vel, int voff, std::vector<double> &ref,
                     std::vector<double> &sum)
{
  const int nb = bodies.size();
  std::vector<double> local(BODY_NSUM * nb, 0.0);
  sum.assign(BODY_NSUM * nb, 0.0);
  Atom *atom = lmp->atom;
  Domain *domain = lmp->domain;
  double **x = atom->x;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // positions relative to the body's reference point by the minimum image: a body
  // created across a periodic boundary is whole whatever its image flags, and the second
  // moment about the centre of mass (a difference of sums) keeps its digits
  const int periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  for (int i = 0; i < nlocal; i++) {
    const int k = body_index(state, mask, groupbit, bodies, i);
    if (k < 0) continue;
    const double m = state->rmass[i];
    double *s = local.data() + BODY_NSUM * k;
    double xu[3] = {x[i][0] - ref[3 * k], x[i][1] - ref[3 * k + 1], x[i][2] - ref[3 * k + 2]};
    if (periodic) domain->minimum_image(FLERR, xu);
    add_body_sum(s, m, xu, vel[i] + voff);
  }
  if (nb) MPI_Allreduce(local.data(), sum.data(), BODY_NSUM * nb, MPI_DOUBLE, MPI_SUM, lmp->world);
  // the reference follows the centre of mass (the same on every rank)
  for (int k = 0; k < nb; k++) {
    const double *t = sum.data() + BODY_NSUM * k;
    if (t[0] > 0.0)
      for (int d = 0; d < 3; d++) ref[3 * k + d] += t[1 + d] / t[0];
  }
}
