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
   pair esph/solid: the user's words. set_defaults() gives every optional
   pair_style keyword its default, settings() reads the pair_style line,
   coeff() the pair_coeff lines (material, equation of state, strength,
   rigid types); every bad word is an error that names it and what is
   expected.
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "memory.h"
#include "modify.h"

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

/* ----------------------------------------------------------------------
   defaults of the optional pair_style keywords
------------------------------------------------------------------------- */

void PairESPHSolid::set_defaults()
{
  kernel = CUBIC;
  dim = domain->dimension;
  alpha = beta = 1.0;
  eps = 0.1;
  vswitch_flag = 0;
  vswitch_min = 0.1;
  vswitch_l = 0.2;
  recon_set = RECON_VANLEER;
  recon_flag = RECON_OFF;
  recon_given = 0;
  recon_warned = 0;
  hybrid_warned = 0;
  heat_flag = 0;
  g1 = g2 = 0.0;
  hvar_flag = 0;
  hmax = 1.0;
  contact = CONTACT_SOLID;
  gaptol = 0.05;
  onset = 5;
  cone_flag = 0;
  cone_on = 0;
  couple_flag = 0;
  gap_plane = 0;
  gap_touch = 1;
  couple_on = 0;
  correct_flag = CORRECT_RATE;
  astress_flag = 0;
  astress_eps = 0.0;
  astress_n = 4;
  astress_dp = 0.0;
  xsph_flag = 0;
  xsph_eps = 0.0;
  friction = 0.0;
  fric_held = fric_found = nullptr;
  fric_nmax = 0;
  simd_set = 1;
}

/* ---------------------------------------------------------------------- */

PairESPHSolid::~PairESPHSolid()
{
  if (copymode) return;
  delete state;
  memory->destroy(acc);
  memory->destroy(hq);
  memory->destroy(drho);
  memory->destroy(de);
  memory->destroy(dh);
  memory->destroy(ds);
  memory->destroy(dalpha);
  memory->destroy(bvel);
  memory->destroy(bspin);
  memory->destroy(xsph);
  memory->destroy(cpl);
  memory->destroy(atom_contact);
  memory->destroy(fric_held);
  memory->destroy(fric_found);
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
    delete[] eos;
    memory->destroy(shear);
    memory->destroy(yield);
    memory->destroy(hardening);
    memory->destroy(rigid);
    memory->destroy(matset);
  }
}

/* ---------------------------------------------------------------------- */

void PairESPHSolid::allocate()
{
  allocated = 1;
  const int n = atom->ntypes + 1;
  memory->create(setflag, n, n, "pair:setflag");
  memory->create(cutsq, n, n, "pair:cutsq");
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) setflag[i][j] = 0;
  eos = new EOS[n];
  memory->create(shear, n, "pair:shear");
  memory->create(yield, n, "pair:yield");
  memory->create(hardening, n, "pair:hardening");
  memory->create(rigid, n, "pair:rigid");
  memory->create(matset, n, "pair:matset");
  for (int i = 0; i < n; i++) {
    matset[i] = 0;
    shear[i] = 0.0;
    yield[i] = 0.0;
    hardening[i] = 0.0;
    rigid[i] = 0;
    eos[i] = EOS{EOS_LINEAR, 0.0, 0.0, 0.0, 0.0, 0.0};
  }
}

/* ----------------------------------------------------------------------
   pair_style esph/solid h keyword value ...
------------------------------------------------------------------------- */

void PairESPHSolid::settings(int narg, char **arg)
{
  if (narg < 1) utils::missing_cmd_args(FLERR, "pair_style esph/solid", error);
  // a new pair_style command starts from the defaults
  set_defaults();
  h0 = utils::numeric(FLERR, arg[0], false, lmp);
  if (h0 <= 0.0)
    error->all(FLERR, 1, "Pair esph/solid smoothing length h must be > 0, got {}", arg[0]);

  // keywords given that only contact solid reads (a warning under the other rules)
  std::vector<std::string> solid_only;
  int iarg = 1;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "kernel") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid kernel", error);
      if (strcmp(arg[iarg + 1], "cubic") == 0)
        kernel = CUBIC;
      else if (strcmp(arg[iarg + 1], "wendland") == 0)
        kernel = WENDLAND;
      else
        error->all(FLERR, iarg + 2, "Unknown pair esph/solid kernel {}: expected cubic or wendland",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "dimension") == 0) {
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid dimension", error);
      dim = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (dim < 1 || dim > domain->dimension)
        error->all(FLERR, iarg + 2,
                   "Pair esph/solid dimension must be 1 .. {} (the box dimension), got {}",
                   domain->dimension, arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "visc") == 0) {
      if (iarg + 3 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid visc", error);
      alpha = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      beta = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      eps = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (alpha < 0.0 || beta < 0.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid visc alpha and beta must be >= 0");
      if (eps <= 0.0) error->all(FLERR, iarg + 4, "Pair esph/solid visc epsilon must be > 0");
      iarg += 4;
    } else if (strcmp(arg[iarg], "visc/switch") == 0) {
      if (iarg + 1 < narg && strcmp(arg[iarg + 1], "off") == 0) {
        vswitch_flag = 0;
        iarg += 2;
        continue;
      }
      if (iarg + 2 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid visc/switch", error);
      vswitch_min = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      vswitch_l = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (vswitch_min <= 0.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid visc/switch alpha_min must be > 0, got {}",
                   arg[iarg + 1]);
      if (vswitch_l <= 0.0 || vswitch_l > 1.0)
        error->all(FLERR, iarg + 3, "Pair esph/solid visc/switch l must be in (0, 1], got {}",
                   arg[iarg + 2]);
      vswitch_flag = 1;
      iarg += 3;
    } else if (strcmp(arg[iarg], "visc/recon") == 0) {
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid visc/recon", error);
      recon_given = 1;
      if (strcmp(arg[iarg + 1], "vanleer") == 0)
        recon_set = RECON_VANLEER;
      else if (strcmp(arg[iarg + 1], "minmod") == 0)
        recon_set = RECON_MINMOD;
      else if (strcmp(arg[iarg + 1], "off") == 0)
        recon_set = RECON_OFF;
      else
        error->all(FLERR, iarg + 1,
                   "Pair esph/solid visc/recon must be vanleer, minmod or off, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "heat") == 0) {
      if (iarg + 2 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid heat", error);
      g1 = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      g2 = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
      if (g1 < 0.0 || g2 < 0.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid heat g1 and g2 must be >= 0");
      heat_flag = (g1 > 0.0 || g2 > 0.0) ? 1 : 0;
      iarg += 3;
    } else if (strcmp(arg[iarg], "hvar") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid hvar", error);
      hmax = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (hmax < 1.0)
        error->all(FLERR, iarg + 2,
                   "Pair esph/solid hvar needs the largest allowed h/h0 (>= 1), got {}",
                   arg[iarg + 1]);
      hvar_flag = 1;
      iarg += 2;
    } else if (strcmp(arg[iarg], "contact") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid contact", error);
      if (strcmp(arg[iarg + 1], "off") == 0)
        contact = CONTACT_OFF;
      else if (strcmp(arg[iarg + 1], "solid") == 0)
        contact = CONTACT_SOLID;
      else if (strcmp(arg[iarg + 1], "paper") == 0)
        contact = CONTACT_PAPER;
      else
        error->all(FLERR, iarg + 2,
                   "Unknown pair esph/solid contact rule {}: expected off, solid or paper",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "gradient") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid gradient", error);
      if (strcmp(arg[iarg + 1], "plain") == 0)
        correct_flag = CORRECT_PLAIN;
      else if (strcmp(arg[iarg + 1], "corrected") == 0)
        correct_flag = CORRECT_RATE;
      else if (strcmp(arg[iarg + 1], "bonet/lok") == 0)
        correct_flag = CORRECT_BONETLOK;
      else if (strcmp(arg[iarg + 1], "torquefree") == 0)
        correct_flag = CORRECT_TORQUEFREE;
      else
        error->all(FLERR, iarg + 2,
                   "Unknown pair esph/solid gradient {}: expected plain, corrected, bonet/lok or "
                   "torquefree",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "artstress") == 0) {
      if (iarg + 3 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid artstress", error);
      astress_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      astress_n = utils::inumeric(FLERR, arg[iarg + 2], false, lmp);
      astress_dp = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
      if (astress_eps < 0.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid artstress epsilon must be >= 0, got {}",
                   arg[iarg + 1]);
      if (astress_n < 1)
        error->all(FLERR, iarg + 3, "Pair esph/solid artstress exponent n must be >= 1, got {}",
                   arg[iarg + 2]);
      if (astress_dp <= 0.0)
        error->all(FLERR, iarg + 4, "Pair esph/solid artstress spacing dp must be > 0, got {}",
                   arg[iarg + 3]);
      astress_flag = (astress_eps > 0.0);
      // (W / W(dp))^n is a hard core for a large n: a helper's n = 1000 lost atoms at once
      if (astress_flag && astress_n > 8 && comm->me == 0)
        error->warning(FLERR,
                       "Pair esph/solid artstress exponent {}: the repulsion grows as (W / "
                       "W(dp))^{} below the spacing dp, a hard core that the time step does "
                       "not resolve (published and tested: 4); use n from 2 to 8",
                       astress_n, astress_n);
      iarg += 4;
    } else if (strcmp(arg[iarg], "simd") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid simd", error);
      simd_set = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else if (strcmp(arg[iarg], "xsph") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid xsph", error);
      xsph_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (xsph_eps < 0.0 || xsph_eps > 1.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid xsph epsilon must be in [0, 1], got {}",
                   arg[iarg + 1]);
      xsph_flag = (xsph_eps > 0.0);
      iarg += 2;
    } else if (strcmp(arg[iarg], "onset") == 0) {
      solid_only.emplace_back("onset");
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid onset", error);
      onset = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (onset < 0)
        error->all(FLERR, iarg + 2, "Pair esph/solid onset must be >= 0 steps, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "contact/normal") == 0) {
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid contact/normal", error);
      if (strcmp(arg[iarg + 1], "cone") == 0)
        cone_flag = 1;
      else if (strcmp(arg[iarg + 1], "mean") == 0)
        cone_flag = 0;
      else
        error->all(FLERR, iarg + 2, "Pair esph/solid contact/normal must be cone or mean, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "contact/gap") == 0) {
      solid_only.emplace_back("contact/gap");
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid contact/gap", error);
      gap_plane = gap_touch = 0;
      if (strcmp(arg[iarg + 1], "touch") == 0)
        gap_touch = 1;
      else if (strcmp(arg[iarg + 1], "plane") == 0)
        gap_plane = 1;
      else if (strcmp(arg[iarg + 1], "projection") != 0)
        error->all(FLERR, iarg + 2,
                   "Pair esph/solid contact/gap must be touch, projection or plane, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "contact/couple") == 0) {
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_style esph/solid contact/couple", error);
      couple_flag = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else if (strcmp(arg[iarg], "friction") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid friction", error);
      friction = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (friction < 0.0 || !std::isfinite(friction))
        error->all(FLERR, iarg + 2,
                   "Pair esph/solid friction coefficient must be a finite number >= 0, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "gap/tol") == 0) {
      solid_only.emplace_back("gap/tol");
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid gap/tol", error);
      gaptol = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (gaptol < 0.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid gap/tol must be >= 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else {
      error->all(FLERR, iarg + 1, "Unknown pair_style esph/solid keyword: {}", arg[iarg]);
    }
  }
  if (friction > 0.0 && contact == CONTACT_OFF && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid friction {} has no effect with contact off (bodies do not "
                   "touch): use contact solid or paper",
                   friction);
  // legal but meaningless contact settings (measured: a ramp of 1000 steps never coupled a
  // short contact; a cap of 1e300 lets separating pairs push across any gap)
  if (contact == CONTACT_SOLID && onset > ONSET_WARN && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid onset {}: the coupling of a newly touching pair builds over "
                   "{} steps while the bodies move into each other, and a contact shorter than "
                   "that never couples fully (tested: 0 to 5, default 5); use at most {}",
                   onset, onset, ONSET_WARN);
  if (contact == CONTACT_SOLID && gaptol > 1.0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid gap/tol {}: separating pairs may push across an open gap of "
                   "up to {} smoothing lengths, i.e. between surfaces that are visibly apart "
                   "(default 0.05); use a value below 1",
                   gaptol, gaptol);
  if (astress_flag && astress_dp >= KERNEL_SUPPORT * h0)
    error->all(FLERR,
               "Pair esph/solid artstress spacing dp = {} must be below the kernel support "
               "{} x h = {}",
               astress_dp, KERNEL_SUPPORT, KERNEL_SUPPORT * h0);
  if (vswitch_flag && vswitch_min > alpha)
    error->all(FLERR,
               "Pair esph/solid visc/switch alpha_min {} must not exceed the visc alpha {} (its "
               "ceiling)",
               vswitch_min, alpha);
  // the switched coefficient is per-atom state, like the density
  if (vswitch_flag) ESPHState::ensure_visc(lmp);
  // without a viscosity there is nothing to reconstruct: the default's reconstruction is
  // then off (it would cost without effect); a visc/recon given explicitly is warned about
  if (recon_set && alpha == 0.0 && beta == 0.0) {
    if (recon_given && comm->me == 0)
      error->warning(FLERR,
                     "Pair esph/solid visc/recon with visc alpha and beta 0 has no effect (there "
                     "is no viscosity to reconstruct): set visc alpha or beta > 0, or drop "
                     "visc/recon");
    recon_set = RECON_OFF;
  }
  // its strain rates are per-atom state (restart files): made here, so that a restart file's
  // rates are taken up before a command between read_restart and the run moves atoms
  // (delete_atoms); a run that has no use for them drops them (init_recon())
  if (recon_set) ESPHState::ensure_recon(lmp);
  // so are the plastic strain and the switched viscosity's alpha, which a restart file may
  // hold although this scene has no yield stress or switch yet (a later run may give them
  // again): made to take them up, dropped by drop_unused_state() where they are 0 everywhere
  if (modify->nfix_restart_peratom > 0) {
    ESPHState::ensure_plastic(lmp);
    ESPHState::ensure_visc(lmp);
  }
  // and the normal cones (carried from one force computation to the next; made here, before
  // a read_data that names their sections)
  if (cone_flag && contact == CONTACT_SOLID) ESPHState::ensure_cone(lmp);
  // and the static part of the friction (the same)
  if (friction > 0.0 && contact != CONTACT_OFF) ESPHState::ensure_fric(lmp);
  if (contact == CONTACT_PAPER && alpha == 0.0 && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid contact paper with visc alpha 0: the paper's gate (only "
                   "approaching pairs interact) then gains energy at every switch (+67 % in "
                   "the 1D rod impact); use contact solid or a visc alpha > 0");
  // the gate of contact solid: its keywords mean nothing to the other rules
  for (const auto &word : solid_only)
    if (contact != CONTACT_SOLID && comm->me == 0)
      error->warning(FLERR,
                     "Pair esph/solid {} applies to contact solid only (the gap gate); contact "
                     "{} ignores it: drop {} or use contact solid",
                     word, contact == CONTACT_PAPER ? "paper" : "off", word);
  if (cone_flag && contact != CONTACT_SOLID && comm->me == 0)
    error->warning(FLERR,
                   "Pair esph/solid contact/normal cone applies to contact solid only; contact "
                   "{} uses no common normal of cones: drop contact/normal or use contact solid",
                   contact == CONTACT_PAPER ? "paper" : "off");
  cut_global = KERNEL_SUPPORT * h0 * hmax;
}

/* ----------------------------------------------------------------------
   pair_coeff I I rho0 value shear value eos linear K
   pair_coeff I I rho0 value shear value eos mie/gruneisen c0 s gamma0
   materials are per type: I and J must be the same type or range
------------------------------------------------------------------------- */

void PairESPHSolid::coeff(int narg, char **arg)
{
  if (narg < 2) error->all(FLERR, "Incorrect args for pair coefficients" + utils::errorurl(21));
  if (!allocated) allocate();

  int ilo, ihi, jlo, jhi;
  utils::bounds(FLERR, arg[0], 1, atom->ntypes, ilo, ihi, error);
  utils::bounds(FLERR, arg[1], 1, atom->ntypes, jlo, jhi, error);
  if (ilo != jlo || ihi != jhi)
    error->all(FLERR, 1,
               "Pair esph/solid materials are per atom type: use pair_coeff I I (or * *), not "
               "{} {}",
               arg[0], arg[1]);

  double rho0 = -1.0, G = -1.0, Y = 0.0, H = 0.0;
  int rgd = 0;
  EOS eq{-1, 0.0, 0.0, 0.0, 0.0, 0.0};
  int iarg = 2;
  while (iarg < narg) {
    if (strcmp(arg[iarg], "rho0") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_coeff esph/solid rho0", error);
      rho0 = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (rho0 <= 0.0)
        error->all(FLERR, iarg + 1, "Pair esph/solid rho0 must be > 0, got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "shear") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_coeff esph/solid shear", error);
      G = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (G < 0.0)
        error->all(FLERR, iarg + 1, "Pair esph/solid shear modulus must be >= 0, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "yield") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_coeff esph/solid yield", error);
      Y = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (Y < 0.0)
        error->all(FLERR, iarg + 1,
                   "Pair esph/solid yield stress must be >= 0 (0: elastic), got {}", arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "hardening") == 0) {
      if (iarg + 1 >= narg)
        utils::missing_cmd_args(FLERR, "pair_coeff esph/solid hardening", error);
      H = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (H < 0.0)
        error->all(FLERR, iarg + 1, "Pair esph/solid hardening modulus must be >= 0, got {}",
                   arg[iarg + 1]);
      iarg += 2;
    } else if (strcmp(arg[iarg], "rigid") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_coeff esph/solid rigid", error);
      rgd = utils::logical(FLERR, arg[iarg + 1], false, lmp);
      iarg += 2;
    } else if (strcmp(arg[iarg], "eos") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_coeff esph/solid eos", error);
      if (strcmp(arg[iarg + 1], "linear") == 0) {
        if (iarg + 2 >= narg)
          utils::missing_cmd_args(FLERR, "pair_coeff esph/solid eos linear", error);
        eq.type = EOS_LINEAR;
        eq.K = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
        if (eq.K <= 0.0)
          error->all(FLERR, iarg + 3, "Pair esph/solid eos linear bulk modulus must be > 0, got {}",
                     arg[iarg + 2]);
        iarg += 3;
      } else if (strcmp(arg[iarg + 1], "mie/gruneisen") == 0) {
        if (iarg + 4 >= narg)
          utils::missing_cmd_args(FLERR, "pair_coeff esph/solid eos mie/gruneisen", error);
        eq.type = EOS_MIE_GRUNEISEN;
        eq.c0 = utils::numeric(FLERR, arg[iarg + 2], false, lmp);
        eq.s = utils::numeric(FLERR, arg[iarg + 3], false, lmp);
        eq.gamma0 = utils::numeric(FLERR, arg[iarg + 4], false, lmp);
        if (eq.c0 <= 0.0)
          error->all(FLERR, iarg + 3, "Pair esph/solid eos mie/gruneisen c0 must be > 0, got {}",
                     arg[iarg + 2]);
        if (eq.s < 0.0)
          error->all(FLERR, iarg + 4, "Pair esph/solid eos mie/gruneisen s must be >= 0, got {}",
                     arg[iarg + 3]);
        if (eq.gamma0 < 0.0)
          error->all(FLERR, iarg + 5,
                     "Pair esph/solid eos mie/gruneisen gamma0 must be >= 0, got {}",
                     arg[iarg + 4]);
        // the Hugoniot pressure diverges at the compression eta = 1 - rho0/rho = 1/s (a
        // helper's s = 1e6 multiplied the energy by 138 within 50 steps of contact)
        if (eq.s > MG_SLOPE_WARN && comm->me == 0)
          error->warning(FLERR,
                         "Pair esph/solid eos mie/gruneisen s {}: its Hugoniot pressure "
                         "diverges at the compression 1 - rho0/rho = 1/s = {:.3g}, which an "
                         "impact reaches (metals: s from 1 to 2, iron 1.92, aluminium 1.4); "
                         "check the value",
                         eq.s, 1.0 / eq.s);
        iarg += 5;
      } else {
        error->all(FLERR, iarg + 2,
                   "Unknown pair esph/solid eos {}: expected linear or mie/gruneisen",
                   arg[iarg + 1]);
      }
    } else {
      error->all(FLERR, iarg, "Unknown pair_coeff esph/solid keyword: {}", arg[iarg]);
    }
  }
  if (rho0 < 0.0) error->all(FLERR, "Pair esph/solid pair_coeff is missing the rho0 keyword");
  if (G < 0.0) error->all(FLERR, "Pair esph/solid pair_coeff is missing the shear keyword");
  if (eq.type < 0) error->all(FLERR, "Pair esph/solid pair_coeff is missing the eos keyword");
  if (H > 0.0 && Y <= 0.0)
    error->all(FLERR, "Pair esph/solid hardening {} needs a yield stress > 0 (keyword yield)", H);
  eq.rho0 = rho0;
  // the EOS works in internal units (factors set by the constructor: the unit style
  // cannot change once a box exists); G, yield and hardening stay in pressure units, like
  // the stress they act on (d2_esph_s)
  if (eq.type == EOS_LINEAR) eq.K *= units.pressure_in;
  // plasticity carries the equivalent plastic strain per atom
  if (Y > 0.0) ESPHState::ensure_plastic(lmp);

  for (int i = ilo; i <= ihi; i++) {
    eos[i] = eq;
    shear[i] = G;
    yield[i] = Y;
    hardening[i] = H;
    rigid[i] = rgd;
    matset[i] = 1;
  }
  // every pair of types with materials interacts
  int count = 0;
  for (int i = 1; i <= atom->ntypes; i++)
    for (int j = i; j <= atom->ntypes; j++)
      if (matset[i] && matset[j]) {
        setflag[i][j] = 1;
        count++;
      }
  if (count == 0) error->all(FLERR, "Incorrect args for pair coefficients" + utils::errorurl(21));
}
