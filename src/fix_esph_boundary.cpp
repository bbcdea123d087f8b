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
   Non-mass boundary particles carrying unit outward normals (seed paper
   section 4.2). Generated once on the surfaces of the bodies made of the
   real particles in the fix group, or taken from a user-supplied group of
   zero-mass particles with given normals. Their motion, the rotation of
   their normals and the interpolation of their fields happen in the
   regular per-step flow of pair esph/solid and fix esph/integrate.
------------------------------------------------------------------------- */

#include "fix_esph_boundary.h"

#include "atom.h"
#include "atom_vec.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_check.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "force.h"
#include "group.h"
#include "memory.h"
#include "modify.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;
using namespace FixConst;

enum { GENERATE, GIVEN };

// a particle is on the surface when its kernel-weighted neighbour centroid is off
// by more than this fraction of the spacing (first layer of a cubic lattice: 0.18)
static constexpr double SURFACE_OFFSET = 0.05;
// the spacing keyword against the median nearest-neighbour distance of the real particles:
// a warning beyond SPACING_WARN, an error beyond SPACING_ERROR (at twice the spacing the
// surface detection marks inner layers and puts boundary particles inside the body; at
// half of it the detection kernel sees no neighbours)
static constexpr double SPACING_WARN = 1.1;
static constexpr double SPACING_ERROR = 1.5;

/* ---------------------------------------------------------------------- */

FixESPHBoundary::FixESPHBoundary(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), state(nullptr)
{
  scalar_flag = 1;
  extscalar = 1;
  global_freq = 1;

  spacing = 0.0;
  smooth = 1.0;
  btype = 0;
  mode = GENERATE;
  ncreated = 0;

  int iarg = 3;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "spacing") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary spacing", error);
      spacing = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (spacing <= 0.0)
        error->all(FLERR, iarg + 1, "Fix esph/boundary spacing must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "type") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary type", error);
      btype = utils::expand_type_int(FLERR, arg[iarg + 1], Atom::ATOM, lmp);
      if (btype < 1 || btype > atom->ntypes)
        error->all(FLERR, iarg + 1, "Fix esph/boundary type {} is not a valid atom type (1-{})",
                   arg[iarg + 1], atom->ntypes);
      iarg += 2;
    } else if (strcmp(arg[iarg], "smooth") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary smooth", error);
      smooth = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (smooth < 1.0 || smooth > 3.0)
        error->all(FLERR, iarg + 1, "Fix esph/boundary smooth must be in [1,3] spacings, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "given") == 0) {
      mode = GIVEN;
      iarg += 1;
    } else {
      error->all(FLERR, iarg, "Unknown fix esph/boundary keyword: {}", arg[iarg]);
    }
  }
  if (mode == GENERATE && spacing == 0.0)
    error->all(FLERR, "Fix esph/boundary needs the particle spacing: spacing <value>");
}

/* ----------------------------------------------------------------------
   the state fixes and the boundary particles are created here, not in the
   constructor: Modify is still adding this fix while its constructor runs
------------------------------------------------------------------------- */

void FixESPHBoundary::post_constructor()
{
  state = new ESPHState(lmp);
  if (mode != GENERATE) return;

  state->fetch();
  // zero-mass particles in the group are taken as existing boundary particles (after
  // read_restart or read_data): they must have normals, else they are real particles
  // whose mass was not set
  bigint nzero = 0, nzero_all, ngroup = 0, ngroup_all;
  tagint bad = 0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (atom->mask[i] & groupbit) ngroup++;
    if (!(atom->mask[i] & groupbit) || state->rmass[i] != 0.0) continue;
    nzero++;
    const double *n = state->n[i];
    if (n[0] * n[0] + n[1] * n[1] + n[2] * n[2] < 0.25 && (bad == 0 || atom->tag[i] < bad))
      bad = atom->tag[i] > 0 ? atom->tag[i] : 1;
  }
  MPI_Allreduce(&nzero, &nzero_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  MPI_Allreduce(&ngroup, &ngroup_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  // (all of the group without mass: generate() says so)
  if (nzero_all < ngroup_all)
    ESPHCheck::first_error(lmp, bad,
                           fmt::format("Fix esph/boundary: atom {} in group {} has zero mass but "
                                       "no normal, so it is no boundary particle: set the masses "
                                       "of all real particles before defining this fix",
                                       bad, group->names[igroup]));
  // new boundary particles (not reused ones): the spacing must be the particles' spacing
  if (nzero_all == 0) {
    const double ratio = ESPHCheck::spacing_ratio(lmp, state, groupbit, spacing);
    if (ratio > 0.0) {
      const double off = MAX(ratio, 1.0 / ratio);
      const std::string what = fmt::format("Fix esph/boundary spacing {} but the real particles of "
                                           "group {} are {:.4g} apart (median "
                                           "nearest-neighbour distance, {:.3g} x spacing)",
                                           spacing, group->names[igroup], ratio * spacing, ratio);
      if (off > SPACING_ERROR)
        error->all(FLERR, "{}: set spacing to the particle (lattice) spacing", what);
      if (off > SPACING_WARN && comm->me == 0)
        error->warning(FLERR, "{}: the boundary particles are placed for the given spacing", what);
    }
  }
  generate();
  // what the boundary particles are for: later changes of the bodies are caught in init()
  made_for = ESPHCheck::body_counts(lmp, state, groupbit);
}

/* ---------------------------------------------------------------------- */

FixESPHBoundary::~FixESPHBoundary()
{
  delete state;
}

/* ---------------------------------------------------------------------- */

int FixESPHBoundary::setmask()
{
  return 0;
}

/* ----------------------------------------------------------------------
   check the boundary particles: unit normals, a body, and every body with
   real particles in the group has boundary particles
------------------------------------------------------------------------- */

void FixESPHBoundary::init()
{
  if (!force->pair_match("^esph/solid", 0))
    error->all(FLERR, Error::NOLASTLINE, "Fix esph/boundary requires pair style esph/solid");
  // generated boundary particles belong to the bodies as they were at generation
  if (mode == GENERATE) {
    const auto now = ESPHCheck::body_counts(lmp, state, groupbit);
    if (now != made_for)
      error->all(FLERR, Error::NOLASTLINE,
                 "Fix esph/boundary {} generated its boundary particles for the real particles "
                 "({}) but group {} now holds ({}): define fix esph/boundary after the masses "
                 "and body IDs (i_esph_body) are set, and do not change them afterwards",
                 id, ESPHCheck::format_bodies(made_for), group->names[igroup],
                 ESPHCheck::format_bodies(now));
  }
  state->fetch();
  const int *mask = atom->mask;
  std::vector<int> real_bodies, bnd_bodies;
  tagint bad = 0;
  double badlen = 0.0;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit)) continue;
    if (state->rmass[i] > 0.0) {
      real_bodies.push_back(state->body[i]);
      continue;
    }
    const double *n = state->n[i];
    const double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    if (fabs(n2 - 1.0) > 1.0e-6 && (bad == 0 || atom->tag[i] < bad)) {
      bad = atom->tag[i] > 0 ? atom->tag[i] : 1;
      badlen = sqrt(n2);
    }
    bnd_bodies.push_back(state->body[i]);
  }
  ESPHCheck::first_error(lmp, bad,
                         fmt::format("Boundary particle {} of fix esph/boundary has a normal of "
                                     "length {}, not a unit normal",
                                     bad, badlen));
  real_bodies = ESPHCheck::global_set(lmp, real_bodies);
  bnd_bodies = ESPHCheck::global_set(lmp, bnd_bodies);
  if (bnd_bodies.empty())
    error->all(FLERR, Error::NOLASTLINE, "Fix esph/boundary group {} has no boundary particles",
               group->names[igroup]);
  for (int b : real_bodies)
    if (!std::binary_search(bnd_bodies.begin(), bnd_bodies.end(), b))
      error->all(FLERR, Error::NOLASTLINE,
                 "Body {} has real particles but no boundary particles in fix esph/boundary", b);
  for (int b : bnd_bodies)
    if (!real_bodies.empty() && !std::binary_search(real_bodies.begin(), real_bodies.end(), b))
      error->all(FLERR, Error::NOLASTLINE,
                 "Fix esph/boundary has boundary particles of body {} which has no real particles",
                 b);
}

/* ---------------------------------------------------------------------- */

double FixESPHBoundary::compute_scalar()
{
  state->fetch();
  const int *mask = atom->mask;
  bigint n = 0, total;
  for (int i = 0; i < atom->nlocal; i++)
    if ((mask[i] & groupbit) && state->rmass[i] == 0.0) n++;
  MPI_Allreduce(&n, &total, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  return (double) total;
}

/* ----------------------------------------------------------------------
   generate boundary particles on the surfaces of the bodies in the group.
   A real particle is on the surface when the kernel-weighted centroid of its
   same-body neighbours (support 2 x spacing) is off-centre; its outward
   normal is minus that offset. One boundary particle is placed per surface
   particle at half a spacing outside it (on a face, an edge or a corner of
   a lattice body). All group particles are gathered on every rank once.
------------------------------------------------------------------------- */

void FixESPHBoundary::generate()
{
  state->fetch();
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;

  // existing boundary particles in the group (e.g. after read_restart): reuse them
  bigint nexist = 0, nexist_all;
  for (int i = 0; i < nlocal; i++)
    if ((mask[i] & groupbit) && state->rmass[i] == 0.0) nexist++;
  MPI_Allreduce(&nexist, &nexist_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  bigint ngroup = 0, ngroup_all;
  for (int i = 0; i < nlocal; i++)
    if (mask[i] & groupbit) ngroup++;
  MPI_Allreduce(&ngroup, &ngroup_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nexist_all > 0 && nexist_all == ngroup_all)
    error->all(FLERR,
               "Fix esph/boundary: all {} particles of group {} have zero mass; set the masses "
               "(and body IDs) of the real particles before defining this fix",
               ngroup_all, group->names[igroup]);
  if (nexist_all > 0) {
    if (comm->me == 0)
      utils::logmesg(lmp, "Fix esph/boundary: using {} existing boundary particles\n", nexist_all);
    return;
  }

  // gather x and body of all real group particles
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
    mine.push_back(atom->x[i][0]);
    mine.push_back(atom->x[i][1]);
    mine.push_back(atom->x[i][2]);
    mine.push_back((double) state->body[i]);
  }
  int nmine = mine.size();
  std::vector<int> counts(comm->nprocs), displs(comm->nprocs);
  MPI_Allgather(&nmine, 1, MPI_INT, counts.data(), 1, MPI_INT, world);
  int total = 0;
  for (int p = 0; p < comm->nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  std::vector<double> all(total);
  MPI_Allgatherv(mine.data(), nmine, MPI_DOUBLE, all.data(), counts.data(), displs.data(),
                 MPI_DOUBLE, world);
  const int nall = total / 4;
  if (nall == 0)
    error->all(FLERR, "Fix esph/boundary group {} has no real particles", group->names[igroup]);

  // periodic images near the box faces
  const double cut = ESPH::KERNEL_SUPPORT * spacing;
  const double cutimg = ESPH::KERNEL_SUPPORT * smooth * spacing;
  std::vector<double> pts;
  pts.reserve(all.size());
  const double *lo = domain->boxlo, *hi = domain->boxhi, *prd = domain->prd;
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int k = 0; k < nall; k++) {
    const double *p = &all[4 * k];
    int sh[3][3], ns[3];
    for (int d = 0; d < 3; d++) {
      ns[d] = 0;
      sh[d][ns[d]++] = 0;
      if (per[d] && p[d] < lo[d] + cutimg) sh[d][ns[d]++] = 1;
      if (per[d] && p[d] > hi[d] - cutimg) sh[d][ns[d]++] = -1;
    }
    for (int a = 0; a < ns[0]; a++)
      for (int b = 0; b < ns[1]; b++)
        for (int c = 0; c < ns[2]; c++) {
          pts.push_back(p[0] + sh[0][a] * prd[0]);
          pts.push_back(p[1] + sh[1][b] * prd[1]);
          pts.push_back(p[2] + sh[2][c] * prd[2]);
          pts.push_back(p[3]);
        }
  }
  const int npts = pts.size() / 4;

  // hash grid with cell size = support radius
  auto cellkey = [cut](double x, double y, double z) {
    const long long ix = (long long) floor(x / cut) + (1 << 20);
    const long long iy = (long long) floor(y / cut) + (1 << 20);
    const long long iz = (long long) floor(z / cut) + (1 << 20);
    return (ix << 42) | (iy << 21) | iz;
  };
  std::unordered_map<long long, std::vector<int>> grid;
  for (int k = 0; k < npts; k++)
    grid[cellkey(pts[4 * k], pts[4 * k + 1], pts[4 * k + 2])].push_back(k);

  const int dim = domain->dimension;
  // detection with h = spacing (support 2 spacings: only the outer layer is off-centre);
  // the normal direction from a kernel with h = smooth spacings: 1 (default) is exact on
  // the faces, edges and corners of lattice blocks, a wider kernel averages the staircase
  // of a lattice approximating a curved surface
  const double hn = smooth * spacing;
  const double norm = ESPH::kernel_norm(ESPH::CUBIC, 3, spacing);
  const double normn = ESPH::kernel_norm(ESPH::CUBIC, 3, hn);
  const double hinv = 1.0 / spacing;
  const int reach = (int) ceil(ESPH::KERNEL_SUPPORT * hn / cut);

  std::vector<double> newx, newn;
  std::vector<int> src;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
    const double *xi = atom->x[i];
    const double bi = (double) state->body[i];
    double c[3] = {0.0, 0.0, 0.0}, wsum = 0.0, cn[3] = {0.0, 0.0, 0.0};
    for (int a = -reach; a <= reach; a++)
      for (int b = -reach; b <= reach; b++)
        for (int cc = -reach; cc <= reach; cc++) {
          auto it = grid.find(cellkey(xi[0] + a * cut, xi[1] + b * cut, xi[2] + cc * cut));
          if (it == grid.end()) continue;
          for (int k : it->second) {
            const double *p = &pts[4 * k];
            if (p[3] != bi) continue;
            const double d[3] = {p[0] - xi[0], p[1] - xi[1], p[2] - xi[2]};
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            double w, dw;
            if (ESPH::kernel_eval(ESPH::CUBIC, 3, normn, 1.0 / hn, r, w, dw)) {
              cn[0] += w * d[0];
              cn[1] += w * d[1];
              cn[2] += w * d[2];
            }
            if (!ESPH::kernel_eval(ESPH::CUBIC, 3, norm, hinv, r, w, dw)) continue;
            c[0] += w * d[0];
            c[1] += w * d[1];
            c[2] += w * d[2];
            wsum += w;
          }
        }
    if (dim == 2) c[2] = 0.0;
    const double off = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / wsum;
    if (off < SURFACE_OFFSET * spacing) continue;
    if (dim == 2) cn[2] = 0.0;
    const double len = sqrt(cn[0] * cn[0] + cn[1] * cn[1] + cn[2] * cn[2]);
    if (len == 0.0) continue;
    const double n[3] = {-cn[0] / len, -cn[1] / len, -cn[2] / len};
    // half a spacing outside along each lattice direction the normal points to
    const double nmax = MAX(fabs(n[0]), MAX(fabs(n[1]), fabs(n[2])));
    for (int d = 0; d < 3; d++) {
      newx.push_back(xi[d] + 0.5 * spacing * n[d] / nmax);
      newn.push_back(n[d]);
    }
    src.push_back(i);
  }

  // create the boundary particles; they migrate to their owners at the next setup
  const int nprev = atom->nlocal;
  const int nnew = src.size();
  for (int k = 0; k < nnew; k++) {
    double xnew[3] = {newx[3 * k], newx[3 * k + 1], newx[3 * k + 2]};
    for (int d = 0; d < 3; d++)
      if (!per[d] && (xnew[d] < lo[d] || xnew[d] >= hi[d]))
        error->one(FLERR,
                   "Fix esph/boundary: boundary particle of atom {} at ({} {} {}) lies outside the "
                   "non-periodic box; enlarge the box by half a spacing around the bodies",
                   atom->tag[src[k]], xnew[0], xnew[1], xnew[2]);
    const int s = src[k];
    atom->avec->create_atom(btype > 0 ? btype : atom->type[s], xnew);
  }
  atom->data_fix_compute_variable(nprev, atom->nlocal);
  state->fetch();
  for (int k = 0; k < nnew; k++) {
    const int m = nprev + k;
    const int s = src[k];
    atom->mask[m] = atom->mask[s];
    atom->image[m] = atom->image[s];
    for (int d = 0; d < 3; d++) {
      atom->v[m][d] = atom->v[s][d];
      state->n[m][d] = newn[3 * k + d];
    }
    state->rmass[m] = 0.0;
    state->body[m] = state->body[s];
    state->rho[m] = 0.0;
    state->e[m] = 0.0;
    state->h[m] = state->h[s];
    state->depth[m] = 0.0;
    for (int d = 0; d < 6; d++) state->s[m][d] = 0.0;
  }

  bigint nblocal = atom->nlocal;
  MPI_Allreduce(&nblocal, &atom->natoms, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (atom->tag_enable) atom->tag_extend();
  if (atom->map_style != Atom::MAP_NONE) {
    atom->map_init();
    atom->map_set();
  }
  bigint nn = nnew;
  MPI_Allreduce(&nn, &ncreated, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (comm->me == 0)
    utils::logmesg(lmp, "Fix esph/boundary: created {} boundary particles\n", ncreated);
}
