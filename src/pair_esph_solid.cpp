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

#include "atom.h"
#include "comm.h"
#include "domain.h"
#include "error.h"
#include "esph_check.h"
#include "esph_contact.h"
#include "esph_kernel.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "fix.h"
#include "fix_esph_integrate.h"
#include "force.h"
#include "info.h"
#include "math_special.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"
#include "update.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;
using namespace ESPH;

// slots of the accumulator array acc[i][*]
// real particles
static constexpr int A_G = 0;         // 0..8: G = sum_j m_j (v_j - v_i) (x) grad_i W_ij
static constexpr int A_AVHEAT = 9;    // viscous heating
static constexpr int A_HEAT = 10;     // artificial heat transfer
static constexpr int A_NSUM = 11;     // 11..13: sum_k n_k W_ik over boundary particles k
static constexpr int A_DSUM = 14;     // sum_k W_ik (x_k - x_i).n_k
static constexpr int A_WSUM = 15;     // sum_k W_ik
// 16..24: M_i = sum_j m_j (x_j - x_i) (x) grad_i W_ij (gradient corrected), summed by the
// correction pass before the pair loop
static constexpr int A_M = 16;
static constexpr int A_XSPH = 25;    // 25..27: sum_j m_j / rhobar_ij (v_j - v_i) W_ij (xsph)
static constexpr int A_GW = 28;      // sum_k W_ik over own boundary particles with a gap
static constexpr int A_GG = 29;      // sum_k W_ik (gap_k + dt gapdot_k)
static constexpr int A_GV = 30;      // sum_k W_ik gapdot_k
// end of the gap slots, communicated together: A_GW..A_GV of real particles (slot 31
// unused), B_GAP..B_GAP+3 of boundary particles
static constexpr int GAP_END = 32;
// length that regularises the alignment score of two boundary particles, and below which
// an open gap counts as touching (round-off of coinciding faces), in h0
static constexpr double GAP_EPS = 1.0e-6;

// optional pair terms, bits of the last template parameter of pair_loop()
static constexpr int EXTRA_ASTRESS = 1;
static constexpr int EXTRA_XSPH = 2;
static constexpr int EXTRA_FRICTION = 4;
static constexpr int EXTRA_RIGID = 8;
static constexpr int EXTRA_VSWITCH = 16;
// the friction of a pair never exceeds the force that would stop the pair's slip within
// 1/STICK_SHARE of a step, so that the many pairs of a particle cannot reverse its slip
static constexpr double STICK_SHARE = 32.0;
// boundary particles
static constexpr int B_A = 0;        // 0..8: sum_p V_p v_p (x) grad_k W_kp
static constexpr int B_B = 9;        // 9..11: sum_p V_p grad_k W_kp
static constexpr int B_VSUM = 12;    // 12..14: sum_p V_p W_kp v_p
static constexpr int B_WSUM = 15;    // sum_p V_p W_kp
static constexpr int B_M = 16;       // 16..24: sum_p V_p (x_p - x_k) (x) grad_k W_kp
static constexpr int B_XSUM = 25;    // 25..27: sum_p V_p W_kp (x_p - x_k)
static constexpr int B_GAP = 28;     // 28..31: facing partners (contact_bnd_merge)

// slots of the hoisted array hq[i][*]
static constexpr int Q_V = 0;    // 0..2 predicted velocity
static constexpr int Q_RHO = 3;
static constexpr int Q_C = 4;
static constexpr int Q_H = 5;
static constexpr int Q_A = 6;       // 6..11 sigma / rho^2 (Voigt)
static constexpr int Q_N = 12;      // 12..14 normal
static constexpr int Q_GAP = 15;    // surface gap (d_esph_gap)
static constexpr int Q_E = 16;
static constexpr int Q_ZETA = 17;
static constexpr int Q_GAPV = 18;    // its rate (d_esph_gapv)
static constexpr int Q_ENG = 19;     // engagement with another body (d_esph_eng)
// with the artificial stress only (not communicated: computed for ghosts from Q_A)
static constexpr int Q_R = 20;        // 20..25 artificial stress R / rho^2 (Voigt)
static constexpr int Q_RFLAG = 26;    // 1 if R != 0
// with the viscosity switch: alpha_i after those, Q_ALPHA or Q_ALPHA_AST
static constexpr int Q_ALPHA = 20;
static constexpr int Q_ALPHA_AST = 27;
// with the gradient correction: B_i (9, row major) in the last columns, from qcol_b

enum { COMM_HOIST, COMM_ACC, COMM_NORMALS, COMM_GAPS, COMM_ATOM_CONTACT, COMM_CORR };

static constexpr double BIG_DT = 1.0e300;

/* ---------------------------------------------------------------------- */

PairESPHSolid::PairESPHSolid(LAMMPS *lmp) :
    Pair(lmp), eos(nullptr), shear(nullptr), yield(nullptr), hardening(nullptr), rigid_flag(0),
    rigid(nullptr), matset(nullptr), nmax(0), acc(nullptr), hq(nullptr), drho(nullptr), de(nullptr),
    dh(nullptr), ds(nullptr), dalpha(nullptr), bvel(nullptr), bspin(nullptr), xsph(nullptr),
    hq_cols(NHQ), qcol_b(-1), nboundary(0), atom_contact_flag(0), atom_contact_nmax(0),
    atom_contact(nullptr), state(nullptr), fix_int(nullptr)
{
  single_enable = 0;
  restartinfo = 0;
  one_coeff = 0;
  manybody_flag = 0;
  comm_forward = 20;    // 12 + 6 contact geometry + 2 heat
  comm_reverse = NACC;

  h0 = 0.0;
  cut_global = 0.0;
  set_defaults();

  pred_valid = 0;
  normals_valid = 0;
  dt_cfl = 0.0;
  dt_step = 0.0;
  dt_keep = 0;
  ncontact_pairs = ntouch_pairs = 0;
  fcontact = 0.0;
  comm_stage = COMM_HOIST;
  comm_bnd = 0;
  nforward = nreverse = 0;

  state = new ESPHState(lmp);
  units.set(force->ftm2v, force->mvv2e, force->nktv2p);
}

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
  heat_flag = 0;
  g1 = g2 = 0.0;
  hvar_flag = 0;
  hmax = 1.0;
  contact = CONTACT_SOLID;
  gaptol = 0.05;
  onset = 10;
  correct_flag = 1;
  astress_flag = 0;
  astress_eps = 0.0;
  astress_n = 4;
  astress_dp = 0.0;
  xsph_flag = 0;
  xsph_eps = 0.0;
  friction = 0.0;
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
  memory->destroy(atom_contact);
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
        correct_flag = 0;
      else if (strcmp(arg[iarg + 1], "corrected") == 0)
        correct_flag = 1;
      else if (strcmp(arg[iarg + 1], "bonet/lok") == 0)
        correct_flag = 2;
      else
        error->all(FLERR, iarg + 2,
                   "Unknown pair esph/solid gradient {}: expected plain, corrected or bonet/lok",
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
      iarg += 4;
    } else if (strcmp(arg[iarg], "xsph") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid xsph", error);
      xsph_eps = utils::numeric(FLERR, arg[iarg + 1], false, lmp);
      if (xsph_eps < 0.0 || xsph_eps > 1.0)
        error->all(FLERR, iarg + 2, "Pair esph/solid xsph epsilon must be in [0, 1], got {}",
                   arg[iarg + 1]);
      xsph_flag = (xsph_eps > 0.0);
      iarg += 2;
    } else if (strcmp(arg[iarg], "onset") == 0) {
      if (iarg + 1 >= narg) utils::missing_cmd_args(FLERR, "pair_style esph/solid onset", error);
      onset = utils::inumeric(FLERR, arg[iarg + 1], false, lmp);
      if (onset < 0)
        error->all(FLERR, iarg + 2, "Pair esph/solid onset must be >= 0 steps, got {}",
                   arg[iarg + 1]);
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

/* ---------------------------------------------------------------------- */

void PairESPHSolid::init_style()
{
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
  auto fixes = modify->get_fix_by_style("^esph/integrate$");
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
  if (contact != CONTACT_OFF && modify->get_fix_by_style("^esph/boundary$").empty()) {
    // contact needs boundary particles only when there is more than one body
    int lmin = 1 << 30, lmax = -(1 << 30);
    state->fetch();
    const int *body = state->body;
    for (int i = 0; i < atom->nlocal; i++) {
      lmin = MIN(lmin, body[i]);
      lmax = MAX(lmax, body[i]);
    }
    int gmin, gmax;
    MPI_Allreduce(&lmin, &gmin, 1, MPI_INT, MPI_MIN, world);
    MPI_Allreduce(&lmax, &gmax, 1, MPI_INT, MPI_MAX, world);
    if (gmin != gmax)
      error->all(FLERR, Error::NOLASTLINE,
                 "Pair esph/solid contact {} between bodies {}..{} requires fix esph/boundary "
                 "(boundary particles with normals); use contact off for traditional SPH",
                 contact == CONTACT_PAPER ? "paper" : "solid", gmin, gmax);
  }
  // per-atom contact output only while a compute esph/atom asks for it (its init() follows)
  atom_contact_flag = 0;
  neighbor->add_request(this);
}

/* ---------------------------------------------------------------------- */

double PairESPHSolid::init_one(int i, int j)
{
  if (setflag[i][j] == 0)
    error->all(FLERR, Error::NOLASTLINE,
               "All pair esph/solid materials are not set (use pair_coeff I I rho0 ... for every "
               "type). Status:\n" +
                   Info::get_pair_coeff_status(lmp));
  return cut_global;
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
  // (resume_check() restores the time step of the last computation for the gap forecast)
  pred_valid = fix_int->resume_check();
  normals_valid = pred_valid;
  dt_keep = pred_valid;
  state->fetch();
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  for (int i = 0; i < nlocal; i++) {
    if (state->rho[i] == 0.0) state->rho[i] = eos[type[i]].rho0;
    if (state->h[i] == 0.0) state->h[i] = h0;
  }
  // the state the run starts from, and the arrangement of the particles (one pass each)
  ESPHCheck::state(lmp, state, eos, cut_global / KERNEL_SUPPORT, units);
  ESPHCheck::pairs(lmp, state, list, cut_global * cut_global, h0, dim);
  if (contact != CONTACT_OFF)
    ESPHCheck::contact_bodies(lmp, state, contact == CONTACT_PAPER ? "paper" : "solid");
  bigint nb = 0;
  for (int i = 0; i < nlocal; i++)
    if (state->rmass[i] == 0.0) nb++;
  MPI_Allreduce(&nb, &nboundary, 1, MPI_LMP_BIGINT, MPI_SUM, world);

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
  const int cols0 = NHQ + (astress_flag ? NHQ_AST : 0) + (vswitch_flag ? 1 : 0);
  qcol_b = (correct_flag == 2) ? cols0 : -1;
  const int cols = cols0 + (qcol_b >= 0 ? 9 : 0);
  if (cols != hq_cols) {
    memory->destroy(hq);
    hq_cols = cols;
    if (nmax > 0) memory->create(hq, nmax, hq_cols, "pair:hq");
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
  memory->grow(acc, nmax, NACC, "pair:acc");
  memory->grow(hq, nmax, hq_cols, "pair:hq");
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

/* ----------------------------------------------------------------------
   per-particle work hoisted out of the pair loop: predicted state, EOS,
   sigma/rho^2, sound speed; local CFL estimate
------------------------------------------------------------------------- */

void PairESPHSolid::hoist()
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  double **v = atom->v;
  const double *rmass = state->rmass;
  // inside a step the integrator has predicted the state at its end
  double **pred = pred_valid ? fix_int->pred : nullptr;
  const double hlimit = cut_global / KERNEL_SUPPORT * (1.0 + 1.0e-12);
  // internal units from here on: sigma/rho^2, e and c (esph_units.h)
  const double ein = units.energy_in, pin = units.pressure_in;
  // the switched viscosity coefficient: its column, and the predicted or current alpha_i
  const int qal = astress_flag ? Q_ALPHA_AST : Q_ALPHA;
  const double *alpha_now = vswitch_flag ? state->alpha : nullptr;

  double dtmin = BIG_DT;
  for (int i = 0; i < nlocal; i++) {
    double *q = hq[i];
    const double *p = pred ? pred[i] : nullptr;
    // with fix esph/integrate move no another fix has set v at the end of the step
    const double *vi = (p && fix_int->move) ? p + FixESPHIntegrate::P_V : v[i];
    q[Q_V] = vi[0];
    q[Q_V + 1] = vi[1];
    q[Q_V + 2] = vi[2];
    q[Q_N] = state->n[i][0];
    q[Q_N + 1] = state->n[i][1];
    q[Q_N + 2] = state->n[i][2];
    q[Q_GAP] = state->gap[i];
    q[Q_GAPV] = state->gapv[i];
    q[Q_ENG] = state->eng[i];
    if (rmass[i] > 0.0) {
      const int itype = type[i];
      const double rho = p ? p[FixESPHIntegrate::P_RHO] : state->rho[i];
      const double e = (p ? p[FixESPHIntegrate::P_E] : state->e[i]) * ein;
      const double h = p ? p[FixESPHIntegrate::P_H] : state->h[i];
      const double *sp = p ? p + FixESPHIntegrate::P_S : state->s[i];
      double P, c2;
      eos[itype].compute(rho, e, P, c2);
      if (c2 < 0.0) c2 = 0.0;
      const double c = sqrt(c2);
      const double inv = 1.0 / (rho * rho);
      q[Q_RHO] = rho;
      q[Q_C] = c;
      q[Q_H] = h;
      q[Q_A] = (sp[0] * pin - P) * inv;
      q[Q_A + 1] = (sp[1] * pin - P) * inv;
      q[Q_A + 2] = (sp[2] * pin - P) * inv;
      q[Q_A + 3] = sp[3] * pin * inv;
      q[Q_A + 4] = sp[4] * pin * inv;
      q[Q_A + 5] = sp[5] * pin * inv;
      q[Q_E] = e;
      if (alpha_now) q[qal] = p ? p[FixESPHIntegrate::P_ALPHA] : alpha_now[i];
      // CFL with the longitudinal wave speed
      const double cl = sqrt(c2 + 4.0 * shear[itype] * pin / (3.0 * rho));
      const double vmag = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
      double dti = h / (cl + vmag);
      if (heat_flag) {
        const double divv = p ? p[FixESPHIntegrate::P_DIVV] : -drho[i] / rho;
        q[Q_ZETA] = g1 * h * c + g2 * h * h * (fabs(divv) - divv);
        // explicit diffusion with diffusivity zeta: dt <= h^2 / (2 D zeta)
        if (q[Q_ZETA] > 0.0) dti = MIN(dti, h * h / (2.0 * dim * q[Q_ZETA]));
      } else {
        q[Q_ZETA] = 0.0;
      }
      if (dti < dtmin) dtmin = dti;
      if (hvar_flag && h > hlimit)
        error->one(FLERR, Error::NOLASTLINE,
                   "Smoothing length {} of atom {} exceeds the pair esph/solid limit hvar x h = {}",
                   h, atom->tag[i], hlimit);
    } else {
      q[Q_RHO] = q[Q_C] = q[Q_E] = q[Q_ZETA] = 0.0;
      q[Q_H] = state->h[i];
      for (int k = 0; k < 6; k++) q[Q_A + k] = 0.0;
      if (alpha_now) q[qal] = 0.0;
    }
  }
  dt_cfl = dtmin;
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
  nforward = 12 + (bnd ? 6 : 0) + (heat_flag ? 2 : 0) + (vswitch_flag ? 1 : 0);
  if (bnd && !normals_valid) compute_normals();
  hoist();
  comm_stage = COMM_HOIST;
  comm->forward_comm(this, nforward);

  // without boundary particles or gradient correction only G and the heating terms
  nreverse = (bnd || correct_flag || xsph_flag) ? NACC : 11;
  for (int i = 0; i < nall; i++) memset(acc[i], 0, sizeof(double) * nreverse);

  if (correct_flag == 2) correction();
  if (astress_flag) artificial_stress();

  ncontact_pairs = ntouch_pairs = 0;
  fcontact = 0.0;
  // keep the nodes of body pairs seen before: no allocation in the pair loop once known
  for (auto &kv : body_tally) kv.second = {0.0, 0.0, 0.0};
  if (atom_contact_flag) atom_contact_clear();
  run_pair_loop(bnd);

  if (force->newton_pair) {
    comm_stage = COMM_ACC;
    comm->reverse_comm(this, nreverse);
    if (atom_contact_flag) {
      comm_stage = COMM_ATOM_CONTACT;
      comm->reverse_comm(this, 2);
    }
  }
  finalize(eflag);
  if (vflag_fdotr) virial_fdotr_compute();
}

/* ----------------------------------------------------------------------
   solid rule: the gap of a cross-body pair, the gaps of both particles
   brought to the present with their rates
------------------------------------------------------------------------- */

static inline double solid_gap(const double *qi, const double *qj, double dt)
{
  return contact_gap_pair(qi[Q_GAP] + dt * qi[Q_GAPV], qj[Q_GAP] + dt * qj[Q_GAPV]);
}

/* ----------------------------------------------------------------------
   M^-1 of the correction from its sums (row major), the out-of-plane
   diagonal set to rho; false where M is singular (a particle with too few
   neighbours): then the plain gradient is used
------------------------------------------------------------------------- */

static bool correction_inverse(const double *m, double rho, int dim, Eigen::Matrix3d &Minv)
{
  Eigen::Matrix3d M;
  M << m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8];
  for (int d = dim; d < 3; d++) M(d, d) = rho;
  if (fabs(M.determinant()) <= 1.0e-6 * rho * rho * rho) return false;
  Minv = M.inverse();
  return true;
}

/* ----------------------------------------------------------------------
   the gradient correction, before the pair loop (Bonet and Lok 1999): for
   every real particle M_i = sum_j m_j (x_j - x_i) (x) grad_i W_ij over the
   pairs that couple in the pair loop (own body; other bodies weighted by the
   contact gate, which depends only on the geometry), then
   B_i = (sigma_i / rho_i) M_i^-T for owned and ghost particles. The pair
   loop's stress force m_i m_j (B_i + B_j) grad_i W has no torque on a body:
   sum_j m_j (x_j - x_i) (x) M_i^-T grad_i W = I leaves the symmetric
   sigma_i. Its work is B_i : G_i (the energy), and L = G M^-1 the velocity
   gradient, exact for linear fields
------------------------------------------------------------------------- */

void PairESPHSolid::correction()
{
  if (hvar_flag)
    correction_loop<1>();
  else
    correction_loop<0>();
  if (force->newton_pair) {
    comm_stage = COMM_CORR;
    comm->reverse_comm(this, 9);
  }
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const double *rmass = state->rmass;
  const int *type = atom->type;
  const double pin = units.pressure_in;
  double dtmin = dt_cfl;
  for (int i = 0; i < nlocal; i++) {
    const double *q = hq[i];
    const Eigen::Matrix3d A = voigt_to_matrix(q + Q_A);
    double *B = hq[i] + qcol_b;
    Eigen::Matrix3d Minv;
    Eigen::Matrix3d Bm;
    if (rmass[i] > 0.0 && correction_inverse(acc[i] + A_M, q[Q_RHO], dim, Minv)) {
      Bm = q[Q_RHO] * A * Minv.transpose();
      // the correction stiffens a particle whose kernel support is cut (a free surface,
      // by up to about 2 normal to it) by the gain kappa, the largest singular value of
      // rho M^-1: its CFL step shrinks by sqrt(kappa) (measured: the free bar's ends go
      // unstable at 0.3 h / c_L without this, stable at 0.25)
      const Eigen::Matrix3d K = q[Q_RHO] * Minv;
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
      es.computeDirect(K.transpose() * K, Eigen::EigenvaluesOnly);
      const double sqrt_kappa = sqrt(sqrt(std::max(es.eigenvalues()(2), 0.0)));
      if (sqrt_kappa > 1.0) {
        const double rho = q[Q_RHO];
        const double cl = sqrt(q[Q_C] * q[Q_C] + 4.0 * shear[type[i]] * pin / (3.0 * rho));
        const double *v = q + Q_V;
        const double vmag = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        dtmin = std::min(dtmin, q[Q_H] / (cl * sqrt_kappa + vmag));
      }
    } else {
      Bm = A;
    }
    for (int r = 0; r < 3; r++)
      for (int c = 0; c < 3; c++) B[3 * r + c] = Bm(r, c);
  }
  dt_cfl = dtmin;
  // the ghosts' partial sums are with their owners: the pair loop's reverse
  // communication must not add them again
  for (int i = nlocal; i < nall; i++)
    for (int k = A_M; k < A_M + 9; k++) acc[i][k] = 0.0;
  comm_stage = COMM_CORR;
  comm->forward_comm(this, 9);
}

/* ---------------------------------------------------------------------- */

template <int HVAR> void PairESPHSolid::correction_loop()
{
  double **x = atom->x;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  const double gap_cap = gaptol * h0;
  const double dt = dt_step;
  // as in the pair loop: other bodies are coupled by the contact rule only with boundary
  // particles, rigid particles only with other bodies
  const int contact_on = (nboundary > 0) && (contact != CONTACT_OFF);
  const int solid = (contact == CONTACT_SOLID);

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double mi = rmass[i];
    if (mi == 0.0) continue;
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const int bi = body[i];
    const int ri = rigid_flag && rigid[type[i]];
    const double *qi = hq[i];
    double mci[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double mj = rmass[j];
      if (mj == 0.0) continue;
      const double dx[3] = {xi - x[j][0], yi - x[j][1], zi - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq_global) continue;
      const int cross = contact_on && (bi != body[j]);
      const int rj = rigid_flag && rigid[type[j]];
      if ((ri || rj) && (!cross || (ri && rj))) continue;
      const double *qj = hq[j];
      // another body: weighted by the solid rule's coupling weight (smooth in time); the
      // paper's rule switches pairs on and off from step to step, and a correction that
      // switched with them would kick the particles: there every neighbour counts
      double wgt = 1.0;
      if (cross && solid) {
        wgt = contact_pair_weight(solid_gap(qi, qj, dt), gap_cap, qi[Q_ENG], qj[Q_ENG]);
        if (wgt == 0.0) continue;
      }
      double norm = norm0, hinv = hinv0;
      if (HVAR) {
        const double hij = 0.5 * (qi[Q_H] + qj[Q_H]);
        hinv = 1.0 / hij;
        norm = kernel_norm(kernel, dim, hij);
      }
      double w, dw;
      if (!kernel_eval(kernel, dim, norm, hinv, sqrt(rsq), w, dw)) continue;
      dw *= wgt;
      const double g[3] = {dw * dx[0], dw * dx[1], dw * dx[2]};    // grad_i W_ij
      // x_j - x_i = -dx for i; x_i - x_j = dx and grad_j W = -g for j
      for (int a = 0; a < 3; a++) {
        const double xa = -mj * dx[a];
        mci[3 * a] += xa * g[0];
        mci[3 * a + 1] += xa * g[1];
        mci[3 * a + 2] += xa * g[2];
      }
      if (newton_pair || j < nlocal) {
        double *aj = acc[j] + A_M;
        for (int a = 0; a < 3; a++) {
          const double xa = -mi * dx[a];
          aj[3 * a] += xa * g[0];
          aj[3 * a + 1] += xa * g[1];
          aj[3 * a + 2] += xa * g[2];
        }
      }
    }
    double *ai = acc[i] + A_M;
    for (int k = 0; k < 9; k++) ai[k] += mci[k];
  }
}

/* ----------------------------------------------------------------------
   Monaghan (2000) / Gray, Monaghan and Swift (2001) artificial stress of
   every owned and ghost real particle from its sigma / rho^2 (already
   communicated): in the principal frame R'_aa = -epsilon sigma'_aa / rho^2
   where sigma'_aa > 0 (tension), 0 otherwise; R = V R' V^T
------------------------------------------------------------------------- */

void PairESPHSolid::artificial_stress()
{
  const int nall = atom->nlocal + atom->nghost;
  for (int i = 0; i < nall; i++) {
    const double *A = hq[i] + Q_A;
    double *R = hq[i] + Q_R;
    for (int k = 0; k < NHQ_AST; k++) R[k] = 0.0;
    // compression in every direction (the common case in impact): nothing to do;
    // the largest eigenvalue is at most the largest Gershgorin bound
    const double g0 = A[0] + fabs(A[3]) + fabs(A[4]);
    const double g1 = A[1] + fabs(A[3]) + fabs(A[5]);
    const double g2 = A[2] + fabs(A[4]) + fabs(A[5]);
    if (g0 <= 0.0 && g1 <= 0.0 && g2 <= 0.0) continue;
    const Eigen::Matrix3d M = voigt_to_matrix(A);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es;
    es.computeDirect(M);
    const Eigen::Vector3d lam = es.eigenvalues();
    const Eigen::Matrix3d &V = es.eigenvectors();
    Eigen::Matrix3d Rm = Eigen::Matrix3d::Zero();
    for (int a = 0; a < 3; a++)
      if (lam(a) > 0.0) Rm -= astress_eps * lam(a) * V.col(a) * V.col(a).transpose();
    matrix_to_voigt(Rm, R);
    hq[i][Q_RFLAG] = 1.0;    // some principal stress is tensile
  }
}

/* ----------------------------------------------------------------------
   sums for the normal (eq. 30) and depth of real particle p from boundary
   particle k: dx = x_i - x_j and sgn = +1 if k == i, -1 if k == j, so that
   x_k - x_p = sgn dx
------------------------------------------------------------------------- */

static inline void add_normal_sums(double *ap, double w, double sgn, const double *dx,
                                   const double *nk)
{
  ap[A_NSUM] += w * nk[0];
  ap[A_NSUM + 1] += w * nk[1];
  ap[A_NSUM + 2] += w * nk[2];
  ap[A_DSUM] += w * (sgn * dx[0] * nk[0] + sgn * dx[1] * nk[1] + sgn * dx[2] * nk[2]);
  ap[A_WSUM] += w;
}

/* ----------------------------------------------------------------------
   real particle p takes the gap of its own body's boundary particle k (with
   kernel weight w), extrapolated by dt with its rate to the present
------------------------------------------------------------------------- */

static inline void add_gap_sums(double *ap, double w, const double *qk, double dt)
{
  if (qk[Q_GAP] >= GAP_NONE) return;
  ap[A_GW] += w;
  ap[A_GG] += w * (qk[Q_GAP] + dt * qk[Q_GAPV]);
  ap[A_GV] += w * qk[Q_GAPV];
}

/* ----------------------------------------------------------------------
   boundary particles i and j of different bodies: gap candidate for both
   (the same number seen from either side), see esph_contact.h
------------------------------------------------------------------------- */

static inline void bnd_gap_pair(double *ai, double *aj, const double *qi, const double *qj,
                                const double *dx, double eps)
{
  const double xab[3] = {-dx[0], -dx[1], -dx[2]};
  const double vab[3] = {qj[Q_V] - qi[Q_V], qj[Q_V + 1] - qi[Q_V + 1], qj[Q_V + 2] - qi[Q_V + 2]};
  double c, g, gd;
  if (!contact_bnd_gap(qi + Q_N, qj + Q_N, xab, vab, eps, c, g, gd)) return;
  contact_bnd_keep(ai + B_GAP, c, g, gd);
  if (aj) contact_bnd_keep(aj + B_GAP, c, g, gd);
}

/* ----------------------------------------------------------------------
   the pair loop: one pass over the half neighbour list
   real-real same body (or contact off): full SPH coupling (eqs. 1-7, 8, 15, 17)
   real-real other body: contact rule (section 4.3), normal components only
   real-boundary same body: interpolation to the boundary particle (4.2) and
     the real particle's normal sums (eq. 30)
------------------------------------------------------------------------- */

template <int BND, int HVAR, int HEAT, int CORR, int EXTRA> void PairESPHSolid::pair_loop()
{
  double **x = atom->x;
  double **f = atom->f;
  const tagint *tag = atom->tag;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int *type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;

  // constant h: kernel normalisation once
  const double norm0 = kernel_norm(kernel, dim, h0);
  const double hinv0 = 1.0 / h0;
  const double gap_cap = gaptol * h0;
  const double gap_eps = GAP_EPS * h0;
  const double dt = dt_step;
  // pair forces in force units (atom->f, the contact force); all else internal
  const double fconv = units.force;
  const int solid = (contact == CONTACT_SOLID);
  // artificial stress: 1 / W(dp) at constant h
  double wdp_inv0 = 0.0;
  constexpr int AST = EXTRA & EXTRA_ASTRESS;
  constexpr int XSPH = EXTRA & EXTRA_XSPH;
  constexpr int FRIC = BND && (EXTRA & EXTRA_FRICTION);
  constexpr int RIG = BND && (EXTRA & EXTRA_RIGID);
  constexpr int VSW = EXTRA & EXTRA_VSWITCH;
  constexpr int QAL = AST ? Q_ALPHA_AST : Q_ALPHA;
  // switched viscosity: beta_ij keeps the ratio beta / alpha of the visc keyword
  const double beta_ratio = (VSW && alpha > 0.0) ? beta / alpha : 0.0;
  if (AST) {
    double wdp, dwdp;
    kernel_eval(kernel, dim, norm0, hinv0, astress_dp, wdp, dwdp);
    wdp_inv0 = 1.0 / wdp;
  }

  const int inum = list->inum;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;

  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    const double mi = rmass[i];
    const int bi = body[i];
    const double *qi = hq[i];
    // sums for i in registers (acc[i] and acc[j] could alias for the compiler)
    double fxi = 0.0, fyi = 0.0, fzi = 0.0;
    double gi[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double mci[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    double avhi = 0.0, heati = 0.0;
    double xsi[3] = {0.0, 0.0, 0.0};
    const int *jlist = firstneigh[i];
    const int jnum = numneigh[i];

    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx[3] = {xi - x[j][0], yi - x[j][1], zi - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq_global) continue;
      const double mj = rmass[j];
      if (BND && mi == 0.0 && mj == 0.0) {
        // two boundary particles: the surface gap between different bodies
        if (solid && bi != body[j])
          bnd_gap_pair(acc[i], (newton_pair || j < nlocal) ? acc[j] : nullptr, qi, hq[j], dx,
                       gap_eps);
        continue;
      }
      const double *qj = hq[j];

      double hij, norm, hinv;
      if (HVAR) {
        hij = 0.5 * (qi[Q_H] + qj[Q_H]);
        hinv = 1.0 / hij;
        norm = kernel_norm(kernel, dim, hij);
      } else {
        hij = h0;
        hinv = hinv0;
        norm = norm0;
      }
      double w, dw;
      if (!kernel_eval(kernel, dim, norm, hinv, sqrt(rsq), w, dw)) continue;
      const double g[3] = {dw * dx[0], dw * dx[1], dw * dx[2]};    // grad_i W_ij
      const int jown = (newton_pair || j < nlocal);

      if (BND && (mi == 0.0 || mj == 0.0)) {
        // boundary particle k and real particle p of the same body
        if (bi != body[j]) continue;
        int k, p;
        double sgn;
        if (mi == 0.0) {
          k = i;
          p = j;
          sgn = 1.0;
        } else {
          k = j;
          p = i;
          sgn = -1.0;
        }
        const double *qp = hq[p];
        const double *qk = hq[k];
        if (k < nlocal || newton_pair || k == i) {
          // grad_k W_kp = sgn * g
          double *ak = acc[k];
          const double Vp = rmass[p] / qp[Q_RHO];
          const double gk[3] = {sgn * g[0], sgn * g[1], sgn * g[2]};
          for (int a = 0; a < 3; a++) {
            const double va = Vp * qp[Q_V + a];
            ak[B_A + 3 * a] += va * gk[0];
            ak[B_A + 3 * a + 1] += va * gk[1];
            ak[B_A + 3 * a + 2] += va * gk[2];
            ak[B_B + a] += Vp * gk[a];
            ak[B_VSUM + a] += Vp * w * qp[Q_V + a];
            // x_p - x_k = -sgn * dx
            const double xa = -sgn * Vp * dx[a];
            ak[B_M + 3 * a] += xa * gk[0];
            ak[B_M + 3 * a + 1] += xa * gk[1];
            ak[B_M + 3 * a + 2] += xa * gk[2];
            ak[B_XSUM + a] += xa * w;
          }
          ak[B_WSUM] += Vp * w;
        }
        if (p < nlocal || newton_pair || p == i) {
          add_normal_sums(acc[p], w, sgn, dx, qk + Q_N);
          if (solid) add_gap_sums(acc[p], w, qk, dt);
        }
        continue;
      }

      // two real particles
      const int cross = BND && (contact != CONTACT_OFF) && (bi != body[j]);
      // a rigid particle (pair_coeff ... rigid yes) meets only deformable ones of other
      // bodies, as the mirror image of its partner: stress, sound speed and density of the
      // partner, twice the normal relative velocity (below): the reaction of a rigid wall
      const int ri = RIG && rigid[type[i]], rj = RIG && rigid[type[j]];
      if ((ri || rj) && (!cross || (ri && rj))) continue;
      const double *qa = ri ? qj : qi;
      const double *qb = rj ? qi : qj;
      double vij[3] = {qi[Q_V] - qj[Q_V], qi[Q_V + 1] - qj[Q_V + 1], qi[Q_V + 2] - qj[Q_V + 2]};
      // stress force per m_i m_j: (sigma_i / rho_i^2 + sigma_j / rho_j^2) grad_i W, or with
      // the correction (B_i + B_j) grad_i W, B = (sigma / rho) M^-T (Bonet and Lok 1999)
      double Tg[3];
      if (CORR == 2) {
        const double *Bi = qa + qcol_b;
        const double *Bj = qb + qcol_b;
        for (int r = 0; r < 3; r++)
          Tg[r] = (Bi[3 * r] + Bj[3 * r]) * g[0] + (Bi[3 * r + 1] + Bj[3 * r + 1]) * g[1] +
              (Bi[3 * r + 2] + Bj[3 * r + 2]) * g[2];
      } else {
        const double *Ai = qa + Q_A;
        const double *Aj = qb + Q_A;
        const double T[6] = {Ai[0] + Aj[0], Ai[1] + Aj[1], Ai[2] + Aj[2],
                             Ai[3] + Aj[3], Ai[4] + Aj[4], Ai[5] + Aj[5]};
        Tg[0] = T[0] * g[0] + T[3] * g[1] + T[4] * g[2];
        Tg[1] = T[3] * g[0] + T[1] * g[1] + T[5] * g[2];
        Tg[2] = T[4] * g[0] + T[5] * g[1] + T[2] * g[2];
      }
      double nc[3] = {0.0, 0.0, 0.0};
      double vn = 0.0, xn = 0.0;
      double vt[3] = {0.0, 0.0, 0.0};
      if (cross) {
        contact_normal(qi + Q_N, qj + Q_N, dx, nc);
        vn = vij[0] * nc[0] + vij[1] * nc[1] + vij[2] * nc[2];
        xn = dx[0] * nc[0] + dx[1] * nc[1] + dx[2] * nc[2];
        // the slip velocity (of i against j) for friction
        if (FRIC)
          for (int a = 0; a < 3; a++) vt[a] = vij[a] - vn * nc[a];
        if (RIG && (ri || rj)) vn *= 2.0;
        // only the normal relative velocity couples across the interface
        vij[0] = vn * nc[0];
        vij[1] = vn * nc[1];
        vij[2] = vn * nc[2];
      }

      // Monaghan-Gingold artificial viscosity (eqs. 4-7)
      const double vr = vij[0] * dx[0] + vij[1] * dx[1] + vij[2] * dx[2];
      double pi_ij = 0.0;
      if (vr < 0.0) {
        const double mu = hij * vr / (rsq + eps * hij * hij);
        double al = alpha, be = beta;
        if (VSW) {
          // Morris-Monaghan switch: the mean of the two particles' alpha
          al = 0.5 * (qa[QAL] + qb[QAL]);
          be = beta_ratio * al;
        }
        pi_ij =
            (-al * 0.5 * (qa[Q_C] + qb[Q_C]) * mu + be * mu * mu) / (0.5 * (qa[Q_RHO] + qb[Q_RHO]));
      }
      // heating by the artificial viscosity and stress, half to each particle
      double avh = 0.5 * pi_ij * (vij[0] * g[0] + vij[1] * g[1] + vij[2] * g[2]);
      if (AST && !cross && (qi[Q_RFLAG] + qj[Q_RFLAG] > 0.0)) {
        // Monaghan (2000) artificial stress f_ij^n (R_i + R_j): a repulsion between
        // particles in tension, R = -epsilon sigma'/rho^2 in the principal frame
        double wdp_inv = wdp_inv0;
        if (HVAR) {
          double wdp, dwdp;
          kernel_eval(kernel, dim, norm, hinv, astress_dp, wdp, dwdp);
          wdp_inv = 1.0 / wdp;
        }
        const double fn = MathSpecial::powint(w * wdp_inv, astress_n);
        const double *Ri = qi + Q_R;
        const double *Rj = qj + Q_R;
        const double R[6] = {fn * (Ri[0] + Rj[0]), fn * (Ri[1] + Rj[1]), fn * (Ri[2] + Rj[2]),
                             fn * (Ri[3] + Rj[3]), fn * (Ri[4] + Rj[4]), fn * (Ri[5] + Rj[5])};
        const double Rg[3] = {R[0] * g[0] + R[3] * g[1] + R[4] * g[2],
                              R[3] * g[0] + R[1] * g[1] + R[5] * g[2],
                              R[4] * g[0] + R[5] * g[1] + R[2] * g[2]};
        Tg[0] += Rg[0];
        Tg[1] += Rg[1];
        Tg[2] += Rg[2];
        avh -= 0.5 * (vij[0] * Rg[0] + vij[1] * Rg[1] + vij[2] * Rg[2]);
      }
      const double mm = mi * mj * fconv;
      double ff[3] = {mm * (Tg[0] - pi_ij * g[0]), mm * (Tg[1] - pi_ij * g[1]),
                      mm * (Tg[2] - pi_ij * g[2])};

      if (cross) {
        double fn = ff[0] * nc[0] + ff[1] * nc[1] + ff[2] * nc[2];
        // with newton off a pair with a ghost partner is on two ranks: count it once
        const int count_pair = newton_pair || j < nlocal || tag[i] < tag[j];
        double phi = 1.0;
        int touching;
        if (solid) {
          const double gap = solid_gap(qi, qj, dt);
          // touching: closed, or open by no more than round-off (faces that coincide in exact
          // arithmetic are a round-off distance apart in a rotated scene); counted before
          // the gate
          touching = (gap <= gap_eps);
          phi = contact_pair_weight(gap, gap_cap, qi[Q_ENG], qj[Q_ENG]);
        } else {
          // the paper's rule measures no gap: an interacting pair is a touching one
          touching = contact_approach(vn, xn);
        }
        if (touching && count_pair) {
          ntouch_pairs++;
          tally_bodies(bi, body[j])[0] += 1.0;
        }
        // solid: no tension across contact, a pair that would pull (or not push) does not
        // interact at all (also not in the strain rate and energy, which would otherwise see
        // work that no force does); paper: only approaching pairs interact
        if (solid ? (phi == 0.0 || fn >= 0.0) : !touching) continue;
        // the coupling weight scales force, strain rate and heating alike, so that the
        // work of the force is what the internal energy receives
        fn *= phi;
        avh *= phi;
        for (int a = 0; a < 3; a++) vij[a] *= phi;
        ff[0] = fn * nc[0];
        ff[1] = fn * nc[1];
        ff[2] = fn * nc[2];
        if (FRIC) {
          // Coulomb friction: mu |f_n| against the slip, the work going into heat, half
          // to each particle (below the slip speed at which that force would reverse the
          // slip, the force that stops it)
          const double vt2 = vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2];
          if (vt2 > 0.0) {
            const double vtm = sqrt(vt2);
            const double fstick = mm / (mi + mj) * vtm / (STICK_SHARE * dt);
            const double ft = std::min(-friction * fn, fstick);
            const double s = ft / vtm;
            for (int a = 0; a < 3; a++) ff[a] -= s * vt[a];
            avh += 0.5 * ft * vtm / mm;
          }
        }
        // transmitted compressive normal force; with newton off a pair with a ghost
        // partner is seen by two ranks
        const double fpair = (newton_pair || j < nlocal) ? -fn : -0.5 * fn;
        fcontact += fpair;
        auto &tb = tally_bodies(bi, body[j]);
        tb[2] += fpair;
        if (count_pair) {
          ncontact_pairs++;
          tb[1] += 1.0;
        }
        // per-atom contact output of compute esph/atom, only when one asks for it
        if (atom_contact_flag) {
          double **catom = atom_contact;
          catom[i][0] += 1.0;
          catom[i][1] -= fn;
          if (jown) {
            catom[j][0] += 1.0;
            catom[j][1] -= fn;
          }
        }
      }

      fxi += ff[0];
      fyi += ff[1];
      fzi += ff[2];

      // G = sum_j m_j (v_j - v_i) (x) grad_i W, for i and j alike
      for (int a = 0; a < 3; a++) {
        const double wa = -mj * vij[a];
        gi[3 * a] += wa * g[0];
        gi[3 * a + 1] += wa * g[1];
        gi[3 * a + 2] += wa * g[2];
      }
      avhi += mj * avh;
      if (CORR == 1) {
        // x_j - x_i = -dx
        for (int a = 0; a < 3; a++) {
          const double xa = -mj * dx[a];
          mci[3 * a] += xa * g[0];
          mci[3 * a + 1] += xa * g[1];
          mci[3 * a + 2] += xa * g[2];
        }
      }
      double heat = 0.0;
      if (HEAT && !cross) {
        // artificial heat transfer (eqs. 8-10), conservative pairwise form
        const double zbar = 0.5 * (qi[Q_ZETA] + qj[Q_ZETA]);
        const double rbar = 0.5 * (qi[Q_RHO] + qj[Q_RHO]);
        heat = 2.0 * zbar / rbar * (qi[Q_E] - qj[Q_E]) * dw * rsq / (rsq + eps * hij * hij);
        heati += mj * heat;
      }

      // XSPH (Monaghan 1989): particles move with the velocity smoothed over their
      // own body, xsph_i = sum_j m_j / rhobar_ij (v_j - v_i) W_ij
      double wx = 0.0;
      if (XSPH && !cross) {
        wx = w / (0.5 * (qi[Q_RHO] + qj[Q_RHO]));
        xsi[0] -= mj * wx * vij[0];
        xsi[1] -= mj * wx * vij[1];
        xsi[2] -= mj * wx * vij[2];
      }

      if (jown) {
        double *aj = acc[j];
        if (XSPH && !cross)
          for (int a = 0; a < 3; a++) aj[A_XSPH + a] += mi * wx * vij[a];
        f[j][0] -= ff[0];
        f[j][1] -= ff[1];
        f[j][2] -= ff[2];
        for (int a = 0; a < 3; a++) {
          const double wa = -mi * vij[a];
          aj[A_G + 3 * a] += wa * g[0];
          aj[A_G + 3 * a + 1] += wa * g[1];
          aj[A_G + 3 * a + 2] += wa * g[2];
        }
        aj[A_AVHEAT] += mi * avh;
        if (HEAT) aj[A_HEAT] -= mi * heat;
        if (CORR == 1)
          for (int a = 0; a < 3; a++) {
            const double xa = -mi * dx[a];
            aj[A_M + 3 * a] += xa * g[0];
            aj[A_M + 3 * a + 1] += xa * g[1];
            aj[A_M + 3 * a + 2] += xa * g[2];
          }
      }
    }
    f[i][0] += fxi;
    f[i][1] += fyi;
    f[i][2] += fzi;
    if (mi > 0.0) {
      double *ai = acc[i];
      for (int k = 0; k < 9; k++) ai[A_G + k] += gi[k];
      ai[A_AVHEAT] += avhi;
      if (HEAT) ai[A_HEAT] += heati;
      if (XSPH)
        for (int a = 0; a < 3; a++) ai[A_XSPH + a] += xsi[a];
      if (CORR == 1)
        for (int k = 0; k < 9; k++) ai[A_M + k] += mci[k];
    }
  }
}

/* ----------------------------------------------------------------------
   dispatch: optional physics switched off is compiled out of the pair loop
------------------------------------------------------------------------- */

template <int BND, int HVAR, int HEAT, int CORR> void PairESPHSolid::pair_loop_extra()
{
  const int extra = (astress_flag ? EXTRA_ASTRESS : 0) | (xsph_flag ? EXTRA_XSPH : 0) |
      (vswitch_flag ? EXTRA_VSWITCH : 0);
  // friction and rigid bodies act between bodies only: with boundary particles
  if constexpr (BND) {
    const int fric = (friction > 0.0 && contact != CONTACT_OFF);
    switch ((fric ? EXTRA_FRICTION : 0) | (rigid_flag ? EXTRA_RIGID : 0)) {
      case EXTRA_FRICTION:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_FRICTION>(extra);
        return;
      case EXTRA_RIGID:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_RIGID>(extra);
        return;
      case EXTRA_FRICTION | EXTRA_RIGID:
        pair_loop_select<BND, HVAR, HEAT, CORR, EXTRA_FRICTION | EXTRA_RIGID>(extra);
        return;
      default:
        break;
    }
  }
  pair_loop_select<BND, HVAR, HEAT, CORR, 0>(extra);
}

template <int BND, int HVAR, int HEAT, int CORR, int CONTACT_EXTRA>
void PairESPHSolid::pair_loop_select(int extra)
{
  switch (extra) {
    case 0:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA>();
      break;
    case EXTRA_ASTRESS:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_ASTRESS>();
      break;
    case EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_XSPH>();
      break;
    case EXTRA_ASTRESS | EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_ASTRESS | EXTRA_XSPH>();
      break;
    case EXTRA_VSWITCH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VSWITCH>();
      break;
    case EXTRA_VSWITCH | EXTRA_ASTRESS:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VSWITCH | EXTRA_ASTRESS>();
      break;
    case EXTRA_VSWITCH | EXTRA_XSPH:
      pair_loop<BND, HVAR, HEAT, CORR, CONTACT_EXTRA | EXTRA_VSWITCH | EXTRA_XSPH>();
      break;
    default:
      pair_loop<BND, HVAR, HEAT, CORR,
                CONTACT_EXTRA | EXTRA_VSWITCH | EXTRA_ASTRESS | EXTRA_XSPH>();
      break;
  }
}

template <int BND, int HVAR, int HEAT> void PairESPHSolid::run_corr()
{
  if (correct_flag == 2)
    pair_loop_extra<BND, HVAR, HEAT, 2>();
  else if (correct_flag == 1)
    pair_loop_extra<BND, HVAR, HEAT, 1>();
  else
    pair_loop_extra<BND, HVAR, HEAT, 0>();
}

template <int BND, int HVAR> void PairESPHSolid::run_heat()
{
  if (heat_flag)
    run_corr<BND, HVAR, 1>();
  else
    run_corr<BND, HVAR, 0>();
}

template <int BND> void PairESPHSolid::run_hvar()
{
  if (hvar_flag)
    run_heat<BND, 1>();
  else
    run_heat<BND, 0>();
}

void PairESPHSolid::run_pair_loop(int bnd)
{
  if (bnd)
    run_hvar<1>();
  else
    run_hvar<0>();
}

/* ----------------------------------------------------------------------
   turn accumulated sums into rates (per particle, after reverse comm)
------------------------------------------------------------------------- */

void PairESPHSolid::finalize(int eflag)
{
  const int nlocal = atom->nlocal;
  const int *type = atom->type;
  const double *rmass = state->rmass;
  double **v = atom->v;
  const int bnd = (nboundary > 0);
  double esum = 0.0;
  const int qal = astress_flag ? Q_ALPHA_AST : Q_ALPHA;

  for (int i = 0; i < nlocal; i++) {
    const double *a = acc[i];
    const double *q = hq[i];
    if (rmass[i] > 0.0) {
      const double rho = q[Q_RHO];
      const double *sp = pred_valid ? fix_int->pred[i] + FixESPHIntegrate::P_S : state->s[i];
      Eigen::Matrix3d L;
      L << a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8];
      // continuity (eq. 1): drho_i = sum_j m_j (v_i - v_j).grad_i W = -tr G
      drho[i] = -(a[0] + a[4] + a[8]);
      // energy (eq. 3): de_i = sigma_i : G_i / rho_i^2, with the correction B_i : G_i (the
      // work of the corrected forces), plus viscous heating and heat transfer
      // (in energy/mass units per time, as d_esph_e is stored)
      double work;
      if (correct_flag == 2) {
        const double *B = q + qcol_b;
        work = 0.0;
        for (int k = 0; k < 9; k++) work += B[k] * a[A_G + k];
      } else {
        const double *A = q + Q_A;
        work = A[0] * a[0] + A[1] * a[4] + A[2] * a[8] + A[3] * (a[1] + a[3]) +
            A[4] * (a[2] + a[6]) + A[5] * (a[5] + a[7]);
      }
      de[i] = (work + a[A_AVHEAT] + a[A_HEAT]) * units.energy;
      // velocity gradient L = G / rho (eqs. 15, 17), Jaumann-rate stress (eq. 18);
      // corrected: L = G Mm^-1, exact for linear velocity fields also at free surfaces
      Eigen::Matrix3d Minv;
      if (correct_flag && correction_inverse(a + A_M, rho, dim, Minv))
        L = L * Minv;
      else
        L /= rho;
      jaumann_rate(L, sp, shear[type[i]], ds[i]);
      if (xsph_flag)
        for (int d = 0; d < 3; d++) xsph[i][d] = xsph_eps * a[A_XSPH + d];
      // variable smoothing length (eq. 24): dh/dt = -h/(D rho) drho/dt
      dh[i] = hvar_flag ? -q[Q_H] / (dim * rho) * drho[i] : 0.0;
      // viscosity switch (Morris and Monaghan 1997): decay to alpha_min over
      // tau = h / (l c), rise towards alpha under compression, div v = -drho / rho
      if (vswitch_flag) {
        const double al = q[qal];
        const double compress = MAX(drho[i] / rho, 0.0);
        dalpha[i] = -(al - vswitch_min) * vswitch_l * q[Q_C] / q[Q_H] + compress * (alpha - al);
      }
      if (bnd) store_normal(i);
      if (eflag) {
        const double ei = rmass[i] * q[Q_E] * units.energy;
        esum += ei;
        if (eflag_atom) eatom[i] += ei;
      }
    } else {
      // boundary particle: interpolated velocity and spin from the real particles (4.2)
      store_bnd_gap(i);
      drho[i] = de[i] = dh[i] = 0.0;
      for (int k = 0; k < 6; k++) ds[i][k] = 0.0;
      if (vswitch_flag) dalpha[i] = 0.0;
      if (a[B_WSUM] > 0.0) {
        // interpolation from the real particles p of the body: with the Shepard means
        // vbar, xi = xbar - x_k, and the corrected velocity gradient
        //   L = (A - vbar (x) b) (M - xi (x) b)^-1,
        // exact for a linear velocity field where the kernel is one-sided (surface)
        const double inv = 1.0 / a[B_WSUM];
        const double vbar[3] = {a[B_VSUM] * inv, a[B_VSUM + 1] * inv, a[B_VSUM + 2] * inv};
        const double xi[3] = {a[B_XSUM] * inv, a[B_XSUM + 1] * inv, a[B_XSUM + 2] * inv};
        Eigen::Matrix3d Lk, M;
        for (int r = 0; r < 3; r++)
          for (int c = 0; c < 3; c++) {
            Lk(r, c) = a[B_A + 3 * r + c] - vbar[r] * a[B_B + c];
            M(r, c) = a[B_M + 3 * r + c] - xi[r] * a[B_B + c];
          }
        for (int d = dim; d < 3; d++) M(d, d) = 1.0;
        if (fabs(M.determinant()) > 1.0e-6)
          Lk = Lk * M.inverse();
        else
          Lk.setZero();
        // the boundary particle moves with the Shepard mean corrected by the rotation
        // only: extrapolating the strain part would overshoot at impact fronts
        const Eigen::Matrix3d Wk = 0.5 * (Lk - Lk.transpose());
        double vk[3];
        for (int r = 0; r < 3; r++)
          vk[r] = vbar[r] - (Wk(r, 0) * xi[0] + Wk(r, 1) * xi[1] + Wk(r, 2) * xi[2]);
        bvel[i][0] = vk[0];
        bvel[i][1] = vk[1];
        bvel[i][2] = vk[2];
        bspin[i][0] = 0.5 * (Lk(0, 1) - Lk(1, 0));
        bspin[i][1] = 0.5 * (Lk(0, 2) - Lk(2, 0));
        bspin[i][2] = 0.5 * (Lk(1, 2) - Lk(2, 1));
      } else {
        bvel[i][0] = v[i][0];
        bvel[i][1] = v[i][1];
        bvel[i][2] = v[i][2];
        bspin[i][0] = bspin[i][1] = bspin[i][2] = 0.0;
      }
    }
  }
  if (eflag_global) eng_vdwl += esum;
  if (bnd) normals_valid = 1;
}

/* ----------------------------------------------------------------------
   normal and depth of real particle i from its sums; the length of the
   normal is kept as the coherence |sum n_k W| / sum W <= 1
------------------------------------------------------------------------- */

void PairESPHSolid::store_normal(int i)
{
  const double *a = acc[i];
  const double n2 =
      a[A_NSUM] * a[A_NSUM] + a[A_NSUM + 1] * a[A_NSUM + 1] + a[A_NSUM + 2] * a[A_NSUM + 2];
  if (n2 > 0.0 && a[A_WSUM] > 0.0) {
    const double inv = 1.0 / a[A_WSUM];
    for (int d = 0; d < 3; d++) state->n[i][d] = a[A_NSUM + d] * inv;
    state->depth[i] = a[A_DSUM] * inv;
  } else {
    state->n[i][0] = state->n[i][1] = state->n[i][2] = 0.0;
    state->depth[i] = 0.0;
  }
  // the gap from the boundary particles of the own body, at the time of this computation
  if (contact == CONTACT_SOLID && a[A_GW] > 0.0) {
    state->gap[i] = a[A_GG] / a[A_GW];
    state->gapv[i] = a[A_GV] / a[A_GW];
  } else {
    state->gap[i] = GAP_NONE;
    state->gapv[i] = 0.0;
  }
  // engagement for the next computation, from the gap it will see; the stored value is
  // the one this computation used until now (hoisted)
  state->eng[i] = (contact == CONTACT_SOLID)
      ? contact_engage(hq[i][Q_ENG], state->gap[i] + dt_step * state->gapv[i] - GAP_EPS * h0, onset)
      : 0.0;
}

/* ----------------------------------------------------------------------
   the tally of the pair of bodies a, b (in either order) of this compute
------------------------------------------------------------------------- */

std::array<double, 3> &PairESPHSolid::tally_bodies(int a, int b)
{
  const auto key = (a < b) ? std::make_pair(a, b) : std::make_pair(b, a);
  auto it = body_tally.find(key);
  if (it == body_tally.end())
    it = body_tally.emplace(key, std::array<double, 3>{0.0, 0.0, 0.0}).first;
  return it->second;
}

/* ----------------------------------------------------------------------
   gap of boundary particle i from its best facing partner of another body
------------------------------------------------------------------------- */

void PairESPHSolid::store_bnd_gap(int i)
{
  if (!contact_bnd_result(acc[i] + B_GAP, state->gap[i], state->gapv[i])) {
    state->gap[i] = GAP_NONE;
    state->gapv[i] = 0.0;
  }
}

/* ----------------------------------------------------------------------
   normals (eq. 30) and depths of real particles from the boundary particles
   of their own body; used at the start of a run, later they come with the
   regular pair loop
------------------------------------------------------------------------- */

void PairESPHSolid::compute_normals()
{
  double **x = atom->x;
  double **v = atom->v;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  const int newton_pair = force->newton_pair;
  const double cutsq_global = cut_global * cut_global;
  const int solid = (contact == CONTACT_SOLID);

  // normals, h and velocities of the boundary particles must be known on ghosts
  for (int i = 0; i < nlocal; i++) {
    for (int d = 0; d < 3; d++) {
      hq[i][Q_N + d] = state->n[i][d];
      hq[i][Q_V + d] = v[i][d];
    }
    hq[i][Q_H] = state->h[i];
    hq[i][Q_ENG] = state->eng[i];
  }
  comm_stage = COMM_NORMALS;
  comm->forward_comm(this, 7);
  for (int i = 0; i < nall; i++) {
    for (int k = A_NSUM; k <= A_WSUM; k++) acc[i][k] = 0.0;
    for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
  }

  // pass 1: normal sums of real particles, gaps of boundary particles
  for (int ii = 0; ii < list->inum; ii++) {
    const int i = list->ilist[ii];
    const int *jlist = list->firstneigh[i];
    for (int jj = 0; jj < list->numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
      const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
      if (rsq >= cutsq_global) continue;
      if (rmass[i] == 0.0 && rmass[j] == 0.0) {
        if (solid && body[i] != body[j])
          bnd_gap_pair(acc[i], (newton_pair || j < nlocal) ? acc[j] : nullptr, hq[i], hq[j], dx,
                       GAP_EPS * h0);
        continue;
      }
      if (rmass[i] > 0.0 && rmass[j] > 0.0) continue;
      if (body[i] != body[j]) continue;
      const double hij = hvar_flag ? 0.5 * (hq[i][Q_H] + hq[j][Q_H]) : h0;
      double w, dw;
      if (!kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw))
        continue;
      const int p = (rmass[i] > 0.0) ? i : j;
      const int k = (p == i) ? j : i;
      if (p >= nlocal && !newton_pair && p != i) continue;
      const double sgn = (k == i) ? 1.0 : -1.0;
      add_normal_sums(acc[p], w, sgn, dx, hq[k] + Q_N);
    }
  }
  if (newton_pair) {
    comm_stage = COMM_NORMALS;
    comm->reverse_comm(this, (A_WSUM - A_NSUM + 1) + (GAP_END - A_GW));
  }
  for (int i = 0; i < nlocal; i++) {
    if (rmass[i] == 0.0) {
      store_bnd_gap(i);
      hq[i][Q_GAP] = state->gap[i];
      hq[i][Q_GAPV] = state->gapv[i];
    } else {
      for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
    }
  }

  // pass 2: gaps of real particles from their own boundary particles
  if (solid) {
    comm_stage = COMM_GAPS;
    comm->forward_comm(this, 2);
    for (int i = nlocal; i < nall; i++)
      for (int k = A_GW; k < GAP_END; k++) acc[i][k] = 0.0;
    for (int ii = 0; ii < list->inum; ii++) {
      const int i = list->ilist[ii];
      const int *jlist = list->firstneigh[i];
      for (int jj = 0; jj < list->numneigh[i]; jj++) {
        const int j = jlist[jj] & NEIGHMASK;
        if ((rmass[i] == 0.0) == (rmass[j] == 0.0)) continue;
        if (body[i] != body[j]) continue;
        const double dx[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
        const double rsq = dx[0] * dx[0] + dx[1] * dx[1] + dx[2] * dx[2];
        if (rsq >= cutsq_global) continue;
        const double hij = hvar_flag ? 0.5 * (hq[i][Q_H] + hq[j][Q_H]) : h0;
        double w, dw;
        if (!kernel_eval(kernel, dim, kernel_norm(kernel, dim, hij), 1.0 / hij, sqrt(rsq), w, dw))
          continue;
        const int p = (rmass[i] > 0.0) ? i : j;
        const int k = (p == i) ? j : i;
        if (p >= nlocal && !newton_pair && p != i) continue;
        // the gaps are of this moment: no extrapolation
        add_gap_sums(acc[p], w, hq[k], 0.0);
      }
    }
    if (newton_pair) {
      comm_stage = COMM_GAPS;
      comm->reverse_comm(this, GAP_END - A_GW);
    }
  }
  for (int i = 0; i < nlocal; i++) {
    if (rmass[i] == 0.0) continue;
    store_normal(i);
    // the force computation brings the gap forward by one step: it is of now
    if (state->gap[i] < GAP_NONE) state->gap[i] -= update->dt * state->gapv[i];
  }
  normals_valid = 1;
}

/* ----------------------------------------------------------------------
   normal, surface gap, gap rate and engagement (6 values) of owned atom i that the
   last force computation used (its hoisted copy; valid until the next
   computation); false before any computation
------------------------------------------------------------------------- */

bool PairESPHSolid::geometry_used(int i, double *out) const
{
  if (!hq) return false;
  const double *q = hq[i];
  for (int k = 0; k < 3; k++) out[k] = q[Q_N + k];
  out[3] = q[Q_GAP];
  out[4] = q[Q_GAPV];
  out[5] = q[Q_ENG];
  return true;
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
  const int qal = astress_flag ? Q_ALPHA_AST : Q_ALPHA;
  for (int i = 0; i < n; i++) {
    const double *q = hq[list[i]];
    for (int k = 0; k < 12; k++) buf[m++] = q[k];
    if (comm_bnd) {
      for (int k = Q_N; k <= Q_GAP; k++) buf[m++] = q[k];
      buf[m++] = q[Q_GAPV];
      buf[m++] = q[Q_ENG];
    }
    if (heat_flag) {
      buf[m++] = q[Q_E];
      buf[m++] = q[Q_ZETA];
    }
    if (vswitch_flag) buf[m++] = q[qal];
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
  const int qal = astress_flag ? Q_ALPHA_AST : Q_ALPHA;
  for (int i = first; i < last; i++) {
    double *q = hq[i];
    for (int k = 0; k < 12; k++) q[k] = buf[m++];
    if (comm_bnd) {
      for (int k = Q_N; k <= Q_GAP; k++) q[k] = buf[m++];
      q[Q_GAPV] = buf[m++];
      q[Q_ENG] = buf[m++];
    }
    if (heat_flag) {
      q[Q_E] = buf[m++];
      q[Q_ZETA] = buf[m++];
    }
    if (vswitch_flag) q[qal] = buf[m++];
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
  for (int i = first; i < last; i++) {
    const double *a = acc[i];
    if (comm_stage == COMM_NORMALS) {
      for (int k = A_NSUM; k <= A_WSUM; k++) buf[m++] = a[k];
      for (int k = A_GW; k < GAP_END; k++) buf[m++] = a[k];
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
  const double *rmass = state->rmass;
  for (int i = 0; i < n; i++) {
    const int j = list[i];
    double *a = acc[j];
    int k0 = 0, k1 = nreverse;
    if (comm_stage == COMM_NORMALS) {
      for (int k = A_NSUM; k <= A_WSUM; k++) a[k] += buf[m++];
      k0 = A_GW;
      k1 = GAP_END;
    } else if (comm_stage == COMM_GAPS) {
      k0 = A_GW;
      k1 = GAP_END;
    } else if (comm_stage == COMM_CORR) {
      k0 = A_M;
      k1 = A_M + 9;
    }
    const int gaps = (k1 > A_GW) && (rmass[j] == 0.0);
    for (int k = k0; k < k1; k++) {
      if (gaps && k == B_GAP) {
        contact_bnd_merge(a + B_GAP, buf + m);
        m += GAP_SLOTS;
        k += GAP_SLOTS - 1;
      } else {
        a[k] += buf[m++];
      }
    }
  }
}

/* ---------------------------------------------------------------------- */

double PairESPHSolid::memory_usage()
{
  double bytes = Pair::memory_usage();
  bytes += (double) nmax * (NACC + hq_cols + 3 + 6 + 3 + 3) * sizeof(double);
  if (xsph) bytes += (double) nmax * 3 * sizeof(double);
  if (dalpha) bytes += (double) nmax * sizeof(double);
  bytes += (double) atom_contact_nmax * 2 * sizeof(double);
  return bytes;
}

/* ---------------------------------------------------------------------- */

void *PairESPHSolid::extract(const char *str, int &dim_out)
{
  dim_out = 0;
  if (strcmp(str, "h") == 0) return (void *) &h0;
  if (strcmp(str, "cut") == 0) return (void *) &cut_global;
  return nullptr;
}

/* ----------------------------------------------------------------------
   per-atom contact output for compute esph/atom: zeroed for owned and
   ghost atoms before the pair loop, which adds to it for every interacting
   cross-body pair (count, transmitted compressive normal force)
------------------------------------------------------------------------- */

void PairESPHSolid::atom_contact_clear()
{
  const int nall = atom->nlocal + atom->nghost;
  if (atom->nmax > atom_contact_nmax) {
    atom_contact_nmax = atom->nmax;
    memory->destroy(atom_contact);
    memory->create(atom_contact, atom_contact_nmax, 2, "pair:atom_contact");
  }
  if (nall > 0) memset(&atom_contact[0][0], 0, sizeof(double) * 2 * nall);
}
