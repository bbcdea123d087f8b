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
#include "esph_contact.h"
#include "esph_grid.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "force.h"
#include "group.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "region.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <unordered_map>
#include <vector>

using namespace LAMMPS_NS;
using MathConst::MY_PI;
using namespace FixConst;
using ESPH::CellGrid;

enum { GENERATE, GIVEN };

// a particle is on the surface when its kernel-weighted neighbour centroid is off
// by more than this fraction of the spacing (first layer of a cubic lattice: 0.18)
static constexpr double SURFACE_OFFSET = 0.05;
// neighbours closer than this many spacings shape a particle's cell (boundary particle
// placement): the first shell of simple cubic, bcc, fcc and hcp lattices and the face
// diagonals of simple cubic
static constexpr double NEAR_SHELL = 1.5;
// a particle whose nearest neighbours' second moment M has det M < THIN_DET tr^3 and a sum
// of 2x2 principal minors > THIN_PLANE tr^2 has them in a plane, not on a line (a plane:
// det 0, minors >= tr^2 / 4; a line: both 0; a lattice body's inside: det tr^3 / 27)
static constexpr double THIN_DET = 1.0e-6;
static constexpr double THIN_PLANE = 0.01;
// more than this fraction of the particles whose nearest neighbours span the space have no
// simple cubic cell (lattice_frame()): the bodies are not on a simple cubic lattice (on one,
// every particle has its cell; a staircase surface a few percent without)
static constexpr double NONCUBIC_WARN = 0.25;
// keyword region: the surface points searched within this many spacings
static constexpr double REGION_REACH = 3.0;
// ... a boundary particle closer than REGION_ON spacings to the surface is looked at from
// REGION_NUDGE spacings out along its own normal
static constexpr double REGION_ON = 1.0e-6;
static constexpr double REGION_NUDGE = 0.25;
// ... a boundary particle whose real particle lies within REGION_EDGE_REACH spacings of
// two or more of its region's faces (a cylinder's rim, a block's edge) sits at an edge,
// where the nearer face's normal would replace the edge's: it keeps its generated normal
static constexpr double REGION_EDGE_REACH = 0.999;
// ... two faces count as an edge if their normals are more than 30 degrees from parallel
// and from antiparallel (the two faces of a thin wall are no edge)
static constexpr double REGION_EDGE_COS = 0.8660254037844386;
// ... a region's contact is checked this many spacings on either side of its surface point
static constexpr double REGION_CHECK = 1.0e-3;
// ... in 2d a contact whose direction is more than this far (sin of 30 degrees) out of the
// plane is one of the region's z faces, which bound the plane, not the body
static constexpr double REGION_PLANE_SIN = 0.5;
// ... a region other than a sphere that turns a generated normal by more than REGION_EDGE
// degrees elsewhere does not describe the body's surface there: warned
// (fix_esph_boundary.rst, "Normals from regions")
static constexpr double REGION_EDGE = 40.0;
// the spacing keyword against the median nearest-neighbour distance of the real particles:
// a warning beyond SPACING_WARN, an error beyond SPACING_ERROR (at twice the spacing the
// surface detection marks inner layers and puts boundary particles inside the body; at
// half of it the detection kernel sees no neighbours)
static constexpr double SPACING_WARN = 1.1;
static constexpr double SPACING_ERROR = 1.5;
// the surface fit of the normals (keyword fit): off by default (see the doc); boundary
// particles whose first normals differ by 45 degrees or more (an edge, a corner) do not
// enter each other's fit
static constexpr double FIT_DEFAULT = 0.0;
static constexpr double FIT_COS = 0.70710678118654752;    // cos 45 degrees
// a neighbourhood whose spread across is below FIT_LINE_LO of its spread along (a line:
// the boundary particles of an edge) keeps its first normal, one above FIT_LINE_HI is a
// face and takes the fitted one; in between they are blended
static constexpr double FIT_LINE_LO = 0.1;
static constexpr double FIT_LINE_HI = 0.3;

/* ---------------------------------------------------------------------- */

FixESPHBoundary::FixESPHBoundary(LAMMPS *lmp, int narg, char **arg) :
    Fix(lmp, narg, arg), state(nullptr)
{
  scalar_flag = 1;
  create_attribute = 1;
  extscalar = 1;
  global_freq = 1;

  spacing = 0.0;
  noncubic_found = 0;
  reused = 0;
  smooth = 1.0;
  fit = FIT_DEFAULT;
  btype = 0;
  mode = GENERATE;
  turn_body = 0;
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
    } else if (strcmp(arg[iarg], "fit") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary fit", error);
      fit = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (fit != 0.0 && (fit < 2.0 || fit > 16.0))
        error->all(FLERR, iarg + 1,
                   "Fix esph/boundary fit must be 0 (off) or in [2,16] spacings, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "region") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary region", error);
      Region *region = domain->get_region_by_id(arg[iarg + 1]);
      if (!region)
        error->all(FLERR, iarg + 1, "Fix esph/boundary region {} does not exist", arg[iarg + 1]);
      if (region->openflag)
        error->all(FLERR, iarg + 1,
                   "Fix esph/boundary region {} has open faces (region keyword open): its "
                   "surface does not bound the body cut from it there; use the region without "
                   "open faces",
                   arg[iarg + 1]);
      if (region->dynamic_check())
        error->all(FLERR, iarg + 1,
                   "Fix esph/boundary region {} must be static (no move, rotate or variable "
                   "shape): its surface gives the normals when the boundary particles are made",
                   arg[iarg + 1]);
      region_ids.emplace_back(arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "turn") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "fix esph/boundary turn", error);
      if (strcmp(arg[iarg + 1], "spin") == 0)
        turn_body = 0;
      else if (strcmp(arg[iarg + 1], "body") == 0)
        turn_body = 1;
      else
        error->all(FLERR, iarg + 1,
                   "Fix esph/boundary turn {} is unknown: expected spin (the normals turn with "
                   "the spin around them) or body (with their body's rigid spin)",
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
  if (mode == GIVEN && !region_ids.empty())
    error->all(FLERR,
               "Fix esph/boundary region sets the normals of the boundary particles it makes; "
               "with given they come with the particles (d2_esph_n): drop one of the two");
}

/* ----------------------------------------------------------------------
   a new atom (create_atoms, read_data add, ...) starts with the ESPH state of
   an atom in a fresh box (also without fix esph/integrate; the boundary
   particles made here are set after)
------------------------------------------------------------------------- */

void FixESPHBoundary::set_arrays(int i)
{
  if (state) state->clear_atom(i);
}

/* ----------------------------------------------------------------------
   the state fixes and the boundary particles are created here, not in the
   constructor: Modify is still adding this fix while its constructor runs
------------------------------------------------------------------------- */

void FixESPHBoundary::post_constructor()
{
  state = new ESPHState(lmp);
  if (mode != GENERATE) {
    bnd_for = ESPHCheck::body_counts(lmp, state, groupbit, true);
    return;
  }

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
    if (ratio == ESPHCheck::ISOLATED)
      error->all(FLERR,
                 "Fix esph/boundary spacing {}: most real particles of group {} have no "
                 "particle of their own body within {} x spacing; a body is a cloud of particles "
                 "about one spacing apart (a body of a single particle has no surface): set "
                 "spacing to the particle (lattice) spacing, or give the bodies more particles",
                 spacing, group->names[igroup], ESPHCheck::MAX_RATIO);
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
  bnd_for = ESPHCheck::body_counts(lmp, state, groupbit, true);
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
                 "({}) but group {} now holds ({}): real particles were deleted, lost or given "
                 "other masses or body IDs (i_esph_body) since. Define fix esph/boundary after "
                 "the masses and body IDs are set; after delete_atoms or lost atoms, define it "
                 "again (unfix, then fix) to take the bodies as they are now, with their "
                 "boundary particles",
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
  for (int b : real_bodies) {
    if (std::binary_search(bnd_bodies.begin(), bnd_bodies.end(), b)) continue;
    if (reused > 0)
      error->all(FLERR, Error::NOLASTLINE,
                 "Body {} has real particles but no boundary particles in fix esph/boundary: "
                 "the fix found {} boundary particles in group {} and uses them (it makes "
                 "none when some exist), and none is of body {} (a body added since they were "
                 "made?): delete the existing boundary particles (a group of the zero-mass "
                 "particles, delete_atoms) before defining the fix, so that it makes them for "
                 "every body",
                 b, reused, group->names[igroup], b);
    error->all(FLERR, Error::NOLASTLINE,
               "Body {} has real particles but no boundary particles in fix esph/boundary "
               "(a body gets them where its particles have a surface: a single particle has "
               "no surface; give the body more particles or its boundary particles with "
               "given)",
               b);
  }
  for (int b : bnd_bodies)
    if (!real_bodies.empty() && !std::binary_search(real_bodies.begin(), real_bodies.end(), b))
      error->all(FLERR, Error::NOLASTLINE,
                 "Fix esph/boundary has boundary particles of body {} which has no real particles",
                 b);
  // a body that keeps real particles keeps all of its boundary particles: one deleted or
  // lost leaves a hole in its surface, through which other bodies pass unseen
  {
    const auto bnow = ESPHCheck::body_counts(lmp, state, groupbit, true);
    const auto rnow = ESPHCheck::body_counts(lmp, state, groupbit);
    for (const auto &kv : bnd_for) {
      const auto b = bnow.find(kv.first);
      const bigint have = (b == bnow.end()) ? 0 : b->second;
      if (have >= kv.second || rnow.find(kv.first) == rnow.end()) continue;
      error->all(FLERR, Error::NOLASTLINE,
                 "Fix esph/boundary {}: body {} has {} of the {} boundary particles it had when "
                 "the fix was defined: boundary particles were deleted or lost (delete_atoms?), "
                 "and its surface has holes there, through which other bodies pass. Delete all "
                 "boundary particles (a group of the zero-mass particles, delete_atoms), then "
                 "define fix esph/boundary again (unfix, then fix) to make them anew",
                 id, kv.first, have, kv.second);
    }
  }
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
   particle, half a spacing outside it along its normal: on a flat face of
   any orientation that is the face itself; edges and corners are rounded
   with radius half a spacing. Everything depends on the particles and the
   spacing only, never on the box axes.
   Distributed: each rank works on its own particles and receives from the
   other ranks only those within the search reach of its own (a halo),
   so memory per rank is O(N/P). The neighbour sums run over an integer
   cell grid anchored at the box origin, cell by cell in a fixed order and
   within a cell in the order of atom IDs, so that the boundary particles are
   the same, bit for bit, on any number of ranks.
------------------------------------------------------------------------- */

namespace {
struct Pt {
  double x[3];
  tagint tag;
  int body;
};
}    // namespace

/* ----------------------------------------------------------------------
   the position p and its periodic images within reach of a periodic box face
   (up to 27): returns their number, the positions in img. A triclinic box's
   faces are those of its parallelepiped: the distance to them and the shifts
   between images are the box vectors' (a shift across y moves x by xy), so
   the images come from the fractional coordinates
------------------------------------------------------------------------- */

static int periodic_images(Domain *domain, const double *p, double reach, double img[][3])
{
  const double *lo = domain->boxlo, *hi = domain->boxhi, *prd = domain->prd;
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  int sh[3][3], ns[3];
  // (triclinic) the distance to a face in fractional units: reach times the length of the
  // row of h_inv that gives that fraction (as LAMMPS's communication cutoff of a triclinic box)
  double lam[3] = {0.0, 0.0, 0.0}, len[3] = {0.0, 0.0, 0.0};
  if (domain->triclinic) {
    double x[3] = {p[0], p[1], p[2]};
    domain->x2lamda(x, lam);
    const double *hinv = domain->h_inv;
    len[0] = sqrt(hinv[0] * hinv[0] + hinv[5] * hinv[5] + hinv[4] * hinv[4]);
    len[1] = sqrt(hinv[1] * hinv[1] + hinv[3] * hinv[3]);
    len[2] = hinv[2];
  }
  for (int d = 0; d < 3; d++) {
    ns[d] = 0;
    sh[d][ns[d]++] = 0;
    if (!per[d]) continue;
    const bool nearlo = domain->triclinic ? lam[d] < reach * len[d] : p[d] < lo[d] + reach;
    const bool nearhi = domain->triclinic ? lam[d] > 1.0 - reach * len[d] : p[d] > hi[d] - reach;
    if (nearlo) sh[d][ns[d]++] = 1;
    if (nearhi) sh[d][ns[d]++] = -1;
  }
  // the box vectors (h: xprd, yprd, zprd, yz, xz, xy)
  const double *h = domain->h;
  const double A[3] = {prd[0], 0.0, 0.0};
  const double B[3] = {domain->triclinic ? h[5] : 0.0, prd[1], 0.0};
  const double C[3] = {domain->triclinic ? h[4] : 0.0, domain->triclinic ? h[3] : 0.0, prd[2]};
  int n = 0;
  for (int a = 0; a < ns[0]; a++)
    for (int b = 0; b < ns[1]; b++)
      for (int c = 0; c < ns[2]; c++, n++)
        for (int d = 0; d < 3; d++)
          img[n][d] = p[d] + sh[0][a] * A[d] + sh[1][b] * B[d] + sh[2][c] * C[d];
  return n;
}

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
               "(and body IDs) of the real particles before defining this fix{}",
               ngroup_all, group->names[igroup], ESPHCheck::type_mass_hint(lmp));
  // boundary particles of the group's bodies outside the group (e.g. a fix on the real
  // particles alone after read_restart): a second surface would be made on top of them
  {
    std::vector<int> gbodies;
    for (int i = 0; i < nlocal; i++)
      if ((mask[i] & groupbit) && state->rmass[i] > 0.0) gbodies.push_back(state->body[i]);
    gbodies = ESPHCheck::global_set(lmp, gbodies);
    tagint out = MAXTAGINT;
    for (int i = 0; i < nlocal; i++)
      if (!(mask[i] & groupbit) && state->rmass[i] == 0.0 &&
          std::binary_search(gbodies.begin(), gbodies.end(), state->body[i]))
        out = MIN(out, atom->tag[i]);
    tagint out_all;
    MPI_Allreduce(&out, &out_all, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (out_all != MAXTAGINT)
      error->all(FLERR,
                 "Fix esph/boundary: atom {}, a boundary particle (zero mass) of a body of group "
                 "{}, is not in the group: the fix would make a second surface on top of the "
                 "existing one. Define the fix on a group that holds the boundary particles "
                 "too (e.g. all), and it uses them; or delete them first",
                 out_all, group->names[igroup]);
  }
  std::vector<double> newx, newn;
  std::vector<int> src;
  if (nexist_all > 0) {
    if (comm->me == 0)
      utils::logmesg(lmp, "Fix esph/boundary: using {} existing boundary particles\n", nexist_all);
    reused = nexist_all;
    // (the warnings on the arrangement of the bodies, as for a generation)
    find_surface(newx, newn, src);
    check_counts();
    return;
  }
  find_surface(newx, newn, src);
  if (fit > 0.0) fit_normals(newx, newn, src);
  if (!region_ids.empty()) region_normals(newx, newn, src);

  // create the boundary particles; they migrate to their owners at the next setup
  const double *lo = domain->boxlo, *hi = domain->boxhi;
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
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
    state->gap[m] = ESPH::GAP_NONE;
    state->gapv[m] = 0.0;
    state->eng[m] = 0.0;
    for (int d = 0; d < 6; d++) state->s[m][d] = 0.0;
  }

  // each boundary particle records how many its body was made with (check_counts())
  const auto made = ESPHCheck::body_counts(lmp, state, groupbit, true);
  for (int k = 0; k < nnew; k++) {
    const int m = nprev + k;
    state->depth[m] = (double) made.at(state->body[m]);
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

/* ----------------------------------------------------------------------
   the root of atom ID t in the union-find up (t added as a piece of its
   own when new), the paths on the way pointed at it
------------------------------------------------------------------------- */

static tagint piece_root(std::unordered_map<tagint, tagint> &up, tagint t)
{
  tagint r = up.emplace(t, t).first->second;
  while (up[r] != r) r = up[r];
  while (up[t] != r) {
    const tagint next = up[t];
    up[t] = r;
    t = next;
  }
  return r;
}

/* ----------------------------------------------------------------------
   the surface particles of the group's real particles (detection of
   generate()): for each, where its boundary particle goes (newx), its
   normal (newn) and the particle (src); the warnings on the arrangement
   (sheets one particle thick, another lattice, a body in pieces)
------------------------------------------------------------------------- */

void FixESPHBoundary::find_surface(std::vector<double> &newx, std::vector<double> &newn,
                                   std::vector<int> &src)
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const int dim = domain->dimension;
  const double cut = ESPH::KERNEL_SUPPORT * spacing;     // detection support
  const double hn = smooth * spacing;                    // normal kernel h
  const double reach_len = ESPH::KERNEL_SUPPORT * hn;    // >= cut (smooth >= 1)
  const double *lo = domain->boxlo, *hi = domain->boxhi, *prd = domain->prd;
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};

  // own real particles of the group, with their periodic images near the box faces
  std::vector<Pt> pts;
  bigint nreal = 0;
  double blo[3] = {1.0e300, 1.0e300, 1.0e300}, bhi[3] = {-1.0e300, -1.0e300, -1.0e300};
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
    nreal++;
    const double *p = atom->x[i];
    double img[27][3];
    const int nimg = periodic_images(domain, p, reach_len, img);
    for (int m = 0; m < nimg; m++) {
      Pt q;
      for (int d = 0; d < 3; d++) q.x[d] = img[m][d];
      q.tag = atom->tag[i];
      q.body = state->body[i];
      pts.push_back(q);
    }
    for (int d = 0; d < 3; d++) {
      blo[d] = MIN(blo[d], p[d]);
      bhi[d] = MAX(bhi[d], p[d]);
    }
  }
  bigint nreal_all;
  MPI_Allreduce(&nreal, &nreal_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
  if (nreal_all == 0)
    error->all(FLERR, "Fix esph/boundary group {} has no real particles", group->names[igroup]);

  // halo: every rank receives the points within the search reach of its own particles
  {
    std::vector<double> mine;
    mine.reserve(5 * pts.size());
    for (const auto &q : pts)
      mine.insert(mine.end(), {q.x[0], q.x[1], q.x[2], (double) q.tag, (double) q.body});
    const auto got = halo_exchange(mine, 5, blo, bhi, reach_len);
    for (size_t k = 0; k < got.size(); k += 5) {
      Pt q;
      q.x[0] = got[k];
      q.x[1] = got[k + 1];
      q.x[2] = got[k + 2];
      q.tag = (tagint) got[k + 3];
      q.body = (int) got[k + 4];
      pts.push_back(q);
    }
  }

  // integer cell grid, cell = detection support
  CellGrid grid(lo, cut);
  grid.build(
      pts.size(),
      [&pts](int k) {
        return pts[k].x;
      },
      [&pts](int k) {
        return pts[k].tag;
      });

  // detection with h = spacing (support 2 spacings: only the outer layer is off-centre);
  // the normal direction from a kernel with h = smooth spacings: 1 (default) is exact on
  // the faces, edges and corners of lattice blocks, a wider kernel averages the staircase
  // of a lattice approximating a curved surface
  const double norm = ESPH::kernel_norm(ESPH::CUBIC, 3, spacing);
  const double normn = ESPH::kernel_norm(ESPH::CUBIC, 3, hn);
  const double hinv = 1.0 / spacing;
  const int reach = (int) ceil(reach_len / cut);

  std::vector<double> nearest, planar;
  // the pieces of the bodies: union-find of the real particles (by atom ID) over their nearest
  // neighbours of the same body, the root of a piece its smallest ID (check_pieces())
  std::unordered_map<tagint, tagint> up;
  auto join = [&up](tagint a, tagint b) {
    const tagint ra = piece_root(up, a), rb = piece_root(up, b);
    if (ra < rb) up[rb] = ra;
    if (rb < ra) up[ra] = rb;
  };
  bigint nthin = 0;
  tagint thin_tag = 0;
  // particles whose nearest neighbours span the space, and those of them without a simple
  // cubic (2d: square) cell (lattice_frame()): another lattice or an irregular cloud
  bigint nspan = 0, noncubic = 0;
  tagint noncubic_tag = 0;
  double frame[9];
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
    const double *xi = atom->x[i];
    const int bi = state->body[i];
    long long ci[3];
    grid.cell_of(xi, ci);
    double c[3] = {0.0, 0.0, 0.0}, wsum = 0.0, cn[3] = {0.0, 0.0, 0.0};
    nearest.clear();
    for (int a = -reach; a <= reach; a++)
      for (int b = -reach; b <= reach; b++)
        for (int cc = -reach; cc <= reach; cc++) {
          const std::vector<int> *cell = grid.at(ci, a, b, cc);
          if (!cell) continue;
          for (int k : *cell) {
            const Pt &p = pts[k];
            if (p.body != bi) continue;
            const double d[3] = {p.x[0] - xi[0], p.x[1] - xi[1], p.x[2] - xi[2]};
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            if (r > 0.0 && r < NEAR_SHELL * spacing) {
              nearest.insert(nearest.end(), {d[0], d[1], d[2]});
              join(atom->tag[i], p.tag);
            }
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
    // in 3D a particle whose nearest neighbours of its body all lie in one plane, not on
    // one line (a chain is the 1D model), is in a sheet one particle thick: its two faces
    // need two boundary particles, and it makes at most one (none inside the sheet, where
    // the neighbours balance): counted for a warning
    // (the same second moment says whether the neighbours span the space: only there is a
    // missing cubic cell another lattice, not a chain, a sheet or a lone particle)
    // (in 2d their offsets in the plane: a periodic z of one spacing adds the particle's
    // own images straight above and below)
    const std::vector<double> *nb = &nearest;
    if (dim == 2) {
      planar.clear();
      for (size_t k = 0; k < nearest.size(); k += 3)
        if (nearest[k] != 0.0 || nearest[k + 1] != 0.0)
          planar.insert(planar.end(), {nearest[k], nearest[k + 1], 0.0});
      nb = &planar;
    }
    if (nb->size() >= 3 * (size_t) dim) {
      double m[3][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
      for (size_t k = 0; k < nb->size(); k += 3)
        for (int a = 0; a < 3; a++)
          for (int b = 0; b < 3; b++) m[a][b] += (*nb)[k + a] * (*nb)[k + b];
      const double det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
      const double tr = m[0][0] + m[1][1] + m[2][2];
      const double minors = m[0][0] * m[1][1] - m[0][1] * m[1][0] + m[0][0] * m[2][2] -
          m[0][2] * m[2][0] + m[1][1] * m[2][2] - m[1][2] * m[2][1];
      const bool spans = (dim == 3) ? det >= THIN_DET * tr * tr * tr
                                    : m[0][0] * m[1][1] - m[0][1] * m[1][0] > THIN_PLANE * tr * tr;
      if (dim == 3 && !spans && minors > THIN_PLANE * tr * tr) {
        if (!nthin) thin_tag = atom->tag[i];
        nthin++;
      }
      if (spans) {
        nspan++;
        if (!ESPH::lattice_frame(nb->data(), nb->size() / 3, spacing, dim, frame)) {
          if (!noncubic) noncubic_tag = atom->tag[i];
          noncubic++;
        }
      }
    }
    if (dim == 2) c[2] = 0.0;
    const double off = sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) / wsum;
    if (off < SURFACE_OFFSET * spacing) continue;
    if (dim == 2) cn[2] = 0.0;
    const double len = sqrt(cn[0] * cn[0] + cn[1] * cn[1] + cn[2] * cn[2]);
    if (len == 0.0) continue;
    const double n[3] = {-cn[0] / len, -cn[1] / len, -cn[2] / len};
    // where the ray along the normal leaves the particle's Voronoi cell among its nearest
    // neighbours and their mirror images through it (the missing neighbours outside):
    // cell faces at |d|^2 / (2 n.d). On a lattice body that is the lattice cell of the
    // particle (a cube on a simple cubic lattice, in any orientation), so faces of the
    // body stay flat up to its edges and corners
    double t = HUGE_VAL;
    for (size_t k = 0; k < nearest.size(); k += 3) {
      const double *d = &nearest[k];
      const double nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
      if (nd == 0.0) continue;
      const double dd = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
      // the neighbour itself (n.d > 0) or its mirror image (n.d < 0)
      t = MIN(t, dd / (2.0 * fabs(nd)));
    }
    if (t > spacing) t = (t == HUGE_VAL) ? 0.5 * spacing : spacing;
    for (int d = 0; d < 3; d++) {
      newx.push_back(xi[d] + t * n[d]);
      newn.push_back(n[d]);
    }
    src.push_back(i);
  }

  check_pieces(up, blo, bhi, reach_len);
  {
    bigint thin_all;
    MPI_Allreduce(&nthin, &thin_all, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    tagint tmine = nthin ? thin_tag : MAXTAGINT, tfirst;
    MPI_Allreduce(&tmine, &tfirst, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    if (thin_all > 0 && comm->me == 0)
      error->warning(FLERR,
                     "Fix esph/boundary: {} real particles (e.g. atom {}) lie in a layer one "
                     "particle thick, whose faces get no boundary particles: other bodies meet "
                     "such a layer at its edges only and pass through its faces; build sheets, "
                     "rods and plates at least two particles thick",
                     thin_all, tfirst);
  }
  {
    bigint counts[2] = {nspan, noncubic}, counts_all[2];
    MPI_Allreduce(counts, counts_all, 2, MPI_LMP_BIGINT, MPI_SUM, world);
    tagint tmine = noncubic ? noncubic_tag : MAXTAGINT, tfirst;
    MPI_Allreduce(&tmine, &tfirst, 1, MPI_LMP_TAGINT, MPI_MIN, world);
    noncubic_found = counts_all[1] > NONCUBIC_WARN * counts_all[0];
    if (noncubic_found && comm->me == 0)
      error->warning(FLERR,
                     "Fix esph/boundary: {} of {} real particles of group {} (e.g. atom {}) have "
                     "no {} neighbourhood ({} nearly normal neighbours about one spacing away): "
                     "the bodies are on another lattice (fcc, bcc, hcp, hex) or irregular. The "
                     "boundary particles are placed where the cell of a {} lattice of spacing "
                     "{} ends, and the contact's touch uses such cells: on other arrangements "
                     "contact starts away from where the surfaces meet (fcc cubes face to face: "
                     "0.3 spacings early) and edges meeting edges can pass through each other. "
                     "Build the bodies with lattice {}, or give the boundary particles with "
                     "keyword given",
                     counts_all[1], counts_all[0], group->names[igroup], tfirst,
                     dim == 3 ? "simple cubic" : "square", dim == 3 ? "three" : "two",
                     dim == 3 ? "simple cubic" : "square", spacing, dim == 3 ? "sc" : "sq");
  }
}

/* ----------------------------------------------------------------------
   a body in pieces: the real particles of a body that no chain of nearest
   neighbours (within NEAR_SHELL spacings) joins. Each piece gets its smallest
   atom ID, from the pieces on this rank (the union-find up of its own
   particles and those of the halo, find_surface()) and those of the ranks
   around, exchanged until no label changes (collective). Pieces of one body
   that meet interact as one body, without the contact rule: a WARNING
------------------------------------------------------------------------- */

void FixESPHBoundary::check_pieces(std::unordered_map<tagint, tagint> &up, const double *blo,
                                   const double *bhi, double reach)
{
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  // the smallest ID known for each piece (by its root here)
  std::unordered_map<tagint, tagint> label;
  auto label_of = [&](tagint t) {
    const tagint r = piece_root(up, t);
    return label.emplace(r, r).first->second;
  };
  while (true) {
    std::vector<double> mine;
    for (int i = 0; i < nlocal; i++) {
      if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
      double img[27][3];
      const int nimg = periodic_images(domain, atom->x[i], reach, img);
      const tagint lab = label_of(atom->tag[i]);
      for (int m = 0; m < nimg; m++)
        mine.insert(mine.end(),
                    {img[m][0], img[m][1], img[m][2], (double) atom->tag[i], (double) lab});
    }
    const auto got = halo_exchange(mine, 5, blo, bhi, reach);
    int changed = 0, changed_all;
    for (size_t k = 0; k < got.size(); k += 5) {
      const auto t = (tagint) got[k + 3];
      if (up.find(t) == up.end()) continue;
      const auto lab = (tagint) got[k + 4];
      const tagint r = piece_root(up, t);
      tagint &cur = label.emplace(r, r).first->second;
      if (lab < cur) {
        cur = lab;
        changed = 1;
      }
    }
    MPI_Allreduce(&changed, &changed_all, 1, MPI_INT, MPI_MAX, world);
    if (!changed_all) break;
  }
  // a body is in one piece when all its particles have the same label: the smallest and the
  // largest label over each body
  std::map<int, std::pair<tagint, tagint>> range;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] <= 0.0) continue;
    const tagint lab = label_of(atom->tag[i]);
    auto it = range.emplace(state->body[i], std::make_pair(lab, lab)).first;
    it->second.first = MIN(it->second.first, lab);
    it->second.second = MAX(it->second.second, lab);
  }
  std::vector<int> keys;
  for (const auto &kv : range) keys.push_back(kv.first);
  const std::vector<int> bodies = ESPHCheck::global_set(lmp, keys);
  const int nb = bodies.size();
  std::vector<tagint> lo(nb, MAXTAGINT), hi(nb, 0), lo_all(nb), hi_all(nb);
  for (int k = 0; k < nb; k++) {
    auto it = range.find(bodies[k]);
    if (it == range.end()) continue;
    lo[k] = it->second.first;
    hi[k] = it->second.second;
  }
  MPI_Allreduce(lo.data(), lo_all.data(), nb, MPI_LMP_TAGINT, MPI_MIN, world);
  MPI_Allreduce(hi.data(), hi_all.data(), nb, MPI_LMP_TAGINT, MPI_MAX, world);
  std::string list;
  int nbodies = 0;
  for (int k = 0; k < nb; k++) {
    if (lo_all[k] == hi_all[k]) continue;
    if (nbodies++ < 3)
      list += fmt::format("{}body {} (atoms {} and {} in two of them)", nbodies > 1 ? "; " : "",
                          bodies[k], lo_all[k], hi_all[k]);
  }
  if (nbodies > 0 && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/boundary: {} of group {} in pieces that no particles within {} "
                   "spacings of each other join: {}. Pieces of one body interact as one "
                   "body when they meet, with no contact between them (no contact time, force "
                   "or rebound of their own); give each piece its own body ID (i_esph_body)",
                   nbodies > 1 ? fmt::format("{} bodies", nbodies) : std::string("a body"),
                   group->names[igroup], NEAR_SHELL, list);
}

/* ----------------------------------------------------------------------
   existing boundary particles that the fix uses (none made): each body
   must still have as many as it was made with, which every boundary
   particle records in d_esph_depth (generate(); 0: not known, e.g. given
   ones or those of older files). One deleted or lost leaves a hole in the
   surface, through which other bodies pass (collective; an ERROR). The
   count, not the places: a body that deformed keeps its boundary
   particles where the run took them, and continues as it would have
------------------------------------------------------------------------- */

void FixESPHBoundary::check_counts()
{
  const int *mask = atom->mask;
  std::map<int, double> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(mask[i] & groupbit) || state->rmass[i] != 0.0) continue;
    double &rec = mine[state->body[i]];
    rec = MAX(rec, state->depth[i]);
  }
  std::vector<int> keys;
  for (const auto &kv : mine) keys.push_back(kv.first);
  const std::vector<int> bodies = ESPHCheck::global_set(lmp, keys);
  std::vector<double> rec(bodies.size(), 0.0), rec_all(bodies.size(), 0.0);
  for (size_t k = 0; k < bodies.size(); k++) {
    auto it = mine.find(bodies[k]);
    if (it != mine.end()) rec[k] = it->second;
  }
  MPI_Allreduce(rec.data(), rec_all.data(), (int) rec.size(), MPI_DOUBLE, MPI_MAX, world);
  const auto bnow = ESPHCheck::body_counts(lmp, state, groupbit, true);
  const auto rnow = ESPHCheck::body_counts(lmp, state, groupbit);
  for (size_t k = 0; k < bodies.size(); k++) {
    const int b = bodies[k];
    const bigint have = bnow.count(b) ? bnow.at(b) : 0;
    if (!(rec_all[k] > 0.0) || have >= (bigint) rec_all[k] || !rnow.count(b)) continue;
    error->all(FLERR,
               "Fix esph/boundary: body {} has {} of the {} boundary particles it was made with "
               "(d_esph_depth of a boundary particle records that number): the fix uses the {} "
               "boundary particles it found and makes none, so the surface has holes there "
               "(boundary particles deleted or lost), through which other bodies pass. Delete "
               "all boundary particles (a group of the zero-mass particles, delete_atoms) before "
               "defining the fix, so that it makes them anew",
               b, have, (bigint) rec_all[k], reused);
  }
}

/* ----------------------------------------------------------------------
   records of stride values each (the first three a position) of all ranks:
   returns those of the other ranks within reach of the bounding box
   [blo, bhi] of this rank's own ones (an empty box receives nothing)
------------------------------------------------------------------------- */

std::vector<double> FixESPHBoundary::halo_exchange(const std::vector<double> &mine, int stride,
                                                   const double *blo, const double *bhi,
                                                   double reach)
{
  const int nprocs = comm->nprocs;
  std::vector<double> rbuf;
  if (nprocs == 1) return rbuf;
  std::vector<double> box(6 * nprocs);
  const double me[6] = {blo[0] - reach, blo[1] - reach, blo[2] - reach,
                        bhi[0] + reach, bhi[1] + reach, bhi[2] + reach};
  MPI_Allgather(me, 6, MPI_DOUBLE, box.data(), 6, MPI_DOUBLE, world);
  std::vector<std::vector<double>> out(nprocs);
  for (size_t k = 0; k < mine.size(); k += stride) {
    const double *x = &mine[k];
    for (int p = 0; p < nprocs; p++) {
      if (p == comm->me) continue;
      const double *b = &box[6 * p];
      if (x[0] < b[0] || x[0] > b[3] || x[1] < b[1] || x[1] > b[4] || x[2] < b[2] || x[2] > b[5])
        continue;
      out[p].insert(out[p].end(), x, x + stride);
    }
  }
  std::vector<int> scount(nprocs), rcount(nprocs), sdispl(nprocs), rdispl(nprocs);
  for (int p = 0; p < nprocs; p++) scount[p] = out[p].size();
  MPI_Alltoall(scount.data(), 1, MPI_INT, rcount.data(), 1, MPI_INT, world);
  int stot = 0, rtot = 0;
  for (int p = 0; p < nprocs; p++) {
    sdispl[p] = stot;
    rdispl[p] = rtot;
    stot += scount[p];
    rtot += rcount[p];
  }
  std::vector<double> sbuf(stot);
  rbuf.resize(rtot);
  for (int p = 0; p < nprocs; p++) std::copy(out[p].begin(), out[p].end(), sbuf.data() + sdispl[p]);
  MPI_Alltoallv(sbuf.data(), scount.data(), sdispl.data(), MPI_DOUBLE, rbuf.data(), rcount.data(),
                rdispl.data(), MPI_DOUBLE, world);
  return rbuf;
}

/* ----------------------------------------------------------------------
   a contact of region r with point p (its surface point p - del) that is
   what it claims: finite, of nonzero length, and with its surface point
   between p's side of the region's shape and the other side (checked at
   eps on either side); dir = del / |del|, len = |del| (-1 when not finite)
   LAMMPS's cones with a zero radius end or along y and its unions return
   contacts that are not
------------------------------------------------------------------------- */

static bool region_contact(Region *r, const double *p, const Region::Contact &ct, double eps,
                           double *dir, double &len)
{
  len = sqrt(ct.delx * ct.delx + ct.dely * ct.dely + ct.delz * ct.delz);
  if (!std::isfinite(len)) len = -1.0;
  if (len <= 0.0) return false;
  dir[0] = ct.delx / len;
  dir[1] = ct.dely / len;
  dir[2] = ct.delz / len;
  const int side = r->inside(p[0], p[1], p[2]);
  const double s[3] = {p[0] - ct.delx, p[1] - ct.dely, p[2] - ct.delz};
  const int toward = r->inside(s[0] + eps * dir[0], s[1] + eps * dir[1], s[2] + eps * dir[2]);
  const int beyond = r->inside(s[0] - eps * dir[0], s[1] - eps * dir[1], s[2] - eps * dir[2]);
  return toward == side && beyond != side;
}

/* ----------------------------------------------------------------------
   region_contact() that is not, in 2d, one of the region's z faces (zface:
   they bound the plane, not the body)
------------------------------------------------------------------------- */

static bool region_face(Region *r, const double *p, const Region::Contact &ct, double eps, int dim,
                        double *dir, double &len, bool &zface)
{
  const bool ok = region_contact(r, p, ct, eps, dir, len);
  zface = ok && dim == 2 && fabs(dir[2]) > REGION_PLANE_SIN;
  return ok && !zface;
}

/* ----------------------------------------------------------------------
   real particle xs at an edge of region r: two or more of its faces within
   a spacing of it (from inside), not parallel (the two faces of a thin wall are
   no edge), a face through the particle itself counting as one of unknown
   direction; in 2d only the faces across the plane count (the region's z
   faces bound the plane, not the body). dirs: scratch
------------------------------------------------------------------------- */

static bool region_edge(Region *r, const double *xs, double spacing, int dim,
                        std::vector<std::array<double, 3>> &dirs)
{
  const double eps = REGION_CHECK * spacing;
  double p[3] = {xs[0], xs[1], xs[2]};
  const int nc = r->inside(p[0], p[1], p[2]) ? r->surface_interior(p, REGION_EDGE_REACH * spacing)
                                             : 0;
  dirs.clear();
  int nunknown = 0;
  for (int c = 0; c < nc; c++) {
    double dir[3], len;
    bool zface;
    if (region_face(r, p, r->contact[c], eps, dim, dir, len, zface))
      dirs.push_back({dir[0], dir[1], dir[2]});
    else if (!zface && len >= 0.0 && len <= REGION_ON * spacing)
      nunknown++;    // a face through the particle itself: its direction is unknown
  }
  if (nunknown > 0 && dirs.size() + nunknown >= 2) return true;
  for (size_t a = 0; a < dirs.size(); a++)
    for (size_t b = a + 1; b < dirs.size(); b++)
      if (fabs(dirs[a][0] * dirs[b][0] + dirs[a][1] * dirs[b][1] + dirs[a][2] * dirs[b][2]) <
          REGION_EDGE_COS)
        return true;
  return false;
}

/* ----------------------------------------------------------------------
   keyword region: the normal of a boundary particle whose real particle
   lies in one of the regions (the first that holds it) is the outward
   normal of that region's surface at the surface point nearest to the
   boundary particle, i.e. the gradient of the distance to the surface:
   radial for a sphere, a face's normal beside it, rounded over an edge or
   a corner. The positions stay the ones generate() made. At an edge of
   the region (its real particle within a spacing of two of the region's
   faces: a cylinder's rim, a block's edge) a boundary particle keeps its
   generated normal: the nearer face's normal would replace the edge's
   there, and two cylinders side on would touch at once. A boundary
   particle with no surface point of its region within 3 spacings keeps
   its normal; those, and those more than a spacing from the surface, are
   counted for a warning (the region does not describe that body's surface)
------------------------------------------------------------------------- */

void FixESPHBoundary::region_normals(const std::vector<double> &bx, std::vector<double> &bn,
                                     const std::vector<int> &src)
{
  std::vector<Region *> regions;
  for (const auto &id : region_ids) {
    Region *region = domain->get_region_by_id(id);
    if (!region) error->all(FLERR, "Fix esph/boundary region {} does not exist any more", id);
    region->prematch();
    regions.push_back(region);
  }
  double **x = atom->x;
  const int dim = domain->dimension;
  const double cutoff = REGION_REACH * spacing;
  const double eps = REGION_CHECK * spacing;
  bigint nset = 0, nfar = 0, nnone = 0, nedge = 0, nkept = 0;
  double maxturn = 0.0;
  std::vector<std::array<double, 3>> dirs;
  const int n = src.size();
  for (int k = 0; k < n; k++) {
    const double *xs = x[src[k]];
    Region *region = nullptr;
    for (auto *r : regions)
      if (r->match(xs[0], xs[1], xs[2])) {
        region = r;
        break;
      }
    if (!region) continue;
    // at an edge of the region: the generated normal
    if (region_edge(region, xs, spacing, dim, dirs)) {
      nkept++;
      continue;
    }
    // the nearest surface point: from outside the region's shape, or from inside (a
    // boundary particle of a staircase can lie inside the region it was cut from); a
    // particle on the surface itself (a lattice face, e.g. of touching blocks) is looked at
    // from a quarter spacing out along its own normal, where the nearest point is the same.
    // The body's outward normal is the shape's, reversed for a region with side out
    double nr[3] = {0.0, 0.0, 0.0}, dist = 0.0;
    bool found = false;
    for (int attempt = 0; attempt < 2 && !found; attempt++) {
      const double out = attempt ? REGION_NUDGE * spacing : 0.0;
      double p[3];
      for (int d = 0; d < 3; d++) p[d] = bx[3 * k + d] + out * bn[3 * k + d];
      const int in = region->inside(p[0], p[1], p[2]);
      const int nc = in ? region->surface_interior(p, cutoff) : region->surface_exterior(p, cutoff);
      const double sign = (in ? -1.0 : 1.0) * (region->interior ? 1.0 : -1.0);
      double best = -1.0;
      bool onsurf = false;
      for (int c = 0; c < nc; c++) {
        double dir[3], len;
        bool zface;
        const bool ok = region_face(region, p, region->contact[c], eps, dim, dir, len, zface);
        if (len >= 0.0 && len <= REGION_ON * spacing) onsurf = true;
        if (!ok || (best >= 0.0 && len >= best)) continue;
        best = len;
        for (int d = 0; d < 3; d++) nr[d] = sign * dir[d];
      }
      // on the surface: the direction is undefined there, look again from outside
      found = !onsurf && best > 0.0;
      dist = best;
    }
    if (!found) {
      nnone++;
      continue;
    }
    // more than a spacing from the surface: the region is not this body's surface there
    if (dist > spacing) {
      nfar++;
      continue;
    }
    double *nk = &bn[3 * k];
    const double dot = nk[0] * nr[0] + nk[1] * nr[1] + nk[2] * nr[2];
    const double turn = acos(MAX(-1.0, MIN(1.0, dot)));
    maxturn = MAX(maxturn, turn);
    if (strcmp(region->style, "sphere") != 0 && turn > REGION_EDGE * MY_PI / 180.0) nedge++;
    for (int d = 0; d < 3; d++) nk[d] = nr[d];
    nset++;
  }
  bigint loc[5] = {nset, nfar, nnone, nedge, nkept}, all[5];
  MPI_Allreduce(loc, all, 5, MPI_LMP_BIGINT, MPI_SUM, world);
  double turn;
  MPI_Allreduce(&maxturn, &turn, 1, MPI_DOUBLE, MPI_MAX, world);
  if (comm->me == 0) {
    utils::logmesg(lmp,
                   "Fix esph/boundary: {} boundary particles took the normals of region(s) {} "
                   "(turned by up to {:.3g} degrees), {} at the regions' edges kept their own\n",
                   all[0], utils::join_words(region_ids, " "), turn * 180.0 / MY_PI, all[4]);
    if (all[1] > 0 || all[2] > 0)
      error->warning(FLERR,
                     "Fix esph/boundary: {} boundary particles lie more than a spacing from the "
                     "surface of the region that holds their body particle, and {} have none of "
                     "it within {} spacings (they keep their own normals): a region must be the "
                     "one the body was created from, where the body still is, and a body cut by "
                     "a periodic boundary needs a box a whole number of spacings long",
                     all[1], all[2], REGION_REACH);
    if (all[3] > 0)
      error->warning(FLERR,
                     "Fix esph/boundary: the regions' normals turned {} boundary particles by "
                     "more than {} degrees from their generated normals away from the regions' "
                     "edges: a region there does not follow the surface of the body cut from it "
                     "(check the region, or use the generated normals: no region keyword)",
                     all[3], REGION_EDGE);
  }
}

/* ----------------------------------------------------------------------
   the normals of the new boundary particles (positions bx, first normals bn,
   own ones of this rank) refined by the weighted least-squares sphere or
   plane through the boundary particles of the same body within fit spacings
   that passes through the particle: on a staircase (a lattice cut at an angle
   or to a curved shape) the first normals follow the steps, the fitted
   surface follows the face, the sphere, the cylinder. The weight of particle m in the fit of
   particle k is W(|x_m - x_k|) ((n_k.n_m - cos 45) / (1 - cos 45))^2 for
   n_k.n_m > cos 45 (first normals; cubic spline of support fit spacings), so
   that the faces meeting at an edge or corner are fitted apart. The fitted
   normal is found by inverse iteration from the first normal, continuous in
   the particles also where the spread across is nearly isotropic; a
   neighbourhood that is a line rather than a patch (the boundary particles
   along an edge) keeps its first normal. Sums in the fixed order of the
   integer cell grid and of atom IDs: the same on any number of ranks.
------------------------------------------------------------------------- */

void FixESPHBoundary::fit_normals(const std::vector<double> &bx, std::vector<double> &bn,
                                  const std::vector<int> &src)
{
  const int dim = domain->dimension;
  const double rfit = fit * spacing;
  const double *lo = domain->boxlo;
  const int nown = src.size();

  // records x (3), first normal (3), atom ID of the source particle, body; periodic
  // images of the own ones near the box faces
  constexpr int S = 8;
  std::vector<double> rec;
  double blo[3] = {1.0e300, 1.0e300, 1.0e300}, bhi[3] = {-1.0e300, -1.0e300, -1.0e300};
  for (int k = 0; k < nown; k++) {
    const double *p = &bx[3 * k];
    const double *n = &bn[3 * k];
    for (int d = 0; d < 3; d++) {
      blo[d] = MIN(blo[d], p[d]);
      bhi[d] = MAX(bhi[d], p[d]);
    }
    double img[27][3];
    const int nimg = periodic_images(domain, p, rfit, img);
    for (int m = 0; m < nimg; m++)
      rec.insert(rec.end(),
                 {img[m][0], img[m][1], img[m][2], n[0], n[1], n[2], (double) atom->tag[src[k]],
                  (double) state->body[src[k]]});
  }
  const auto got = halo_exchange(rec, S, blo, bhi, rfit);
  rec.insert(rec.end(), got.begin(), got.end());
  const int nrec = rec.size() / S;

  // integer cell grid of cell size rfit
  CellGrid grid(lo, rfit);
  grid.build(
      nrec,
      [&rec](int k) {
        return &rec[S * k];
      },
      [&rec](int k) {
        return rec[S * k + 6];
      });

  const double norm = ESPH::kernel_norm(ESPH::CUBIC, 3, 0.5 * rfit);
  const double hinv = 2.0 / rfit;
  for (int k = 0; k < nown; k++) {
    const double *xk = &bx[3 * k];
    const Eigen::Vector3d n0(bn[3 * k], bn[3 * k + 1], bn[3 * k + 2]);
    const int body = state->body[src[k]];
    long long ck[3];
    grid.cell_of(xk, ck);
    // weighted moments of the offsets d and of q = |d|^2
    double s0 = 0.0, sq = 0.0, sqq = 0.0;
    Eigen::Vector3d s1 = Eigen::Vector3d::Zero(), spq = Eigen::Vector3d::Zero();
    Eigen::Matrix3d s2 = Eigen::Matrix3d::Zero();
    for (int a = -1; a <= 1; a++)
      for (int b = -1; b <= 1; b++)
        for (int c = -1; c <= 1; c++) {
          const std::vector<int> *cell = grid.at(ck, a, b, c);
          if (!cell) continue;
          for (int m : *cell) {
            const double *q = &rec[S * m];
            if ((int) q[7] != body) continue;
            const double agree = n0(0) * q[3] + n0(1) * q[4] + n0(2) * q[5];
            if (agree <= FIT_COS) continue;
            Eigen::Vector3d d(q[0] - xk[0], q[1] - xk[1], q[2] - xk[2]);
            if (dim == 2) d(2) = 0.0;
            const double r2 = d.squaredNorm();
            double w, dw;
            if (!ESPH::kernel_eval(ESPH::CUBIC, 3, norm, hinv, sqrt(r2), w, dw)) continue;
            const double t = (agree - FIT_COS) / (1.0 - FIT_COS);
            w *= t * t;
            s0 += w;
            s1 += w * d;
            s2 += w * d * d.transpose();
            sq += w * r2;
            spq += w * r2 * d;
            sqq += w * r2 * r2;
          }
        }
    if (s0 <= 0.0) continue;
    const Eigen::Vector3d mean = s1 / s0;
    const Eigen::Matrix3d C = s2 / s0 - mean * mean.transpose();
    // the sphere (or plane) u4 |d|^2 + u.d + u0 = 0 through the own boundary particle
    // (d = 0) with unit normal u there that fits best: with u0 and u4 eliminated the
    // residual is u^T (C - c c^T / v) u, c = cov(d, |d|^2), v = var(|d|^2); exact for
    // any plane and any sphere
    const Eigen::Vector3d cpq = spq / s0 - mean * (sq / s0);
    const double vqq = sqq / s0 - (sq / s0) * (sq / s0);
    Eigen::Matrix3d F = C;
    if (vqq > 1.0e-12 * C.trace() * C.trace()) F -= cpq * cpq.transpose() / vqq;
    double blend = 1.0;
    if (dim == 2) {
      // the surface is a line in the xy plane: the normal stays in it
      F(0, 2) = F(1, 2) = F(2, 0) = F(2, 1) = 0.0;
      F(2, 2) = C.trace();
    } else {
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
      es.computeDirect(C, Eigen::EigenvaluesOnly);
      const Eigen::Vector3d lam = es.eigenvalues();
      const double q = lam(2) > 0.0 ? lam(1) / lam(2) : 0.0;
      const double t = MAX(0.0, MIN(1.0, (q - FIT_LINE_LO) / (FIT_LINE_HI - FIT_LINE_LO)));
      blend = t * t * (3.0 - 2.0 * t);
    }
    if (blend <= 0.0) continue;
    const double eps = 1.0e-6 * C.trace() + 1.0e-30 * spacing * spacing;
    const Eigen::LDLT<Eigen::Matrix3d> solver(F + eps * Eigen::Matrix3d::Identity());
    Eigen::Vector3d v = n0;
    for (int iter = 0; iter < 3; iter++) v = solver.solve(v).normalized();
    const Eigen::Vector3d nn = (blend * v + (1.0 - blend) * n0).normalized();
    for (int d = 0; d < 3; d++) bn[3 * k + d] = nn(d);
  }
}
