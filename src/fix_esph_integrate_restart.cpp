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
   fix esph/integrate: continuing a run. At the end of a run the fix
   remembers the state its prediction belongs to (post_run); the next run,
   or the run that reads a restart file, continues exactly if nothing has
   changed the atoms since (resume_check), else it starts afresh. The
   global and per-atom restart records, which carry the prediction, the
   contact bookkeeping and the time step.
------------------------------------------------------------------------- */

#include "fix_esph_integrate.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_state.h"
#include "input.h"
#include "pair_esph_solid.h"
#include "update.h"

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using namespace LAMMPS_NS;

// number of global values in restart files before the contact records, the first of
// which tells the layout
static constexpr int NRESTART = 7;

// (changed with the per-atom prediction's layout, and with the contact records: 2026-12-05,
// the net force and impulse per pair of bodies)
static constexpr double RESTART_LAYOUT = 2026120501.0;

/* ----------------------------------------------------------------------
   the run ends: remember the state the prediction belongs to, so that the
   next run can tell whether it continues this one
------------------------------------------------------------------------- */

void FixESPHIntegrate::post_run()
{
  time_run_end = elapsed();
  state->fetch();
  for (int i = 0; i < atom->nlocal; i++) {
    save_normal_used(i, pred[i] + P_USED);
    pred[i][P_HASH] = fingerprint(i);
    wrapped_position(i, pred[i] + P_X);
  }
  dt_used = pair->dt_step;
  fp_natoms = atom->natoms;
  fp_step = update->ntimestep;
  // a run without steps (run 0): its setup computation, from the state as is, was the last
  // one; the next run re-evaluates it (resume_check()) instead of starting afresh from the
  // engagements, strain rates and cones it stored, so that run 0 then run N is run N
  if (havepred == RESUME_NONE) havepred = RESUME_SETUP;
  // the bodies' shapes, which the next run's setup compares (a rerun moves the particles
  // frame by frame)
  const bool rerun = input->command && strcmp(input->command, "rerun") == 0;
  if (update->whichflag == 1 && !rerun)
    ESPHCheck::body_shapes(lmp, state, groupbit, shape_bodies, shape_then);
  else
    shape_bodies.clear();
}

/* ----------------------------------------------------------------------
   the normal, surface gap and gap rate of real particle i that the last
   force computation used: the stored ones are those it found, which the
   next step uses
------------------------------------------------------------------------- */

void FixESPHIntegrate::save_normal_used(int i, double *out)
{
  if (pair->geometry_used(i, out)) return;
  for (int k = 0; k < 6; k++) out[k] = 0.0;
}

/* ----------------------------------------------------------------------
   called by the pair style at the setup of a run: RESUME_STEP if the
   prediction of the last completed step (of the previous run, or of the run
   that wrote the restart file) still belongs to every atom, i.e. nothing
   changed the state since (set, velocity, displace_atoms, read_data,
   create_atoms, delete_atoms, ...); RESUME_SETUP if the last run had no
   steps (run 0) and nothing changed since its setup computation. Then the
   setup force computation is a re-evaluation of the last one and the run
   continues exactly; otherwise (RESUME_NONE) it starts from the current
   state. Work at run boundaries only.
------------------------------------------------------------------------- */

int FixESPHIntegrate::resume_check()
{
  int ok = havepred != RESUME_NONE && update->whichflag == 1 && atom->natoms == fp_natoms;
  state->fetch();
  if (ok)
    for (int i = 0; i < atom->nlocal; i++)
      if (pred[i][P_HASH] != fingerprint(i) || !same_position(i, pred[i] + P_X)) {
        ok = 0;
        break;
      }
  int all;
  MPI_Allreduce(&ok, &all, 1, MPI_INT, MPI_MIN, world);
  // a fresh start: the prediction is stale until a step is completed
  if (!all) {
    havepred = RESUME_NONE;
    // nor do the rates stored for the extrapolated prediction
    for (int i = 0; i < atom->nlocal; i++) pred[i][P_PREVOK] = 0.0;
    return RESUME_NONE;
  }
  // the re-evaluation uses the normals the last computation used; it stores the ones it
  // finds, as that computation did
  // (boundary particles carry their own normals; their gaps are found by each computation)
  // The boundary particles another fix moves turned at the end of the last step, after its
  // force computation: the re-evaluation sees them as it did, setup() turns them again
  turned_n.assign(3 * (size_t) atom->nlocal, 0.0);
  for (int i = 0; i < atom->nlocal; i++) {
    if (state->rmass[i] > 0.0)
      for (int d = 0; d < 3; d++) state->n[i][d] = pred[i][P_USED + d];
    else if (turns_at_end(i))
      for (int d = 0; d < 3; d++) {
        turned_n[3 * i + d] = state->n[i][d];
        state->n[i][d] = pred[i][P_USED + d];
      }
    // (after run 0: the boundary particles' velocities that computation saw, which setup()
    // then replaced by their interpolated ones)
    if (havepred == RESUME_SETUP && moves_boundary(i))
      for (int d = 0; d < 3; d++) atom->v[i][d] = pred[i][P_V + d];
    state->gap[i] = pred[i][P_USED + 3];
    state->gapv[i] = pred[i][P_USED + 4];
    state->eng[i] = pred[i][P_USED + 5];
  }
  // and the time step of its gap forecast (with the cfl keyword the step has changed since)
  pair->dt_step = dt_used;
  // (after a run without steps the computation re-evaluated is from the state as is)
  return havepred;
}

/* ----------------------------------------------------------------------
   fingerprint of the state of atom i: a 64-bit hash of the bits of every
   per-atom quantity a step reads but the position, stored as an
   integer-valued double (the top 53 bits). The position is compared apart
   (same_position), to round-off of the box: commands such as balance take
   every position through lamda coordinates and back, which changes the last
   bits, and the run still continues.
------------------------------------------------------------------------- */

static inline uint64_t hash_mix(uint64_t h, double value)
{
  uint64_t z;
  memcpy(&z, &value, sizeof(z));
  // splitmix64 finaliser of h ^ value: every input bit changes every output bit
  z ^= h + 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double FixESPHIntegrate::fingerprint(int i)
{
  uint64_t h = 0;
  for (int d = 0; d < 3; d++) h = hash_mix(h, atom->v[i][d]);
  h = hash_mix(h, state->rmass[i]);
  h = hash_mix(h, state->rho[i]);
  h = hash_mix(h, state->e[i]);
  h = hash_mix(h, state->h[i]);
  for (int k = 0; k < 6; k++) h = hash_mix(h, state->s[i][k]);
  for (int d = 0; d < 3; d++) h = hash_mix(h, state->n[i][d]);
  h = hash_mix(h, state->depth[i]);
  h = hash_mix(h, state->gap[i]);
  h = hash_mix(h, state->gapv[i]);
  h = hash_mix(h, state->eng[i]);
  // (a plastic strain or an alpha of 0 is no state: the same whether ESPH_PLASTIC or
  // ESPH_VISC exists or not)
  if (state->epsp && state->epsp[i] != 0.0) h = hash_mix(h, state->epsp[i]);
  if (state->alpha && state->alpha[i] != 0.0) h = hash_mix(h, state->alpha[i]);
  h = hash_mix(h, (double) atom->type[i]);
  h = hash_mix(h, (double) state->body[i]);
  h = hash_mix(h, (atom->mask[i] & groupbit) ? 1.0 : 0.0);
  return (double) (h >> 11);
}

/* ----------------------------------------------------------------------
   global restart state: whether the per-atom prediction can be continued,
   and the contact bookkeeping
------------------------------------------------------------------------- */

void FixESPHIntegrate::write_restart(FILE *fp)
{
  // written inside a run after a step: the fingerprints of now (pack_restart);
  // between runs: those stored at the end of the last run
  const int now = (update->whichflag == 1 && update->ntimestep != fp_step);
  double list[NRESTART] = {
      RESTART_LAYOUT, (double) havepred,          (double) (now ? atom->natoms : fp_natoms),
      elapsed(),      (double) update->ntimestep, now ? pair->dt_step : dt_used,
      dt_prev};
  // then the contact history of all bodies and per pair of bodies
  std::vector<double> bp(ESPH::ContactRecord::NVALUES);
  contact_all.pack(bp.data());
  bp.push_back((double) body_pairs.size());
  for (size_t p = 0; p < body_pairs.size(); p++) {
    bp.push_back(body_pairs[p].first);
    bp.push_back(body_pairs[p].second);
    double v[ESPH::ContactRecord::NVALUES];
    body_records[p].pack(v);
    bp.insert(bp.end(), v, v + ESPH::ContactRecord::NVALUES);
  }
  if (comm->me == 0) {
    int size = sizeof(list) + bp.size() * sizeof(double);
    fwrite(&size, sizeof(int), 1, fp);
    fwrite(list, sizeof(double), NRESTART, fp);
    fwrite(bp.data(), sizeof(double), bp.size(), fp);
  }
}

/* ----------------------------------------------------------------------
   position of atom i as domain->pbc() will wrap it (orthogonal boxes), so
   that the wrap at the next setup or by write_restart changes nothing
------------------------------------------------------------------------- */

void FixESPHIntegrate::wrapped_position(int i, double *xw)
{
  for (int d = 0; d < 3; d++) xw[d] = atom->x[i][d];
  if (domain->triclinic) return;
  const int per[3] = {domain->xperiodic, domain->yperiodic, domain->zperiodic};
  for (int d = 0; d < 3; d++) {
    if (!per[d]) continue;
    if (xw[d] < domain->boxlo[d]) xw[d] += domain->prd[d];
    if (xw[d] >= domain->boxhi[d]) {
      xw[d] -= domain->prd[d];
      xw[d] = MAX(xw[d], domain->boxlo[d]);
    }
  }
}

/* ----------------------------------------------------------------------
   true if atom i is at the position xw (wrapped_position) up to the
   round-off of a trip through lamda coordinates: 16 ulp of the box extent
------------------------------------------------------------------------- */

bool FixESPHIntegrate::same_position(int i, const double *xw)
{
  double now[3];
  wrapped_position(i, now);
  for (int d = 0; d < 3; d++) {
    const double scale = fabs(domain->boxlo[d]) + fabs(domain->boxhi[d]) + fabs(domain->prd[d]);
    if (!(fabs(now[d] - xw[d]) <= 16.0 * DBL_EPSILON * scale)) return false;
  }
  return true;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::restart(char *buf)
{
  const auto *list = (const double *) buf;
  if (list[0] != RESTART_LAYOUT)
    error->all(FLERR,
               "Fix {} state in the restart file is of another version of the package: "
               "write the restart file again with this version",
               style);
  havepred = (int) list[1];
  fp_natoms = (bigint) list[2];
  fp_step = -1;
  time_file = list[3];
  step_file = (bigint) list[4];
  dt_used = list[5];
  dt_prev = list[6];
  time_pending = 1;
  contact_all.unpack(list + NRESTART);
  const double *bp = list + NRESTART + ESPH::ContactRecord::NVALUES;
  const int np = (int) bp[0];
  body_pairs.clear();
  body_records.clear();
  for (int p = 0; p < np; p++) {
    const double *r = bp + 1 + p * (2 + ESPH::ContactRecord::NVALUES);
    body_pairs.emplace_back((int) r[0], (int) r[1]);
    body_records.emplace_back();
    body_records.back().unpack(r + 2);
  }
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::pack_restart(int i, double *buf)
{
  // the first value is the count, as every fix with per-atom restart data writes it
  buf[0] = NPRED + 1;
  for (int k = 0; k < NPRED; k++) buf[k + 1] = pred[i][k];
  if (update->whichflag == 1 && update->ntimestep != fp_step) {
    state->fetch();
    save_normal_used(i, buf + P_USED + 1);
    buf[P_HASH + 1] = fingerprint(i);
    wrapped_position(i, buf + P_X + 1);
  }
  return NPRED + 1;
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrate::unpack_restart(int nlocal, int nth)
{
  double **extra = atom->extra;
  // skip the values of the fixes before this one
  int m = 0;
  for (int k = 0; k < nth; k++) m += static_cast<int>(extra[nlocal][m]);
  // (a file of another layout is refused by restart(), which LAMMPS calls first)
  m++;
  for (int k = 0; k < NPRED; k++) pred[nlocal][k] = extra[nlocal][m++];
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::size_restart(int /*nlocal*/)
{
  return NPRED + 1;
}

/* ---------------------------------------------------------------------- */

int FixESPHIntegrate::maxsize_restart()
{
  return NPRED + 1;
}
