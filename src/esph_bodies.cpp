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
#include "domain.h"
#include "esph_state.h"

#include <algorithm>
#include <mpi.h>

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

void ESPH::body_sums(LAMMPS *lmp, ESPHState *state, int groupbit, const std::vector<int> &bodies,
                     double *const *vel, int voff, std::vector<double> &sum)
{
  const int nb = bodies.size();
  std::vector<double> local(BODY_NSUM * nb, 0.0);
  sum.assign(BODY_NSUM * nb, 0.0);
  Atom *atom = lmp->atom;
  double **x = atom->x;
  const imageint *image = atom->image;
  const int *mask = atom->mask;
  const int nlocal = atom->nlocal;
  // positions from the box centre: the second moment about the centre of mass is a
  // difference of sums, whose round-off grows with the distance of the origin
  const double *lo = lmp->domain->boxlo, *hi = lmp->domain->boxhi;
  const double o[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
  const Domain *domain = lmp->domain;
  const int periodic = domain->xperiodic || domain->yperiodic || domain->zperiodic;
  for (int i = 0; i < nlocal; i++) {
    const double m = state->rmass[i];
    if (!(mask[i] & groupbit) || !(m > 0.0)) continue;
    const auto it = std::lower_bound(bodies.begin(), bodies.end(), state->body[i]);
    if (it == bodies.end() || *it != state->body[i]) continue;
    double *s = local.data() + BODY_NSUM * (it - bodies.begin());
    double xu[3] = {x[i][0], x[i][1], x[i][2]};
    if (periodic) lmp->domain->unmap(x[i], image[i], xu);
    for (int d = 0; d < 3; d++) xu[d] -= o[d];
    const double *vi = vel[i] + voff;
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
  if (nb) MPI_Allreduce(local.data(), sum.data(), BODY_NSUM * nb, MPI_DOUBLE, MPI_SUM, lmp->world);
}
