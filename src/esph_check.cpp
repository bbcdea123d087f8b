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

#include "esph_check.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_bodies.h"
#include "esph_eos.h"
#include "esph_state.h"
#include "esph_units.h"
#include "fix.h"
#include "modify.h"
#include "neigh_list.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <unordered_map>

using namespace LAMMPS_NS;

// tolerance of a unit normal: |n|^2 within this of 1 (rotation keeps it to round-off)
static constexpr double UNIT_TOL = 1.0e-6;
// bins per spacing of the nearest-neighbour histogram (median to 0.1 %)
static constexpr int NN_BINS = 1000;

/* ---------------------------------------------------------------------- */

void ESPHCheck::first_error(LAMMPS *lmp, tagint tag, const std::string &msg)
{
  MPI_Comm world = lmp->world;
  // tags are >= 1; a rank without an offending atom competes with the largest value
  bigint mine = (tag > 0) ? (bigint) tag : MAXBIGINT, best;
  MPI_Allreduce(&mine, &best, 1, MPI_LMP_BIGINT, MPI_MIN, world);
  if (best == MAXBIGINT) return;
  // without atom IDs (all 0) several ranks may hold one: the lowest rank reports
  int me = lmp->comm->me, nprocs = lmp->comm->nprocs;
  int candidate = (mine == best) ? me : nprocs, owner;
  MPI_Allreduce(&candidate, &owner, 1, MPI_INT, MPI_MIN, world);
  int len = (me == owner) ? (int) msg.size() : 0;
  MPI_Bcast(&len, 1, MPI_INT, owner, world);
  std::string text(len, ' ');
  if (me == owner) text = msg;
  MPI_Bcast(&text[0], len, MPI_CHAR, owner, world);
  lmp->error->all(FLERR, Error::NOLASTLINE, text);
}

/* ---------------------------------------------------------------------- */

bool ESPHCheck::any_atom(LAMMPS *lmp, const std::function<bool(int)> &pred)
{
  int mine = 0, any = 0;
  for (int i = 0; i < lmp->atom->nlocal && !mine; i++) mine = pred(i) ? 1 : 0;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, lmp->world);
  return any != 0;
}

/* ---------------------------------------------------------------------- */

template <typename T>
static std::vector<T> union_all(LAMMPS *lmp, std::vector<T> v, MPI_Datatype type)
{
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  const int nprocs = lmp->comm->nprocs;
  int n = v.size();
  std::vector<int> counts(nprocs), displs(nprocs);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, lmp->world);
  int total = 0;
  for (int p = 0; p < nprocs; p++) {
    displs[p] = total;
    total += counts[p];
  }
  std::vector<T> all(total);
  MPI_Allgatherv(v.data(), n, type, all.data(), counts.data(), displs.data(), type, lmp->world);
  std::sort(all.begin(), all.end());
  all.erase(std::unique(all.begin(), all.end()), all.end());
  return all;
}

std::vector<int> ESPHCheck::global_set(LAMMPS *lmp, std::vector<int> v)
{
  return union_all(lmp, std::move(v), MPI_INT);
}

std::vector<long long> ESPHCheck::global_set(LAMMPS *lmp, std::vector<long long> v)
{
  return union_all(lmp, std::move(v), MPI_LONG_LONG);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::body_shapes(LAMMPS *lmp, ESPHState *state, int groupbit, std::vector<int> &bodies,
                            std::vector<double> &shape)
{
  bodies.clear();
  shape.clear();
  if (!state->body) return;
  for (const auto &kv : body_counts(lmp, state, groupbit)) bodies.push_back(kv.first);
  std::vector<double> ref, sum;
  ESPH::body_reference(lmp, state, groupbit, bodies, ref);
  ESPH::body_sums(lmp, state, groupbit, bodies, lmp->atom->v, 0, ref, sum);
  for (size_t k = 0; k < bodies.size(); k++) {
    const ESPH::BodyMotion b = ESPH::body_motion(sum.data() + ESPH::BODY_NSUM * k);
    const double *S = b.S;
    Eigen::Matrix3d m;
    m << S[0], S[3], S[4], S[3], S[1], S[5], S[4], S[5], S[2];
    const Eigen::Vector3d e =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(m, Eigen::EigenvaluesOnly).eigenvalues();
    shape.insert(shape.end(), {b.M, e[0], e[1], e[2]});
  }
}

/* ----------------------------------------------------------------------
   a change of the second moment's eigenvalues by more than SHAPE_TOL of
   the largest: a strain of about SHAPE_TOL / 2. An impact strains a body
   by 1e-3 and more; rotations and translations (displace_atoms move,
   rotate) change them by round-off only, a jitter of a hundredth of a
   spacing of 10^4 particles by about 1e-6
------------------------------------------------------------------------- */

static constexpr double SHAPE_TOL = 1.0e-4;

void ESPHCheck::check_shapes(LAMMPS *lmp, ESPHState *state, int groupbit,
                             const std::vector<int> &bodies_then,
                             const std::vector<double> &shape_then)
{
  if (bodies_then.empty()) return;
  std::vector<int> bodies;
  std::vector<double> shape;
  body_shapes(lmp, state, groupbit, bodies, shape);
  int nchanged = 0, first = 0;
  double worst = 0.0;
  for (size_t k = 0; k < bodies.size(); k++) {
    const auto it = std::lower_bound(bodies_then.begin(), bodies_then.end(), bodies[k]);
    if (it == bodies_then.end() || *it != bodies[k]) continue;
    const double *now = &shape[SHAPE_NVAL * k];
    const double *then = &shape_then[SHAPE_NVAL * (it - bodies_then.begin())];
    // (particles added or deleted: another body, not a moved one)
    if (fabs(now[0] - then[0]) > 1.0e-12 * then[0] || !(then[3] > 0.0)) continue;
    double change = 0.0;
    for (int e = 1; e < SHAPE_NVAL; e++) change = MAX(change, fabs(now[e] - then[e]) / then[3]);
    if (change > SHAPE_TOL) {
      if (!nchanged) {
        first = bodies[k];
        worst = change;
      }
      nchanged++;
    }
  }
  if (nchanged && lmp->comm->me == 0)
    lmp->error->warning(FLERR,
                        "Fix esph/integrate: {} bod{} changed shape since the last run without "
                        "a step (body {}: second moment by {:.3g} %): its particles were moved "
                        "without their state (change_box ... remap, displace_atoms ramp or "
                        "random, set x), so its density and stress still describe the old "
                        "shape. Move bodies between runs only rigidly (displace_atoms move or "
                        "rotate), or create them anew",
                        nchanged, nchanged > 1 ? "ies" : "y", first, 100.0 * worst);
}

std::string ESPHCheck::type_mass_hint(LAMMPS *lmp)
{
  const Atom *atom = lmp->atom;
  if (atom->mass && atom->mass_setflag)
    for (int t = 1; t <= atom->ntypes; t++)
      if (atom->mass_setflag[t])
        return " (the mass command sets masses per type, which ESPH does not use: it keeps a "
               "mass per particle; set them with set group ... mass)";
  return "";
}

std::map<int, bigint> ESPHCheck::body_counts(LAMMPS *lmp, ESPHState *state, int groupbit,
                                             bool boundary)
{
  state->fetch();
  const int *mask = lmp->atom->mask;
  std::map<int, bigint> local;
  for (int i = 0; i < lmp->atom->nlocal; i++)
    if ((mask[i] & groupbit) && ((state->rmass[i] > 0.0) != boundary)) local[state->body[i]]++;
  std::vector<int> mine;
  for (const auto &kv : local) mine.push_back(kv.first);
  const std::vector<int> bodies = global_set(lmp, mine);
  std::vector<bigint> n(bodies.size(), 0), total(bodies.size(), 0);
  for (size_t k = 0; k < bodies.size(); k++) {
    auto it = local.find(bodies[k]);
    if (it != local.end()) n[k] = it->second;
  }
  MPI_Allreduce(n.data(), total.data(), (int) n.size(), MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  std::map<int, bigint> counts;
  for (size_t k = 0; k < bodies.size(); k++) counts[bodies[k]] = total[k];
  return counts;
}

/* ---------------------------------------------------------------------- */

std::string ESPHCheck::format_bodies(const std::map<int, bigint> &counts)
{
  static constexpr int SHOWN = 6;
  std::string s;
  int k = 0;
  for (const auto &kv : counts) {
    if (k == SHOWN) {
      s += fmt::format(", ... ({} bodies)", counts.size());
      break;
    }
    s += fmt::format("{}body {}: {}", k ? ", " : "", kv.first, kv.second);
    k++;
  }
  return s.empty() ? "none" : s;
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::state(LAMMPS *lmp, ESPHState *st, const ESPH::EOS *eos, double hlimit,
                      const ESPH::Units &units)
{
  Atom *atom = lmp->atom;
  st->fetch();
  const tagint *tag = atom->tag;
  const int *type = atom->type;
  double **x = atom->x, **v = atom->v;
  const double *rmass = st->rmass;
  tagint bad = 0;
  std::string msg;
  auto finite3 = [](const double *a) {
    return std::isfinite(a[0]) && std::isfinite(a[1]) && std::isfinite(a[2]);
  };

  for (int i = 0; i < atom->nlocal; i++) {
    const tagint t = tag[i];
    if (bad > 0 && t >= bad) continue;
    std::string m;
    const double mi = rmass[i];
    if (!std::isfinite(mi)) {
      m = fmt::format("Atom {} has mass {}: not a finite number", t, mi);
    } else if (mi < 0.0) {
      m = fmt::format("Atom {} has negative mass {}", t, mi);
    } else if (!finite3(x[i])) {
      m = fmt::format("Atom {} has position ({} {} {}): not finite", t, x[i][0], x[i][1], x[i][2]);
    } else if (!finite3(v[i])) {
      m = fmt::format("Atom {} has velocity ({} {} {}): not finite (velocity create divides by "
                      "the zero mass of boundary particles: apply it to the real particles only)",
                      t, v[i][0], v[i][1], v[i][2]);
    } else if (mi == 0.0) {
      // boundary particle
      const double *n = st->n[i];
      const double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
      if (!(n2 >= 0.25))
        m = fmt::format("Atom {} has zero mass but no boundary normal: zero-mass particles must "
                        "be boundary particles of fix esph/boundary{}",
                        t, type_mass_hint(lmp));
      else if (fabs(n2 - 1.0) > UNIT_TOL)
        m = fmt::format("Boundary particle {} has a normal of length {}, not a unit normal", t,
                        sqrt(n2));
    } else {
      const double rho = st->rho[i], h = st->h[i], e = st->e[i];
      const double *s = st->s[i];
      if (!(rho > 0.0) || !std::isfinite(rho)) {
        m = fmt::format("Atom {} has density d_esph_rho = {}: it must be > 0 and finite", t, rho);
      } else if (!(h > 0.0) || !std::isfinite(h)) {
        m = fmt::format("Atom {} has smoothing length d_esph_h = {}: it must be > 0 and finite", t,
                        h);
      } else if (h > hlimit * (1.0 + 1.0e-12)) {
        m = fmt::format("Atom {} has smoothing length {} larger than the pair esph/solid cutoff "
                        "allows ({}): increase hvar",
                        t, h, hlimit);
      } else if (!std::isfinite(e)) {
        m = fmt::format("Atom {} has internal energy d_esph_e = {}: not finite", t, e);
      } else {
        for (int k = 0; k < 6 && m.empty(); k++)
          if (!std::isfinite(s[k]))
            m = fmt::format("Atom {} has stress d2_esph_s[{}] = {}: not finite", t, k + 1, s[k]);
        if (m.empty() && st->epsp && (!(st->epsp[i] >= 0.0) || !std::isfinite(st->epsp[i])))
          m = fmt::format("Atom {} has plastic strain d_esph_epsp = {}: it must be >= 0 and "
                          "finite",
                          t, st->epsp[i]);
        if (m.empty()) {
          double P, c2;
          eos[type[i]].compute(rho, e * units.energy_in, P, c2);
          P *= units.pressure;
          if (!std::isfinite(P) || !(c2 > 0.0) || !std::isfinite(c2))
            m = fmt::format("Atom {} (type {}) has no sound speed: its EOS gives P = {} and c^2 = "
                            "{} at density {} and energy {}; the state is outside the EOS",
                            t, type[i], P, c2, rho, e);
        }
      }
    }
    if (!m.empty()) {
      bad = (t > 0) ? t : 1;
      msg = m;
    }
  }
  first_error(lmp, bad, msg);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::pairs(LAMMPS *lmp, ESPHState *st, NeighList *list, double cutsq, double h0,
                      int kdim, double spacing)
{
  const int *body = st->body;
  const double rover = (spacing > 0.0 && body) ? OVERLAP * spacing : 0.0;
  double close = rover * rover;
  tagint close_i = 0, close_j = 0;
  double **x = lmp->atom->x;
  const tagint *tag = lmp->atom->tag;
  const double *rmass = st->rmass;
  const int boxdim = lmp->domain->dimension;
  const double rmin = COINCIDENT * h0, offmax = OFF_DIMENSION * h0;
  tagint bad = 0;
  std::string msg;

  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    if (!(rmass[i] > 0.0)) continue;
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      if (!(rmass[j] > 0.0)) continue;
      const double dx[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq) continue;
      if (rover > 0.0 && body[i] != body[j] && rsq < close) {
        close = rsq;
        close_i = MIN(tag[i], tag[j]);
        close_j = MAX(tag[i], tag[j]);
      }
      const tagint t = MIN(tag[i], tag[j]) > 0 ? MIN(tag[i], tag[j]) : 1;
      if (bad > 0 && t >= bad) continue;
      if (rsq < rmin * rmin) {
        bad = t;
        msg = fmt::format("Atoms {} and {} are at the same position ({} {} {}, distance {}): "
                          "coincident particles make the SPH sums singular; delete one of them",
                          MIN(tag[i], tag[j]), MAX(tag[i], tag[j]), x[i][0], x[i][1], x[i][2],
                          sqrt(rsq));
        continue;
      }
      for (int d = kdim; d < boxdim; d++)
        if (fabs(dx[d]) > offmax) {
          bad = t;
          msg = fmt::format("Pair esph/solid dimension {}: neighbouring atoms {} and {} are {:.6g} "
                            "apart in {}, but a {}D kernel needs the bodies on {}; use dimension "
                            "{} for bodies that extend in {}",
                            kdim, MIN(tag[i], tag[j]), MAX(tag[i], tag[j]), fabs(dx[d]), "xyz"[d],
                            kdim, kdim == 1 ? "a line along x" : "the xy plane", boxdim, "xyz"[d]);
          break;
        }
    }
  }
  first_error(lmp, bad, msg);
  if (rover == 0.0) return;
  // the closest pair of real particles of different bodies, if closer than rover
  struct {
    double r;
    int rank;
  } mine = {close, lmp->comm->me}, all;
  MPI_Allreduce(&mine, &all, 1, MPI_DOUBLE_INT, MPI_MINLOC, lmp->world);
  if (!(all.r < rover * rover)) return;
  tagint pair_tags[2] = {close_i, close_j};
  MPI_Bcast(pair_tags, 2, MPI_LMP_TAGINT, all.rank, lmp->world);
  if (lmp->comm->me == 0)
    lmp->error->warning(FLERR,
                        "Pair esph/solid: real particles {} and {} of different bodies are {:.3g} "
                        "spacings apart at the start of the run: the bodies overlap (touching "
                        "bodies are a spacing apart) and push apart from a state no contact "
                        "reaches, or at rest stay inside each other; build them apart or "
                        "touching",
                        pair_tags[0], pair_tags[1], sqrt(all.r) / spacing);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::contact_bodies(LAMMPS *lmp, ESPHState *st, const char *rule)
{
  st->fetch();
  std::vector<int> real, bnd;
  for (int i = 0; i < lmp->atom->nlocal; i++) {
    if (st->rmass[i] > 0.0)
      real.push_back(st->body[i]);
    else
      bnd.push_back(st->body[i]);
  }
  real = global_set(lmp, real);
  if (real.size() < 2) return;
  bnd = global_set(lmp, bnd);
  std::string have;
  for (int b : bnd) have += fmt::format("{}{}", have.empty() ? "" : " ", b);
  for (int b : real)
    if (!std::binary_search(bnd.begin(), bnd.end(), b))
      lmp->error->all(FLERR, Error::NOLASTLINE,
                      "Pair esph/solid contact {}: body {} has real particles but no boundary "
                      "particles (bodies with boundary particles: {}); define fix esph/boundary "
                      "on a group that holds every body, or use contact off",
                      rule, b, have.empty() ? "none" : have);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::integrators(LAMMPS *lmp, Fix *fix_int, int move)
{
  const int *mask = lmp->atom->mask;
  const int nlocal = lmp->atom->nlocal;
  int moved = 0;
  for (const auto &f : lmp->modify->get_fix_list()) {
    // a second fix esph/integrate has its own error (fix esph/integrate init)
    if (f == fix_int || !f->time_integrate || utils::strmatch(f->style, "^esph/integrate"))
      continue;
    const int both = f->groupbit | fix_int->groupbit;
    int mine = 0, any;
    for (int i = 0; i < nlocal && !mine; i++)
      if ((mask[i] & both) == both) mine = 1;
    MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, lmp->world);
    if (any && move)
      lmp->error->all(FLERR, Error::NOLASTLINE,
                      "Fix {} (style {}) also integrates the motion of atoms of fix "
                      "esph/integrate {}: the particles would be moved twice per step; remove fix "
                      "{}, or use fix esph/integrate ... move no to let it alone move them",
                      f->id, f->style, fix_int->id, f->id);
    moved |= any;
  }
  if (!move && !moved && lmp->comm->me == 0)
    lmp->error->warning(FLERR,
                        "Fix esph/integrate {} has move no but no other fix moves its atoms: "
                        "the particles stay where they are (use move yes, or add e.g. fix move)",
                        fix_int->id);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::rigid_bodies(LAMMPS *lmp, ESPHState *st, Fix *fix_int, const int *rigid)
{
  const int *mask = lmp->atom->mask;
  const int *type = lmp->atom->type;
  const tagint *tag = lmp->atom->tag;
  const int nlocal = lmp->atom->nlocal;
  st->fetch();
  tagint bad = 0;
  std::string msg;
  std::vector<int> rbodies, dbodies;
  for (int i = 0; i < nlocal; i++) {
    if (!(st->rmass[i] > 0.0)) continue;
    if (!rigid[type[i]]) {
      dbodies.push_back(st->body[i]);
      continue;
    }
    rbodies.push_back(st->body[i]);
    if ((mask[i] & fix_int->groupbit) && (bad == 0 || tag[i] < bad)) {
      bad = tag[i];
      msg = fmt::format("Atom {} of rigid type {} (pair_coeff ... rigid yes) is in the group "
                        "of fix esph/integrate {}: a rigid body is not integrated; leave it out "
                        "of that group and move it with e.g. fix move, or leave it at rest",
                        tag[i], type[i], fix_int->id);
    }
  }
  first_error(lmp, bad, msg);
  const auto r = global_set(lmp, rbodies);
  const auto d = global_set(lmp, dbodies);
  std::vector<int> both;
  std::set_intersection(r.begin(), r.end(), d.begin(), d.end(), std::back_inserter(both));
  if (!both.empty())
    lmp->error->all(FLERR, Error::NOLASTLINE,
                    "Body {} (i_esph_body) has real particles of rigid and of deformable "
                    "types: give a rigid body (pair_coeff ... rigid yes) a body ID of its own",
                    both[0]);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::volumes(LAMMPS *lmp, ESPHState *st, const ESPH::EOS *eos,
                        const std::function<double(int)> &spacing_of, int dim)
{
  Atom *atom = lmp->atom;
  st->fetch();
  const int *type = atom->type;
  const double off[2] = {DENSITY_OFF, VOLUME_OFF};
  // count, smallest and largest ratio of the particles off: density, volume
  bigint n[2] = {0, 0}, nall[2];
  double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, loall[2], hiall[2];
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(st->rmass[i] > 0.0) || !(st->rho[i] > 0.0)) continue;
    // (the spacing of the particle's body: 0 without fix esph/boundary)
    const double spacing = spacing_of(st->body ? st->body[i] : 0);
    const double vol0 = (spacing > 0.0) ? pow(spacing, dim) : 0.0;
    const double rho0 = eos[type[i]].rho0;
    const double r[2] = {st->rho[i] / rho0, vol0 > 0.0 ? st->rmass[i] / rho0 / vol0 : 1.0};
    for (int k = 0; k < 2; k++)
      if (r[k] > off[k] || r[k] < 1.0 / off[k]) {
        n[k]++;
        lo[k] = MIN(lo[k], r[k]);
        hi[k] = MAX(hi[k], r[k]);
      }
  }
  MPI_Allreduce(n, nall, 2, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  MPI_Allreduce(lo, loall, 2, MPI_DOUBLE, MPI_MIN, lmp->world);
  MPI_Allreduce(hi, hiall, 2, MPI_DOUBLE, MPI_MAX, lmp->world);
  if (lmp->comm->me != 0) return;
  if (nall[0] > 0)
    lmp->error->warning(FLERR,
                        "{} real particles start the run with a density d_esph_rho of {:.3g} to "
                        "{:.3g} x the rho0 of their type (a strain of that size is no elastic "
                        "state): pair_coeff rho0 changed for particles that exist, or d_esph_rho "
                        "set by hand; set d_esph_rho (and the masses) for the new rho0",
                        nall[0], loall[0], hiall[0]);
  if (nall[1] > 0)
    lmp->error->warning(FLERR,
                        "{} real particles have a reference volume m / rho0 of {:.3g} to {:.3g} "
                        "x spacing^{} of fix esph/boundary (on a simple cubic lattice it is "
                        "spacing^{}): a particle's mass is rho0 x spacing^{} of its type in the "
                        "mass unit of the units style, the spacing the lattice's; another mass "
                        "makes the material as much stiffer or softer, which the time step "
                        "does not see",
                        nall[1], loall[1], hiall[1], dim, dim, dim);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::smoothing_length(LAMMPS *lmp, double h0, double hmax, int hvar_flag, double spacing)
{
  if (!(spacing > 0.0)) return;
  Error *error = lmp->error;
  const double ratio = h0 / spacing;
  if (ratio > H_ERROR)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid smoothing length h = {} is {:.4g} x the particle spacing {} of "
               "fix esph/boundary; expected 1 to 2 spacings, at most {:g} (the kernel reaches "
               "2 h): set h to about 1.3 x the spacing, {:.4g}",
               h0, ratio, spacing, H_ERROR, 1.3 * spacing);
  if (hvar_flag && ratio * hmax > H_ERROR)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid hvar {}: the smoothing length may grow to h x hvar = {:.4g}, "
               "{:.4g} x the particle spacing {} of fix esph/boundary (the neighbour cutoff is "
               "2 h x hvar); expected h x hvar of at most {:g} spacings: hvar is the largest "
               "expected h/h0, usually 1.2 to 2",
               hmax, h0 * hmax, ratio * hmax, spacing, H_ERROR);
  // the kernel reaches 2 h: at h <= spacing / 2 a particle has no neighbour at all
  if (!(ratio > H_NONE))
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid smoothing length h = {} is {:.4g} x the particle spacing {} of "
               "fix esph/boundary: the kernel reaches 2 h, so no particle has a neighbour and "
               "each body falls apart into free particles; expected 1 to 2 spacings (h is "
               "not the cutoff: that is 2 h): set h to about 1.3 x the spacing, {:.4g}",
               h0, ratio, spacing, 1.3 * spacing);
  if (ratio < H_LOW && lmp->comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid smoothing length h = {} is {:.4g} x the particle spacing {} "
                   "of fix esph/boundary; 1 to 2 spacings is usual: with 2 h below two spacings "
                   "a particle sees only its nearest neighbours and the solid is far off (h = "
                   "0.6 spacings: two blocks' rebound 2.75 m/s instead of 4.54). Set h to about "
                   "1.3 x the spacing, {:.4g}, unless meant",
                   h0, ratio, spacing, 1.3 * spacing);
  if (ratio > H_WARN && lmp->comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid smoothing length h = {} is {:.4g} x the particle spacing {} "
                   "of fix esph/boundary; 1 to 2 spacings is usual (a larger h smooths over more "
                   "particles at a higher cost): set h to about 1.3 x the spacing, {:.4g}, unless "
                   "meant",
                   h0, ratio, spacing, 1.3 * spacing);
}

/* ---------------------------------------------------------------------- */

void ESPHCheck::unintegrated(LAMMPS *lmp, ESPHState *st, Fix *fix_int, const int *rigid)
{
  const int *mask = lmp->atom->mask;
  const int *type = lmp->atom->type;
  const tagint *tag = lmp->atom->tag;
  const int nlocal = lmp->atom->nlocal;
  st->fetch();
  // a rigid particle, or one of a deformable type outside the group of fix esph/integrate,
  // that has a velocity no fix applies: the contact sees it move while it stays in place
  // (a deformable block left out of the group with a velocity pumped an impactor from 50
  // to 89 m/s)
  std::vector<int> movers;
  for (const auto &f : lmp->modify->get_fix_list())
    if (f != fix_int && f->time_integrate) movers.push_back(f->groupbit);
  const double *const *v = lmp->atom->v;
  tagint still[2] = {MAXTAGINT, MAXTAGINT};    // rigid, deformable outside the group
  for (int i = 0; i < nlocal; i++) {
    if (!(st->rmass[i] > 0.0)) continue;
    const int k = rigid[type[i]] ? 0 : 1;
    if (k == 1 && (mask[i] & fix_int->groupbit)) continue;
    if (v[i][0] == 0.0 && v[i][1] == 0.0 && v[i][2] == 0.0) continue;
    bool moved = false;
    for (int gb : movers) moved = moved || (mask[i] & gb);
    if (!moved) still[k] = MIN(still[k], tag[i]);
  }
  tagint still_all[2];
  MPI_Allreduce(still, still_all, 2, MPI_LMP_TAGINT, MPI_MIN, lmp->world);
  if (still_all[0] < MAXTAGINT && lmp->comm->me == 0)
    lmp->error->warning(FLERR,
                        "Atom {} of a rigid type (pair_coeff ... rigid yes) has a velocity but no "
                        "fix moves it: the contact takes that velocity as the wall's while the "
                        "body stays in place; move it with e.g. fix move, or set its velocity to "
                        "0",
                        still_all[0]);
  if (still_all[1] < MAXTAGINT && lmp->comm->me == 0)
    lmp->error->warning(FLERR,
                        "Atom {} is outside the group of fix esph/integrate {} and has a velocity "
                        "but no fix moves it: the pair forces and the contact take that velocity "
                        "while the particle stays in place; add it to the group, move it with "
                        "e.g. fix move, or set its velocity to 0",
                        still_all[1], fix_int->id);
  bigint n = 0, nall;
  std::vector<int> bodies;
  for (int i = 0; i < nlocal; i++)
    if (st->rmass[i] > 0.0 && !rigid[type[i]] && !(mask[i] & fix_int->groupbit)) {
      n++;
      bodies.push_back(st->body[i]);
    }
  MPI_Allreduce(&n, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  if (nall == 0) return;
  bodies = global_set(lmp, bodies);
  std::string list;
  for (size_t k = 0; k < bodies.size() && k < 5; k++)
    list += fmt::format("{}{}", k ? " " : "", bodies[k]);
  if (bodies.size() > 5) list += " ...";
  // a frozen body is a legal model (a soft wall, examples/anvil wall frozen): said in the
  // log, not warned
  if (lmp->comm->me == 0)
    utils::logmesg(lmp,
                   "ESPH: {} real particles of deformable types (bodies {}) are outside the "
                   "group of fix esph/integrate {}: their state is frozen (density, stress and "
                   "energy never change), a wall that pushes but neither deforms nor heats; for "
                   "a rigid wall give their type pair_coeff ... rigid yes\n",
                   nall, list, fix_int->id);
}

/* ----------------------------------------------------------------------
   every rank finds for each of its real group particles the nearest
   same-body neighbour among its own particles (no gather: memory O(N/P)) in a
   hash grid of cell size spacing, searched up to MAX_RATIO cells away; the
   median comes from a global histogram. Particles whose nearest neighbour is
   on another rank count as far (at most a thin layer at subdomain faces),
   which the median does not see. ISOLATED: most particles have no
   same-body neighbour within MAX_RATIO spacings
------------------------------------------------------------------------- */

double ESPHCheck::spacing_ratio(LAMMPS *lmp, ESPHState *st, int groupbit, double spacing)
{
  Atom *atom = lmp->atom;
  st->fetch();
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const int nprocs = lmp->comm->nprocs;
  std::vector<double> mine;
  for (int i = 0; i < nlocal; i++) {
    if (!(mask[i] & groupbit) || !(st->rmass[i] > 0.0)) continue;
    for (int d = 0; d < 3; d++) mine.push_back(atom->x[i][d]);
    mine.push_back((double) st->body[i]);
  }
  const bigint nown = mine.size() / 4;
  bigint nall;
  MPI_Allreduce(&nown, &nall, 1, MPI_LMP_BIGINT, MPI_SUM, lmp->world);
  if (nall == 0) return -1.0;
  const std::vector<double> &all = mine;
  const int first = 0;

  auto cell = [spacing](double c) {
    return (long long) floor(c / spacing);
  };
  auto key = [](long long ix, long long iy, long long iz) {
    const long long off = 1 << 20;
    return ((ix + off) << 42) | ((iy + off) << 21) | (iz + off);
  };
  std::unordered_map<long long, std::vector<int>> grid;
  for (int k = 0; k < (int) nown; k++)
    grid[key(cell(all[4 * k]), cell(all[4 * k + 1]), cell(all[4 * k + 2]))].push_back(k);

  const int reach = (int) ceil(MAX_RATIO);
  const double rmax = MAX_RATIO * spacing;
  std::vector<bigint> hist(NN_BINS * reach + 1, 0), histall(hist.size());
  for (int q = 0; q < (int) nown; q++) {
    const int k = first + q;
    const double *p = &all[4 * k];
    const long long cx = cell(p[0]), cy = cell(p[1]), cz = cell(p[2]);
    double best = rmax * rmax;
    for (long long a = -reach; a <= reach; a++)
      for (long long b = -reach; b <= reach; b++)
        for (long long c = -reach; c <= reach; c++) {
          auto it = grid.find(key(cx + a, cy + b, cz + c));
          if (it == grid.end()) continue;
          for (int l : it->second) {
            if (l == k || all[4 * l + 3] != p[3]) continue;
            const double d[3] = {all[4 * l] - p[0], all[4 * l + 1] - p[1], all[4 * l + 2] - p[2]};
            best = MIN(best, d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
          }
        }
    const int bin = MIN((int) (sqrt(best) / spacing * NN_BINS), (int) hist.size() - 1);
    hist[bin]++;
  }
  MPI_Allreduce(hist.data(), histall.data(), (int) hist.size(), MPI_LMP_BIGINT, MPI_SUM,
                lmp->world);
  const bigint n = nall, half = (n + 1) / 2;
  bigint cum = 0;
  for (size_t b = 0; b + 1 < histall.size(); b++) {
    cum += histall[b];
    if (cum >= half) return MIN((b + 0.5) / NN_BINS, MAX_RATIO);
  }
  // the last bin: no same-body neighbour within MAX_RATIO spacings
  return ISOLATED;
}

/* ----------------------------------------------------------------------
   a fix applied at post_integrate (e.g. fix wall/reflect) changes positions
   and velocities after fix esph/integrate made the step's prediction, which
   the force computation then uses: the ESPH state does not follow the change
   (a rod reflected by fix wall/reflect lost 7-10 % of the energy, depending
   on the time step). Legal, hardly meant: a warning naming each such fix
   that acts on real particles
------------------------------------------------------------------------- */

void ESPHCheck::after_prediction(LAMMPS *lmp, ESPHState *st, Fix *fix_int)
{
  Modify *modify = lmp->modify;
  const int *mask = lmp->atom->mask;
  st->fetch();
  for (int k = 0; k < modify->nfix; k++) {
    Fix *f = modify->fix[k];
    if (f == fix_int || !(modify->fmask[k] & FixConst::POST_INTEGRATE)) continue;
    const int bit = f->groupbit;
    const bool acts = any_atom(lmp, [&](int i) {
      return st->rmass[i] > 0.0 && (mask[i] & bit);
    });
    if (acts && lmp->comm->me == 0)
      lmp->error->warning(FLERR,
                          "Fix {} ({}) changes positions or velocities of ESPH particles after "
                          "fix esph/integrate {} predicted the step (post_integrate): the force "
                          "computation and the ESPH state do not see the change, and energy is "
                          "not kept (a rod reflected by fix wall/reflect lost 7-10 %, depending "
                          "on the time step); for a wall use a rigid body (pair_coeff ... rigid "
                          "yes) or a force (fix wall/region)",
                          f->id, f->style, fix_int->id);
  }
}
