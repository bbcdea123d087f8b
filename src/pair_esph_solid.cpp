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
   SPH elastic solid with Jaumann-rate hypoelasticity, Mie-Grueneisen EOS,
   Monaghan-Gingold viscosity and the contact algorithm of
   Min, Lee, Kim & Lee, KSME Int. J. 14 (2000).
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "esph_bodies.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "esph_threads.h"
#include "fix_esph_boundary.h"
#include "fix_esph_integrate.h"
#include "force.h"
#include "group.h"
#include "info.h"
#include "input.h"
#include "math_const.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "pair_hybrid.h"
#include "update.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ---------------------------------------------------------------------- */

PairESPHSolid::PairESPHSolid(LAMMPS *lmp) :
    Pair(lmp), eos(nullptr), shear(nullptr), yield(nullptr), hardening(nullptr), rigid_flag(0),
    rigid(nullptr), matset(nullptr), nmax(0), acc(nullptr), hq(nullptr), drho(nullptr), de(nullptr),
    dh(nullptr), ds(nullptr), dalpha(nullptr), bvel(nullptr), bspin(nullptr), xsph(nullptr),
    cpl(nullptr), acc_cols(A_NN), hq_cols(NHQ), qcol_b(-1), qcol_n(-1), qcol_d(-1), cone_keep(0),
    fric_keep(0), recon_keep(0), nboundary(0), atom_contact_flag(0), atom_contact_nmax(0),
    atom_contact(nullptr), state(nullptr), fix_int(nullptr), spacing_lo(0.0), spacing_hi(0.0),
    nthreads(1)
{
  single_enable = 0;
  restartinfo = 0;
  one_coeff = 0;
  manybody_flag = 0;
  comm_forward = FORWARD_MAX;
  comm_reverse = NACC;

  h0 = 0.0;
  cut_global = 0.0;
  set_defaults();

  pred_valid = 0;
  normals_valid = 0;
  turn_body = 0;
  dt_cfl = 0.0;
  gap_reach2 = 0.0;
  touch_on_run = 0;
  surf_on = 1;
  left_warned = 0;
  dt_step = 0.0;
  dt_keep = 0;
  ncontact_pairs = ntouch_pairs = 0;
  fcontact = 0.0;
  comm_stage = COMM_HOIST;
  comm_bnd = 0;
  nforward = nreverse = 0;
  simd_flag = simd_active = 0;
  listfull = nullptr;
  simd_resplit = 1;
  simd_sep = -1;
  simd_bnd = 0;
  simd_own = 0;

  state = new ESPHState(lmp);
  units.set(force->ftm2v, force->mvv2e, force->nktv2p);
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::init_style()
{
  one_seen.assign((atom->ntypes + 1) * (atom->ntypes + 1), 0);
  // the conversion is generic (esph_units.h), but only these unit styles are tested
  const std::string ustyle = update->unit_style;
  if (ustyle != "si" && ustyle != "metal" && ustyle != "real" && ustyle != "cgs" &&
      ustyle != "micro" && ustyle != "nano" && ustyle != "lj")
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid does not support units {}: expected units si, metal, real, cgs, "
               "micro, nano or lj",
               ustyle);
  if (!atom->rmass_flag)
    error->all(FLERR, Error::NOLASTLINE, "Pair esph/solid requires per-atom masses");
  if ((neighbor->nex_type || neighbor->nex_group || neighbor->nex_mol) && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid with neigh_modify exclude: the excluded pairs are not in its "
                   "neighbor lists, so those particles do not interact at all (bodies whose pairs "
                   "are excluded pass through each other without contact, a body whose own pairs "
                   "are excluded falls apart); use neigh_modify exclude none");
  if ((offset_flag || tail_flag) && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid has no cutoff energy to shift and no long-range tail: "
                   "pair_modify {} has no effect; drop it",
                   offset_flag ? "shift yes" : "tail yes");
  // the per-type masses of atom styles that have them are never used (the per-atom masses
  // are), but write_data writes them and read_data rejects a mass of 0: the types whose
  // mass was not set get 1.0, so that a data file of an ESPH system can be read back
  if (atom->mass && atom->mass_setflag) {
    std::string unset;
    int nunset = 0;
    for (int t = 1; t <= atom->ntypes; t++)
      if (!atom->mass_setflag[t]) {
        atom->mass[t] = 1.0;
        atom->mass_setflag[t] = 1;
        unset += (nunset++ ? " " : "") + std::to_string(t);
      }
    if (nunset && comm->me == 0)
      utils::logmesg(lmp,
                     "Pair esph/solid: per-type mass 1.0 for atom type{} {} (unused: ESPH uses the "
                     "per-atom masses; set for write_data and read_data)\n",
                     nunset > 1 ? "s" : "", unset);
  }
  // an SPH solid has no potential energy whose gradient is its force
  if (update->whichflag == 2)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid does not support minimize: relax an SPH solid with a damped "
               "run instead (e.g. fix viscous with fix esph/integrate)");
  if (update->whichflag == 1 && input->command && strcmp(input->command, "rerun") == 0 &&
      comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid with rerun: a dump holds no SPH state (density, energy, "
                   "stress), so the forces and energies of the frames are those of the state "
                   "left by the last run, not of the frames");
  auto fixes = modify->get_fix_by_style("^esph/integrate");
  if (fixes.empty())
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid requires fix esph/integrate to advance the SPH state");
  fix_int = dynamic_cast<FixESPHIntegrate *>(fixes[0]);
  // with move no another fix moves the particles; otherwise no other fix may
  ESPHCheck::integrators(lmp, fix_int, fix_int->move);
  rigid_flag = 0;
  for (int t = 1; t <= atom->ntypes; t++) rigid_flag |= rigid[t];
  if (rigid_flag && contact == CONTACT_OFF)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid rigid types (pair_coeff ... rigid yes) need a contact rule "
               "(contact solid or paper), not contact off");
  if (rigid_flag) ESPHCheck::rigid_bodies(lmp, state, fix_int, rigid);
  ESPHCheck::unintegrated(lmp, state, fix_int, rigid);
  ESPHCheck::after_prediction(lmp, state, fix_int);
  if (contact != CONTACT_OFF && !boundary_fix()) {
    // contact needs boundary particles only when there is more than one body
    int gmin, gmax, anybnd;
    body_range(gmin, gmax, anybnd);
    if (gmin != gmax)
      error->all(FLERR, Error::NOLASTLINE,
                 "Pair esph/solid contact {} between bodies {}..{} requires fix esph/boundary "
                 "(boundary particles with normals); use contact off for traditional SPH",
                 contact == CONTACT_PAPER ? "paper" : "solid", gmin, gmax);
  }
  init_spacings();
  init_turn();
  init_recon();
  init_cone();
  // contact/gap touch: only where two bodies can touch
  touch_on_run = 0;
  touch_bodies.clear();
  touch_pairs.clear();
  if (contact == CONTACT_SOLID && gap_touch) {
    int gmin, gmax, anybnd;
    body_range(gmin, gmax, anybnd);
    touch_on_run = anybnd && (gmin != gmax);
  }
  // the reach of a surface-gap partner, in the boundary particles' spacing (the smoothing
  // length where no fix esph/boundary gives it; the largest of several)
  const double sb = spacing_hi;
  const double reach = GAP_REACH * ((sb > 0.0) ? sb : h0);
  gap_reach2 = reach * reach;
  // contact/couple: only where cross-body pair forces can have a couple (not in 1d)
  couple_on = couple_flag && (contact != CONTACT_OFF) && (dim > 1);
  if (couple_flag && !couple_on && comm->me == 0)
    error->warning(FLERR, "Pair esph/solid contact/couple has no effect {}: drop it",
                   contact == CONTACT_OFF ? "with contact off (no contact forces)"
                                          : "in dimension 1 (the pair forces have no couple)");
  drop_unused_state();
  // h against the particle spacing, before the neighbour bins are made for the cutoff
  ESPHCheck::smoothing_length(lmp, h0, hmax, hvar_flag, boundary_spacing());
  // per-atom contact output only while a compute esph/atom asks for it (its init() follows)
  atom_contact_flag = 0;
  neighbor->add_request(this);
  // the bulk pairs in vector registers: from a full list (pair_esph_solid_simd.cpp)
  // (listfull stays: LAMMPS calls init_list() only when it makes new lists, and a run with
  // the same requests keeps the last run's)
  simd_flag = simd_set && simd_cpu() && simd_physics() && simd_fits();
  simd_resplit = 1;
  if (simd_flag) neighbor->add_request(this, NeighConst::REQ_FULL)->set_id(1);
}

/* ----------------------------------------------------------------------
   the half list of every pass, and the full list of the vector pass
------------------------------------------------------------------------- */

void PairESPHSolid::init_list(int id, NeighList *ptr)
{
  if (id == 1)
    listfull = ptr;
  else
    list = ptr;
}

/* ----------------------------------------------------------------------
   the full list holds twice the half list's neighbours: with a large h
   (about 3.7 spacings in 3D for the default neigh_modify one 2000) it
   would overflow where the half list does not. Estimated from the spacing
   of fix esph/boundary or else the smallest (m / rho0)^(1/D) of the real
   particles (a simple cubic lattice, 25 % margin); too many: the scalar
   loop, with a warning that says how to keep the vector pass
------------------------------------------------------------------------- */

bool PairESPHSolid::simd_fits()
{
  double sp = boundary_spacing();
  if (!(sp > 0.0)) {
    double vmin = BIG_DT;
    const double *rmass = atom->rmass;
    const int *type = atom->type;
    for (int i = 0; i < atom->nlocal; i++)
      if (rmass[i] > 0.0 && eos[type[i]].rho0 > 0.0)
        vmin = std::min(vmin, rmass[i] / eos[type[i]].rho0);
    double vall = vmin;
    MPI_Allreduce(&vmin, &vall, 1, MPI_DOUBLE, MPI_MIN, world);
    if (vall >= BIG_DT) return true;
    sp = pow(vall, 1.0 / dim);
  }
  const double rc = (cut_global + neighbor->skin) / sp;
  const double n = (dim == 3) ? MathConst::MY_4PI3 * rc * rc * rc
      : (dim == 2)            ? MathConst::MY_PI * rc * rc
                              : 2.0 * rc;
  const bigint need = (bigint) (1.25 * n) + 1;
  if (need <= neighbor->oneatom) return true;
  if (comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid simd yes: a full neighbor list of about {} neighbors per "
                   "atom (h = {:.3g} spacings, neighbor skin {:.3g} spacings) would exceed "
                   "neigh_modify one {}: every pair goes through the scalar loop; {}set "
                   "neigh_modify one {} to keep the vector pass, or simd no to silence this",
                   need, h0 / sp, neighbor->skin / sp, neighbor->oneatom,
                   neighbor->skin > h0 ? "a skin that large is a units style's default "
                                         "(the neighbor command sets it: about 0.2 h is usual); "
                                       : "",
                   need);
  return false;
}

/* ----------------------------------------------------------------------
   the vector pass implements the bulk pairs of the default physics and
   its usual options: constant h, the cubic B-spline, gradient plain or
   corrected, the viscosity with its reconstruction or switch, heat
   transfer. With the artificial stress, XSPH, a variable h, another
   kernel, gradient bonet/lok or torquefree or rigid types every pair goes
   through the scalar loop
------------------------------------------------------------------------- */

bool PairESPHSolid::simd_physics() const
{
  return kernel == CUBIC && !hvar_flag && !astress_flag && !xsph_flag && !rigid_flag &&
      correct_flag <= CORRECT_RATE;
}

/* ----------------------------------------------------------------------
   the reconstruction in use: the one set, unless no type can use it. The
   reconstruction acts only within a body, between real particles of types
   without a yield stress (their strain rates are 0 in a type with one, and
   a rigid type meets other bodies only): in a run without such particles
   it would cost without effect, so it is off. Decided at each run, from
   its pair_coeff and its particles. A run without it drops the strain
   rates (they would be stale by the next run that uses it, which starts
   from zero rates, as a run restarted from this one's restart file does);
   a run with it makes them where they are missing
------------------------------------------------------------------------- */

void PairESPHSolid::init_recon()
{
  recon_flag = recon_set;
  if (recon_set) {
    const int ntypes = atom->ntypes;
    std::vector<int> mine(ntypes + 1, 0), real(ntypes + 1, 0);
    const double *rmass = atom->rmass;
    const int *type = atom->type;
    for (int i = 0; i < atom->nlocal; i++)
      if (rmass[i] > 0.0) mine[type[i]] = 1;
    MPI_Allreduce(mine.data(), real.data(), ntypes + 1, MPI_INT, MPI_MAX, world);
    int usable = 0;
    for (int t = 1; t <= ntypes; t++)
      if (real[t] && setflag[t][t] && !rigid[t] && yield[t] <= 0.0) usable = 1;
    if (!usable) {
      if (recon_given && !recon_warned && comm->me == 0)
        error->warning(FLERR,
                       "Pair esph/solid visc/recon has no effect: no real particle is of a "
                       "deformable type without a yield stress (where the viscosity is "
                       "reconstructed); drop visc/recon");
      recon_warned = 1;
      recon_flag = RECON_OFF;
    }
  }
  if (recon_flag)
    ESPHState::ensure_recon(lmp);
  else
    ESPHState::drop_recon(lmp);
}

/* ----------------------------------------------------------------------
   the normal cones (contact/normal cone) in use: given, under contact
   solid, in a scene with boundary particles and more than one body, where
   a cross-body pair can occur (with friction and rigid types too: their
   variants of the pair loop have the cones). Decided at each run;
   elsewhere their state (made by settings()) is kept but not used
------------------------------------------------------------------------- */

void PairESPHSolid::init_cone()
{
  cone_on = 0;
  if (contact == CONTACT_SOLID && cone_flag) {
    int gmin, gmax, anybnd;
    body_range(gmin, gmax, anybnd);
    cone_on = anybnd && (gmin != gmax);
  }
}

/* ----------------------------------------------------------------------
   the smallest and largest body ID over all ranks' particles, and whether
   any of them is a boundary particle (zero mass)
------------------------------------------------------------------------- */

void PairESPHSolid::body_range(int &gmin, int &gmax, int &anybnd)
{
  state->fetch();
  const double *rmass = state->rmass;
  const int *body = state->body;
  // one reduction: the minimum as the maximum of -body
  int mine[3] = {0, -(1 << 30), -(1 << 30)}, all[3];
  for (int i = 0; i < atom->nlocal; i++) {
    if (rmass[i] == 0.0) mine[0] = 1;
    mine[1] = MAX(mine[1], body[i]);
    mine[2] = MAX(mine[2], -body[i]);
  }
  MPI_Allreduce(mine, all, 3, MPI_INT, MPI_MAX, world);
  anybnd = all[0];
  gmax = all[1];
  gmin = -all[2];
}

/* ----------------------------------------------------------------------
   the plastic strain (fix ESPH_PLASTIC) is kept while a type has a yield
   stress or a particle has some, the switched viscosity's alpha (fix
   ESPH_VISC) while visc/switch is on or a particle has one; else each is
   dropped (nothing to keep, and a run that has it made for a restart
   file's sake then equals the run that never had it)
------------------------------------------------------------------------- */

void PairESPHSolid::drop_unused_state()
{
  int yielding = 0;
  for (int t = 1; t <= atom->ntypes; t++)
    if (setflag[t][t] && yield[t] > 0.0) yielding = 1;
  if (!yielding) drop_if_zero("esph_epsp", ESPHState::FIX_ID_PLASTIC);
  if (!vswitch_flag) drop_if_zero("esph_alpha", ESPHState::FIX_ID_VISC);
}

/* ----------------------------------------------------------------------
   deletes the internal fix fixid of the per-atom double name where it is
   0 for every atom
------------------------------------------------------------------------- */

void PairESPHSolid::drop_if_zero(const char *name, const char *fixid)
{
  int flag, cols;
  const int k = atom->find_custom(name, flag, cols);
  if (k < 0) return;
  const double *value = atom->dvector[k];
  int mine = 0, any;
  for (int i = 0; i < atom->nlocal; i++)
    if (value[i] != 0.0) mine = 1;
  MPI_Allreduce(&mine, &any, 1, MPI_INT, MPI_MAX, world);
  if (!any) ESPHState::drop_optional(lmp, fixid, name);
}

/* ---------------------------------------------------------------------- */

double PairESPHSolid::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, Error::NOLASTLINE,
               "All pair esph/solid materials are not set (use pair_coeff I I rho0 ... for every "
               "type). Status:\n" +
                   Info::get_pair_coeff_status(lmp));
  if ((int) one_seen.size() == (atom->ntypes + 1) * (atom->ntypes + 1))
    one_seen[i * (atom->ntypes + 1) + j] = one_seen[j * (atom->ntypes + 1) + i] = 1;
  return cut_global;
}

/* ----------------------------------------------------------------------
   under pair_style hybrid: two types that are both materials of this style
   (pair_coeff I I ... esph/solid) whose pairs another sub-style was given
   (e.g. pair_coeff 1 2 zero) do not meet through this style: no contact
   between their bodies, no cohesion in a body of both. Legal, hardly meant:
   a warning, once
------------------------------------------------------------------------- */

void PairESPHSolid::check_hybrid()
{
  if (hybrid_warned || force->pair == this) return;
  const int nt = atom->ntypes;
  if ((int) one_seen.size() != (nt + 1) * (nt + 1)) return;
  std::string pairs;
  int npairs = 0;
  for (int i = 1; i <= nt; i++)
    for (int j = i; j <= nt; j++)
      if (setflag[i][i] && setflag[j][j] && !one_seen[i * (nt + 1) + j]) {
        if (npairs++ < 8) pairs += fmt::format("{}{} {}", npairs > 1 ? ", " : "", i, j);
      }
  if (npairs && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid under pair_style {}: types {}{} are esph/solid materials but "
                   "their pairs are given to another sub-style, so their particles do not meet "
                   "through esph/solid (bodies pass through each other, a body of both types "
                   "falls apart): give those pairs to esph/solid (pair_coeff I J esph/solid, or "
                   "no pair_coeff for them) or use pair_style hybrid/overlay",
                   force->pair_style, pairs, npairs > 8 ? ", ..." : "");
  // hybrid/overlay: another sub-style on pairs of esph/solid materials acts on their boundary
  // particles too (no mass; they coincide where two faces touch)
  auto *hybrid = dynamic_cast<PairHybrid *>(force->pair);
  std::vector<int> btypes;
  state->fetch();
  for (int i = 0; i < atom->nlocal; i++)
    if (state->rmass[i] == 0.0) btypes.push_back(atom->type[i]);
  btypes = ESPHCheck::global_set(lmp, btypes);
  auto has_bnd = [&btypes](int t) {
    return std::binary_search(btypes.begin(), btypes.end(), t);
  };
  std::string other;
  if (hybrid && force->pair_map)
    for (int i = 1; i <= nt && other.empty(); i++)
      for (int j = i; j <= nt && other.empty(); j++) {
        if (!setflag[i][i] || !setflag[j][j] || !(has_bnd(i) || has_bnd(j))) continue;
        for (const auto &kv : *force->pair_map) {
          // (zero computes no forces)
          if (utils::strmatch(kv.first, "^esph/solid") || kv.first == "zero") continue;
          // (check_ijtype() only reads the name)
          if (hybrid->check_ijtype(i, j, const_cast<char *>(kv.first.c_str()))) {
            other = fmt::format("{} on types {} {}", kv.first, i, j);
            break;
          }
        }
      }
  if (!other.empty() && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid under pair_style {}: sub-style {}, which are esph/solid "
                   "materials with boundary particles: it acts on those too, which have no mass "
                   "(its forces on them do nothing but move them off the surface) and coincide "
                   "where two faces touch (a force at zero distance: lost atoms); give the "
                   "boundary particles a type of their own (fix esph/boundary ... type) and "
                   "leave that type out of the other sub-style",
                   force->pair_style, other);
  hybrid_warned = 1;
}

/* ----------------------------------------------------------------------
   called at the start of each run (not with run pre no), fill unset density
   and h. A run that continues the previous one, with nothing changed in
   between, re-evaluates the last force computation: at the state the
   integrator predicted for the end of the last step, with the normals that
   computation used (restored by the integrator), so the run goes on as if
   it had not been interrupted. Otherwise the rates are evaluated at the
   current state and the normals are computed afresh from the boundary
   particles.
------------------------------------------------------------------------- */

void PairESPHSolid::setup()
{
  check_hybrid();
  left_warned = 0;
  // (resume_check() restores the time step of the last computation for the gap forecast)
  // RESUME_STEP: a continued run, at the prediction of the last step; RESUME_SETUP: after a
  // run without steps, at the state as is (the setup computation of that run, re-evaluated)
  const int resumed = fix_int->resume_check();
  pred_valid = (resumed == FixESPHIntegrate::RESUME_STEP);
  normals_valid = (resumed != FixESPHIntegrate::RESUME_NONE);
  dt_keep = normals_valid;
  recon_keep = normals_valid;
  cone_keep = normals_valid;
  fric_keep = normals_valid;
  state->fetch();
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  // a run without friction releases the static friction a run with it held (friction given
  // again later starts from none)
  if (state->fric && !(friction > 0.0 && contact != CONTACT_OFF))
    for (int i = 0; i < nlocal; i++)
      for (int k = 0; k < 3; k++) state->fric[i][k] = state->fricu[i][k] = 0.0;
  for (int i = 0; i < nlocal; i++) {
    if (state->rho[i] == 0.0) state->rho[i] = eos[type[i]].rho0;
    if (state->h[i] == 0.0) state->h[i] = h0;
  }
  // the state the run starts from, and the arrangement of the particles (one pass each)
  ESPHCheck::state(lmp, state, eos, cut_global / KERNEL_SUPPORT, units);
  ESPHCheck::pairs(lmp, state, list, cut_global * cut_global, h0, dim,
                   contact != CONTACT_OFF ? boundary_spacing() : 0.0);
  {
    const double spacing = boundary_spacing();
    // (the volume per particle is spacing^D on a simple cubic lattice only: on another one,
    // which fix esph/boundary warns about, a right mass would be warned as wrong)
    bool off_lattice = false;
    for (const auto *f : modify->get_fix_by_style("^esph/boundary$"))
      if (dynamic_cast<const FixESPHBoundary *>(f)->off_lattice()) off_lattice = true;
    if (!off_lattice)
      ESPHCheck::volumes(
          lmp, state, eos,
          [this](int b) {
            return spacing_of(b);
          },
          dim);
    // the artificial stress's dp is the particle spacing (Monaghan 2000)
    if (astress_flag && spacing > 0.0 && comm->me == 0 &&
        (astress_dp > 2.0 * spacing || astress_dp < 0.5 * spacing))
      error->warning(FLERR,
                     "Pair esph/solid artstress dp = {} is {:.3g} x the spacing {} of fix "
                     "esph/boundary: dp is the particle spacing (W(dp) scales the repulsion); "
                     "set dp to the spacing",
                     astress_dp, astress_dp / spacing, spacing);
  }
  if (contact != CONTACT_OFF)
    ESPHCheck::contact_bodies(lmp, state, contact == CONTACT_PAPER ? "paper" : "solid");
  bigint nb = 0;
  for (int i = 0; i < nlocal; i++)
    if (state->rmass[i] == 0.0) nb++;
  MPI_Allreduce(&nb, &nboundary, 1, MPI_LMP_BIGINT, MPI_SUM, world);

  // a run that starts afresh with bodies already engaged in contact, with an integrator that
  // has recorded none (a data file written in contact): what only a restart file keeps is
  // missing
  if (resumed == FixESPHIntegrate::RESUME_NONE && contact != CONTACT_OFF && state->eng &&
      fix_int->body_records.empty()) {
    bigint neng = 0, nengall = 0;
    for (int i = 0; i < nlocal; i++)
      if (state->rmass[i] > 0.0 && state->eng[i] > 0.0) neng++;
    MPI_Allreduce(&neng, &nengall, 1, MPI_LMP_BIGINT, MPI_SUM, world);
    if (nengall > 0 && comm->me == 0)
      error->warning(FLERR,
                     "Pair esph/solid: {} real particles are engaged in contact with another "
                     "body at the start of a run that does not continue a previous one (a data "
                     "file written during contact?): the contact record (fix esph/integrate "
                     "vector elements 4 to 6, compute esph/contact) starts at this run, and the "
                     "integrator's prediction and the last force computation's contact "
                     "geometry, which only restart files keep, are made afresh, so the run "
                     "differs slightly from one that was not interrupted; for an exact "
                     "continuation use write_restart and read_restart",
                     nengall);
  }

  // an unset switched viscosity (0, e.g. a new particle) starts at its ceiling: a shock
  // present at the start (bodies that touch at t = 0) is damped as without the switch
  if (vswitch_flag) {
    if (!state->alpha)
      error->all(FLERR, Error::NOLASTLINE,
                 "Pair esph/solid visc/switch: the fix {} of d_esph_alpha is gone (it must not "
                 "be deleted)",
                 ESPHState::FIX_ID_VISC);
    for (int i = 0; i < nlocal; i++)
      if (state->alpha[i] == 0.0) state->alpha[i] = alpha;
  }
  if (recon_flag && !state->drec)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid visc/recon: fix {} or {} does not hold d2_esph_drec or "
               "d2_esph_drec_used: these fix IDs are reserved for ESPH's internal fixes (use "
               "another fix ID)",
               ESPHState::FIX_ID_RECON, ESPHState::FIX_ID_RECON_USED);
  if (cone_on && !state->cone)
    error->all(FLERR, Error::NOLASTLINE,
               "Pair esph/solid contact/normal cone: the fix {} or {} of the normal cones is "
               "gone (they must not be deleted)",
               ESPHState::FIX_ID_CONE, ESPHState::FIX_ID_CONE_USED);

  grow_work();
  // rates start at zero until the first compute
  for (int i = 0; i < nmax; i++) {
    drho[i] = de[i] = dh[i] = 0.0;
    for (int k = 0; k < 6; k++) ds[i][k] = 0.0;
    if (dalpha) dalpha[i] = 0.0;
  }
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::grow_work()
{
  // the artificial stress keeps R next to the other hoisted quantities (memory locality)
  const int cols0 = NHQ + (astress_flag ? NHQ_AST : 0);
  qcol_b = (correct_flag >= CORRECT_BONETLOK) ? cols0 : -1;
  const int cols1 = cols0 + (qcol_b >= 0 ? 9 : 0);
  qcol_d = recon_flag ? Q_D : -1;
  qcol_n = cone_on ? cols1 : -1;
  const int cols = cols1 + (qcol_n >= 0 ? 6 : 0);
  if (cols != hq_cols) {
    memory->destroy(hq);
    hq_cols = cols;
    if (nmax > 0) memory->create(hq, nmax, hq_cols, "pair:hq");
    if (nmax > 0) memset(hq[0], 0, sizeof(double) * nmax * hq_cols);
  }
  // the cone sums only with the normal cones
  const int acols = couple_on ? NACC : ((qcol_n >= 0) ? A_CT : A_NN);
  if (acols != acc_cols) {
    memory->destroy(acc);
    acc_cols = acols;
    if (nmax > 0) memory->create(acc, nmax, acc_cols, "pair:acc");
  }
  // set by every force computation before the integrator reads it: no initial values
  if (xsph_flag && !xsph && nmax > 0) memory->create(xsph, nmax, 3, "pair:xsph");
  if (vswitch_flag && !dalpha && nmax > 0) {
    memory->create(dalpha, nmax, "pair:dalpha");
    for (int i = 0; i < nmax; i++) dalpha[i] = 0.0;
  }
  if (atom->nmax <= nmax) return;
  const int old = nmax;
  nmax = atom->nmax;
  memory->grow(acc, nmax, acc_cols, "pair:acc");
  memory->grow(hq, nmax, hq_cols, "pair:hq");
  if (cpl) memory->grow(cpl, nmax, 10, "pair:cpl");
  // (rows the vector pass may read in slots this run does not set: finite)
  memset(hq[old], 0, sizeof(double) * (nmax - old) * hq_cols);
  memory->grow(drho, nmax, "pair:drho");
  memory->grow(de, nmax, "pair:de");
  memory->grow(dh, nmax, "pair:dh");
  memory->grow(ds, nmax, 6, "pair:ds");
  memory->grow(bvel, nmax, 3, "pair:bvel");
  memory->grow(bspin, nmax, 3, "pair:bspin");
  if (xsph_flag || xsph) memory->grow(xsph, nmax, 3, "pair:xsph");
  if (vswitch_flag || dalpha) memory->grow(dalpha, nmax, "pair:dalpha");
  for (int i = old; i < nmax; i++) {
    if (dalpha) dalpha[i] = 0.0;
    drho[i] = de[i] = dh[i] = 0.0;
    for (int k = 0; k < 6; k++) ds[i][k] = 0.0;
    for (int k = 0; k < 3; k++) bvel[i][k] = bspin[i][k] = 0.0;
  }
}

/* ---------------------------------------------------------------------- */

/* ----------------------------------------------------------------------
   fix esph/integrate scheme staggered, between its kick and drift: the
   rates (velocity gradient, continuity, stress and energy rates) of the
   current positions and the state the integrator has set in its
   prediction (v^(n+1/2), state of step n). The pass's forces are discarded
   and what it stored for the next step (normals, gaps, engagement) is
   undone: the force computation of the step starts from what this pass saw.
------------------------------------------------------------------------- */

void PairESPHSolid::stagger_rates()
{
  stagger_save();
  compute(0, 0);
  stagger_restore();
}

/* ----------------------------------------------------------------------
   staggered scheme: what the rate pass changes outside its own rates (the
   forces, with those of other styles already in f; the stored contact
   geometry of owned atoms; the flags of the force computation)
------------------------------------------------------------------------- */

void PairESPHSolid::stagger_save()
{
  const int nall = atom->nlocal + atom->nghost;
  const int nlocal = atom->nlocal;
  stagger_f.resize(3 * (size_t) nall);
  if (nall > 0) memcpy(stagger_f.data(), &atom->f[0][0], sizeof(double) * 3 * nall);
  stagger_geom.resize(NGEOM * (size_t) nlocal);
  for (int i = 0; i < nlocal; i++) {
    double *g = &stagger_geom[NGEOM * (size_t) i];
    for (int d = 0; d < 3; d++) g[d] = state->n[i][d];
    g[3] = state->gap[i];
    g[4] = state->gapv[i];
    g[5] = state->eng[i];
    g[6] = state->depth[i];
    if (state->cone)
      for (int k = 0; k < 6; k++) {
        g[7 + k] = state->cone[i][k];
        g[13 + k] = state->coneu[i][k];
      }
    if (state->fric)
      for (int k = 0; k < 3; k++) {
        g[19 + k] = state->fric[i][k];
        g[22 + k] = state->fricu[i][k];
      }
  }
  stagger_flags[0] = normals_valid;
  stagger_flags[1] = dt_keep;
}

void PairESPHSolid::stagger_restore()
{
  const int nall = atom->nlocal + atom->nghost;
  const int nlocal = atom->nlocal;
  if (nall > 0) memcpy(&atom->f[0][0], stagger_f.data(), sizeof(double) * 3 * nall);
  for (int i = 0; i < nlocal; i++) {
    const double *g = &stagger_geom[NGEOM * (size_t) i];
    for (int d = 0; d < 3; d++) state->n[i][d] = g[d];
    state->gap[i] = g[3];
    state->gapv[i] = g[4];
    state->eng[i] = g[5];
    state->depth[i] = g[6];
    if (state->cone)
      for (int k = 0; k < 6; k++) {
        state->cone[i][k] = g[7 + k];
        state->coneu[i][k] = g[13 + k];
      }
    if (state->fric)
      for (int k = 0; k < 3; k++) {
        state->fric[i][k] = g[19 + k];
        state->fricu[i][k] = g[22 + k];
      }
  }
  normals_valid = stagger_flags[0];
  dt_keep = stagger_flags[1];
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::compute(int eflag, int vflag)
{
  ev_init(eflag, vflag);
  grow_work();
  state->fetch();
  if (!dt_keep) dt_step = update->dt;
  dt_keep = 0;

  const int nall = atom->nlocal + atom->nghost;
  const int bnd = (nboundary > 0);

  // forward communication of what neighbours need, in one message
  comm_bnd = bnd;
  nforward = 12 + (bnd ? 6 + (qcol_n >= 0 ? 6 : 0) : 0) + (heat_flag ? 2 : 0) +
      (vswitch_flag ? 1 : 0) + (recon_flag ? 6 : 0);
  // the buffers of the communication are sized by comm_forward
  if (nforward > comm_forward)
    error->one(FLERR,
               "Pair esph/solid: internal error, {} values per atom to communicate, {} sized",
               nforward, comm_forward);
  const int touch = bnd && touch_on_run;
  if (bnd && !normals_valid) compute_normals(touch);
  // (before hoist(), which then also writes the slots only the vector pass reads)
  simd_active = simd_ready();
  hoist();
  comm_stage = COMM_HOIST;
  comm->forward_comm(this, nforward);

  // without boundary particles or gradient correction only G and the heating terms
  // (the cone sums, the last 6 slots, only with contact/normal cone)
  nreverse = (bnd || correct_flag || xsph_flag) ? acc_cols : 11;
  // (the rows are contiguous, memory->create(): all columns of a chunk of rows at once where
  // every column is cleared, instead of a call per row)
  const int ncols = acc_cols, nrev = nreverse;
  ESPH::for_chunks(nthreads, nall, [=](int from, int to, int) {
    if (nrev == ncols && to > from)
      memset(acc[from], 0, sizeof(double) * ncols * (size_t) (to - from));
    else
      for (int i = from; i < to; i++) memset(acc[i], 0, sizeof(double) * nrev);
  });

  // (the correction weighs cross-body pairs as the pair pass does: the same touch)
  const int touch_first = touch && correct_flag >= CORRECT_BONETLOK;
  if (touch_first) update_touch(0);
  if (correct_flag >= CORRECT_BONETLOK) correction();
  if (astress_flag) artificial_stress();

  if (atom_contact_flag) atom_contact_clear();
  if (simd_active) {
    simd_pack();
    simd_split(bnd);
  }
  if (touch && !touch_first) update_touch(simd_active);
  surf_on = surface_sums();
  pair_pass(bnd);
  if (bnd && friction > 0.0 && contact != CONTACT_OFF) friction_pass();

  if (force->newton_pair) {
    comm_stage = COMM_ACC;
    comm->reverse_comm(this, nreverse);
    if (atom_contact_flag) {
      comm_stage = COMM_ATOM_CONTACT;
      comm->reverse_comm(this, 2);
    }
  }
  if (couple_on && bnd) contact_couple();
  finalize(eflag);
  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   fix esph/boundary of the run, if any, and its particle spacing
------------------------------------------------------------------------- */

FixESPHBoundary *PairESPHSolid::boundary_fix() const
{
  const auto fixes = modify->get_fix_by_style("^esph/boundary$");
  return fixes.empty() ? nullptr : dynamic_cast<FixESPHBoundary *>(fixes[0]);
}

/* ----------------------------------------------------------------------
   the spacing of each body from the fixes esph/boundary whose groups hold
   its real particles (collective): bodies may sit on lattices of different
   spacings, each with a fix of its own (the touch's cells, the reach of the
   gap's partners and the checks use them); a body in the groups of two
   fixes with different spacings is an error
------------------------------------------------------------------------- */

void PairESPHSolid::init_spacings()
{
  const auto fixes = modify->get_fix_by_style("^esph/boundary$");
  body_spacings.clear();
  spacing_lo = spacing_hi = 0.0;
  if (fixes.empty()) return;
  // (a fix with given boundary particles may have no spacing: it gives none)
  std::vector<double> sp;
  for (const auto *f : fixes) {
    sp.push_back(dynamic_cast<const FixESPHBoundary *>(f)->get_spacing());
    if (sp.back() > 0.0) {
      spacing_lo = (spacing_lo > 0.0) ? MIN(spacing_lo, sp.back()) : sp.back();
      spacing_hi = MAX(spacing_hi, sp.back());
    }
  }
  if (spacing_lo == spacing_hi) return;
  // (body, fix) of the real particles in the fixes' groups, gathered on every rank
  state->fetch();
  std::vector<long long> mine;
  for (int i = 0; i < atom->nlocal; i++) {
    if (!(state->rmass[i] > 0.0)) continue;
    const int b = state->body ? state->body[i] : 0;
    for (size_t k = 0; k < fixes.size(); k++)
      if (sp[k] > 0.0 && (atom->mask[i] & fixes[k]->groupbit)) mine.push_back(pack_key(b, (int) k));
  }
  for (long long key : ESPHCheck::global_set(lmp, mine)) {
    int b, k;
    unpack_key(key, b, k);
    if (!body_spacings.empty() && body_spacings.back().first == b) {
      if (body_spacings.back().second != sp[k])
        error->all(FLERR, Error::NOLASTLINE,
                   "Body {} (i_esph_body) has real particles in the groups of fixes esph/boundary "
                   "with spacings {} and {}: a body is on one lattice; give each body one spacing",
                   b, body_spacings.back().second, sp[k]);
      continue;
    }
    body_spacings.emplace_back(b, sp[k]);
  }
  // (the keys sort the bodies as unsigned numbers)
  std::sort(body_spacings.begin(), body_spacings.end());
}

/* the spacing of body b (the smallest spacing where no fix with a spacing holds it) */

double PairESPHSolid::spacing_of(int b) const
{
  if (spacing_lo == spacing_hi) return spacing_lo;
  const auto it = std::lower_bound(body_spacings.begin(), body_spacings.end(), b,
                                   [](const std::pair<int, double> &p, int key) {
                                     return p.first < key;
                                   });
  return (it != body_spacings.end() && it->first == b) ? it->second : spacing_lo;
}

/* ----------------------------------------------------------------------
   fix esph/boundary turn body: the bodies in the groups of the fixes with
   turn body (body IDs do not change during a run), less those that extend
   over more than half of a periodic box, and a reference point of each
------------------------------------------------------------------------- */

void PairESPHSolid::init_turn()
{
  turn_body = 0;
  turn_bodies.clear();
  turn_ref.clear();
  std::vector<int> bodies;
  int any = 0;
  for (auto *f : modify->get_fix_by_style("^esph/boundary$")) {
    const auto *bf = dynamic_cast<FixESPHBoundary *>(f);
    if (!bf || !bf->turns_with_body()) continue;
    any = 1;
    if (dim > 1)
      for (const auto &kv : ESPHCheck::body_counts(lmp, state, bf->groupbit))
        bodies.push_back(kv.first);
  }
  if (any && dim == 1 && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/boundary turn body has no effect with pair esph/solid dimension 1 "
                   "(the normals are +-x and never turn): drop it");
  if (bodies.empty()) return;
  std::sort(bodies.begin(), bodies.end());
  bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
  const std::vector<int> wide =
      ESPH::body_reference(lmp, state, group->bitmask[0], bodies, turn_ref);
  turn_bodies.swap(bodies);
  if (!wide.empty() && comm->me == 0)
    error->warning(FLERR,
                   "Fix esph/boundary turn body: {} bod{} ({}{}) extend{} over more than half "
                   "of a periodic box length and {} no rigid rotation (spanning the box, or "
                   "too long for the minimum image): {} normals turn with the interpolated "
                   "spin (turn spin)",
                   wide.size(), wide.size() > 1 ? "ies" : "y", wide[0],
                   wide.size() > 1 ? ", ..." : "", wide.size() > 1 ? "" : "s",
                   wide.size() > 1 ? "have" : "has", wide.size() > 1 ? "their" : "its");
  turn_body = !turn_bodies.empty();
}

/* ----------------------------------------------------------------------
   the pair loop over the whole neighbour list into acc, atom->f and
   atom_contact, and its contact tallies (pair esph/solid/omp: in threads)
------------------------------------------------------------------------- */

void PairESPHSolid::pair_pass(int bnd)
{
  // keep the nodes of body pairs seen before: no allocation in the pair loop once known
  for (auto &kv : body_tally) kv.second.fill(0.0);
  LoopOut out{0, list->inum, acc, atom->f, atom_contact, &body_tally, 0, 0, 0.0};
  fric_pairs.clear();
  out.fric = &fric_pairs;
  run_pair_loop(bnd, out);
  if (simd_active) bulk_pass(out);
  ncontact_pairs = out.ncontact;
  ntouch_pairs = out.ntouch;
  fcontact = out.fcontact;
  dt_cfl = std::min(dt_cfl, out.dtcross);
}

/* ----------------------------------------------------------------------
   add the accumulated sums src[0..k1-k0) to the slots k0..k1-1 of the acc
   row dst: sums, except the gap candidates of a boundary particle (bnd),
   of which the better one is kept (contact_bnd_merge); the reverse
   communication and the threads' private rows (pair esph/solid/omp)
------------------------------------------------------------------------- */

void PairESPHSolid::combine_acc_row(double *dst, const double *src, int k0, int k1, int bnd) const
{
  const int gaps = bnd && (k0 <= B_GAP) && (k1 > B_GAP);
  for (int k = k0; k < k1; k++) {
    if (gaps && k == B_GAP) {
      contact_bnd_merge(dst + B_GAP, src + (k - k0));
      k += GAP_SLOTS - 1;
    } else {
      dst[k] += src[k - k0];
    }
  }
}

/* ---------------------------------------------------------------------- */

int PairESPHSolid::pack_forward_comm(int n, int *list, double *buf, int /*pbc_flag*/, int * /*pbc*/)
{
  int m = 0;
  if (comm_stage == COMM_NORMALS) {
    for (int i = 0; i < n; i++) {
      const double *q = hq[list[i]];
      for (int k = 0; k < 3; k++) buf[m++] = q[Q_N + k];
      buf[m++] = q[Q_H];
      for (int k = 0; k < 3; k++) buf[m++] = q[Q_V + k];
      buf[m++] = q[Q_ENG];
    }
    return m;
  }
  if (comm_stage == COMM_GAPS) {
    for (int i = 0; i < n; i++) {
      const double *q = hq[list[i]];
      buf[m++] = q[Q_GAP];
      buf[m++] = q[Q_GAPV];
    }
    return m;
  }
  if (comm_stage == COMM_CORR) {
    for (int i = 0; i < n; i++) {
      const double *q = hq[list[i]] + qcol_b;
      for (int k = 0; k < 9; k++) buf[m++] = q[k];
    }
    return m;
  }
  if (comm_stage == COMM_COUPLE) {
    for (int i = 0; i < n; i++)
      for (int k = couple_k0; k < couple_k1; k++) buf[m++] = cpl[list[i]][k];
    return m;
  }
  if (comm_stage == COMM_TOUCH) {
    for (int i = 0; i < n; i++)
      for (int k = 0; k < 9; k++) buf[m++] = touch_frame[9 * (size_t) list[i] + k];
    return m;
  }
  if (comm_stage == COMM_FRIC) {
    for (int i = 0; i < n; i++) {
      buf[m++] = acc[list[i]][A_FSUM];
      for (int k = 0; k < 3; k++) buf[m++] = fric_held[list[i]][k];
    }
    return m;
  }
  for (int i = 0; i < n; i++) {
    const double *q = hq[list[i]];
    for (int k = Q_V; k < Q_A + 6; k++) buf[m++] = q[k];
    buf[m++] = q[Q_H];
    if (comm_bnd) {
      for (int k = Q_N; k <= Q_GAP; k++) buf[m++] = q[k];
      buf[m++] = q[Q_GAPV];
      buf[m++] = q[Q_ENG];
      if (qcol_n >= 0)
        for (int k = 0; k < 6; k++) buf[m++] = q[qcol_n + k];
    }
    if (heat_flag) {
      buf[m++] = q[Q_E];
      buf[m++] = q[Q_ZETA];
    }
    if (vswitch_flag) buf[m++] = q[Q_ALPHA];
    if (recon_flag)
      for (int k = 0; k < 6; k++) buf[m++] = q[qcol_d + k];
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::unpack_forward_comm(int n, int first, double *buf)
{
  int m = 0;
  const int last = first + n;
  if (comm_stage == COMM_NORMALS) {
    for (int i = first; i < last; i++) {
      double *q = hq[i];
      for (int k = 0; k < 3; k++) q[Q_N + k] = buf[m++];
      q[Q_H] = buf[m++];
      for (int k = 0; k < 3; k++) q[Q_V + k] = buf[m++];
      q[Q_ENG] = buf[m++];
    }
    return;
  }
  if (comm_stage == COMM_GAPS) {
    for (int i = first; i < last; i++) {
      hq[i][Q_GAP] = buf[m++];
      hq[i][Q_GAPV] = buf[m++];
    }
    return;
  }
  if (comm_stage == COMM_CORR) {
    for (int i = first; i < last; i++) {
      double *q = hq[i] + qcol_b;
      for (int k = 0; k < 9; k++) q[k] = buf[m++];
    }
    return;
  }
  if (comm_stage == COMM_COUPLE) {
    for (int i = first; i < last; i++)
      for (int k = couple_k0; k < couple_k1; k++) cpl[i][k] = buf[m++];
    return;
  }
  if (comm_stage == COMM_TOUCH) {
    for (int i = first; i < last; i++)
      for (int k = 0; k < 9; k++) touch_frame[9 * (size_t) i + k] = buf[m++];
    return;
  }
  if (comm_stage == COMM_FRIC) {
    // (the slot of a boundary particle is one of its gap candidates': left alone)
    const double *rmass = state->rmass;
    for (int i = first; i < last; i++, m += 4) {
      if (rmass[i] > 0.0) acc[i][A_FSUM] = buf[m];
      for (int k = 0; k < 3; k++) fric_held[i][k] = buf[m + 1 + k];
    }
    return;
  }
  for (int i = first; i < last; i++) {
    double *q = hq[i];
    for (int k = Q_V; k < Q_A + 6; k++) q[k] = buf[m++];
    q[Q_H] = buf[m++];
    if (comm_bnd) {
      for (int k = Q_N; k <= Q_GAP; k++) q[k] = buf[m++];
      q[Q_GAPV] = buf[m++];
      q[Q_ENG] = buf[m++];
      if (qcol_n >= 0)
        for (int k = 0; k < 6; k++) q[qcol_n + k] = buf[m++];
    }
    if (heat_flag) {
      q[Q_E] = buf[m++];
      q[Q_ZETA] = buf[m++];
    }
    if (vswitch_flag) q[Q_ALPHA] = buf[m++];
    if (recon_flag)
      for (int k = 0; k < 6; k++) q[qcol_d + k] = buf[m++];
  }
}

/* ----------------------------------------------------------------------
   reverse communication: sums, except for the gap candidates of boundary
   particles, of which the better one is kept (contact_bnd_keep)
------------------------------------------------------------------------- */

int PairESPHSolid::pack_reverse_comm(int n, int first, double *buf)
{
  int m = 0;
  const int last = first + n;
  if (comm_stage == COMM_ATOM_CONTACT) {
    for (int i = first; i < last; i++) {
      buf[m++] = atom_contact[i][0];
      buf[m++] = atom_contact[i][1];
    }
    return m;
  }
  if (comm_stage == COMM_TOUCH) {
    for (int i = first; i < last; i++) buf[m++] = touch_mark[i];
    return m;
  }
  if (comm_stage == COMM_FRIC) {
    for (int i = first; i < last; i++) buf[m++] = acc[i][A_FSUM];
    return m;
  }
  if (comm_stage == COMM_FRIC_FOUND) {
    for (int i = first; i < last; i++)
      for (int k = 0; k < 3; k++) buf[m++] = fric_found[i][k];
    return m;
  }
  if (comm_stage == COMM_COUPLE) {
    // (the rows of atoms without a couple hold nothing)
    for (int i = first; i < last; i++)
      for (int k = couple_k0; k < couple_k1; k++) buf[m++] = cflag[i] ? cpl[i][k] : 0.0;
    return m;
  }
  for (int i = first; i < last; i++) {
    const double *a = acc[i];
    if (comm_stage == COMM_NORMALS) {
      for (int k = A_NSUM; k <= A_WSUM; k++) buf[m++] = a[k];
      for (int k = A_GW; k < GAP_END; k++) buf[m++] = a[k];
      if (qcol_n >= 0)
        for (int k = A_NN; k < A_NN + 6; k++) buf[m++] = a[k];
    } else if (comm_stage == COMM_CORR) {
      for (int k = A_M; k < A_M + 9; k++) buf[m++] = a[k];
    } else if (comm_stage == COMM_GAPS) {
      for (int k = A_GW; k < GAP_END; k++) buf[m++] = a[k];
    } else {
      for (int k = 0; k < nreverse; k++) buf[m++] = a[k];
    }
  }
  return m;
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::unpack_reverse_comm(int n, int *list, double *buf)
{
  int m = 0;
  if (comm_stage == COMM_ATOM_CONTACT) {
    for (int i = 0; i < n; i++) {
      atom_contact[list[i]][0] += buf[m++];
      atom_contact[list[i]][1] += buf[m++];
    }
    return;
  }
  if (comm_stage == COMM_TOUCH) {
    for (int i = 0; i < n; i++) touch_mark[list[i]] += buf[m++];
    return;
  }
  if (comm_stage == COMM_FRIC) {
    // (the slot of a boundary particle is one of its gap candidates': left alone)
    const double *rmass = state->rmass;
    for (int i = 0; i < n; i++, m++)
      if (rmass[list[i]] > 0.0) acc[list[i]][A_FSUM] += buf[m];
    return;
  }
  if (comm_stage == COMM_FRIC_FOUND) {
    for (int i = 0; i < n; i++)
      for (int k = 0; k < 3; k++) fric_found[list[i]][k] += buf[m++];
    return;
  }
  if (comm_stage == COMM_COUPLE) {
    for (int i = 0; i < n; i++)
      for (int k = couple_k0; k < couple_k1; k++) cpl[list[i]][k] += buf[m++];
    return;
  }
  const double *rmass = state->rmass;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    double *a = acc[j];
    int k0 = 0, k1 = nreverse;
    if (comm_stage == COMM_NORMALS) {
      for (int k = A_NSUM; k <= A_WSUM; k++) a[k] += buf[m++];
      combine_acc_row(a, buf + m, A_GW, GAP_END, rmass[j] == 0.0);
      m += GAP_END - A_GW;
      k0 = A_NN;
      k1 = (qcol_n >= 0) ? A_NN + 6 : A_NN;
    } else if (comm_stage == COMM_GAPS) {
      k0 = A_GW;
      k1 = GAP_END;
    } else if (comm_stage == COMM_CORR) {
      k0 = A_M;
      k1 = A_M + 9;
    }
    combine_acc_row(a, buf + m, k0, k1, rmass[j] == 0.0);
    m += k1 - k0;
  }
}

/* ---------------------------------------------------------------------- */

double PairESPHSolid::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) nmax * (acc_cols + hq_cols + 3 + 6 + 3 + 3) * sizeof(double);
  if (xsph) bytes += (double) nmax * 3 * sizeof(double);
  if (cpl) bytes += (double) nmax * 10 * sizeof(double) + (double) cflag.capacity();
  if (dalpha) bytes += (double) nmax * sizeof(double);
  bytes += (double) atom_contact_nmax * 2 * sizeof(double);
  bytes += (double) (touch_mark.capacity() + touch_frame.capacity()) * sizeof(double);
  // friction: the static friction held and found, the recorded cross-body pairs
  bytes +=
      (double) fric_nmax * 6 * sizeof(double) + (double) fric_pairs.capacity() * sizeof(FricPair);
  // the vector pass: the scalar loop's split list (the full list is counted by the
  // neighbor lists; its rows are hq's)
  bytes += (double) (simd_first.capacity() + simd_j.capacity() + simd_nbulk.capacity() +
                     simd_nbnd.capacity() + simd_own_first.capacity() + simd_own_j.capacity()) *
      sizeof(int);
  return bytes;
}

/* ---------------------------------------------------------------------- */

void *PairESPHSolid::extract(const char *str, int &dim_out)
{
  dim_out = 0;
  if (strcmp(str, "h") == 0) return (void *) &h0;
  if (strcmp(str, "cut") == 0) return (void *) &cut_global;
  // (an int: the last force computation used the vector pass; for tests and diagnostics)
  if (strcmp(str, "simd_active") == 0) return (void *) &simd_active;
  return nullptr;
}
