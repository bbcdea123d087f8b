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

#include "esph_state.h"

#include "atom.h"
#include "atom_vec.h"
#include "error.h"
#include "esph_contact.h"
#include "modify.h"

#include <algorithm>
#include <string>
#include <utility>

using namespace LAMMPS_NS;

/* ----------------------------------------------------------------------
   true if internal fix fixid exists; error if its per-atom property name
   exists without it (defined by hand)
------------------------------------------------------------------------- */

static bool internal_fix_exists(LAMMPS *lmp, const char *fixid, const char *name)
{
  if (lmp->modify->get_fix_by_id(fixid)) return true;
  int flag, cols;
  if (lmp->atom->find_custom(name, flag, cols) >= 0)
    lmp->error->all(FLERR, Error::NOLASTLINE,
                    "ESPH per-atom property {} exists but fix {} does not: it must not be "
                    "defined by hand",
                    name, fixid);
  return false;
}

/* ---------------------------------------------------------------------- */

void ESPHState::ensure(LAMMPS *lmp)
{
  if (internal_fix_exists(lmp, FIX_ID, "esph_rho")) return;
  // three fixes, so that each data-file line stays below read_data's 256 characters
  std::string cmd = std::string(FIX_ID) + " all property/atom";
  if (!lmp->atom->rmass_flag) cmd += " rmass";
  cmd += " d_esph_rho d_esph_e d_esph_h i_esph_body d_esph_depth d_esph_gap d_esph_gapv d_esph_eng "
         "ghost yes";
  lmp->modify->add_fix(cmd);
  lmp->modify->add_fix(std::string(FIX_ID_STRESS) + " all property/atom d2_esph_s 6 ghost yes");
  lmp->modify->add_fix(std::string(FIX_ID_NORMAL) + " all property/atom d2_esph_n 3 ghost yes");
}

/* ---------------------------------------------------------------------- */

// a pair of optional internal fixes with a per-atom array d2_<name>[cols] each: what the
// last computation found, and (d2_<name>_used) what it used; in data files or not
static void ensure_pair(LAMMPS *lmp, const char *id, const char *id_used, const std::string &name,
                        int cols, bool writedata)
{
  const std::string wd = writedata ? "" : " writedata no";
  for (const auto &f : {std::make_pair(id, name), std::make_pair(id_used, name + "_used")})
    if (!internal_fix_exists(lmp, f.first, f.second.c_str()))
      lmp->modify->add_fix(
          fmt::format("{} all property/atom d2_{} {}{}", f.first, f.second, cols, wd));
}

// an optional internal fix with one per-atom double d_<name>, created once
static void ensure_optional(LAMMPS *lmp, const char *id, const char *name)
{
  if (internal_fix_exists(lmp, id, name)) return;
  lmp->modify->add_fix(fmt::format("{} all property/atom d_{}", id, name));
}

void ESPHState::ensure_plastic(LAMMPS *lmp)
{
  ensure_optional(lmp, FIX_ID_PLASTIC, "esph_epsp");
}

/* ---------------------------------------------------------------------- */

void ESPHState::ensure_visc(LAMMPS *lmp)
{
  ensure_optional(lmp, FIX_ID_VISC, "esph_alpha");
}

/* ---------------------------------------------------------------------- */

void ESPHState::ensure_recon(LAMMPS *lmp)
{
  // the strain rates of the last computation: in restart files (a continued run is exact),
  // not in data files (read_data needs only the three state sections; a run from a data
  // file starts with zero rates, the paper's viscosity in its first computation)
  ensure_pair(lmp, FIX_ID_RECON, FIX_ID_RECON_USED, "esph_drec", 6, false);
}

/* ---------------------------------------------------------------------- */

void ESPHState::drop_optional(LAMMPS *lmp, const char *fixid, const char *name)
{
  int flag, cols;
  if (lmp->modify->get_fix_by_id(fixid) && lmp->atom->find_custom(name, flag, cols) >= 0)
    lmp->modify->delete_fix(fixid);
}

/* ---------------------------------------------------------------------- */

void ESPHState::drop_recon(LAMMPS *lmp)
{
  drop_optional(lmp, FIX_ID_RECON, "esph_drec");
  drop_optional(lmp, FIX_ID_RECON_USED, "esph_drec_used");
}

/* ---------------------------------------------------------------------- */

void ESPHState::ensure_cone(LAMMPS *lmp)
{
  ensure_pair(lmp, FIX_ID_CONE, FIX_ID_CONE_USED, "esph_cone", 6, true);
}

/* ---------------------------------------------------------------------- */

void ESPHState::ensure_fric(LAMMPS *lmp)
{
  // in restart files (a continued run is exact), not in data files (a run from a data file
  // starts with no friction held)
  ensure_pair(lmp, FIX_ID_FRIC, FIX_ID_FRIC_USED, "esph_fric", 3, false);
}

/* ---------------------------------------------------------------------- */

ESPHState::ESPHState(LAMMPS *_lmp) :
    rmass(nullptr), rho(nullptr), e(nullptr), h(nullptr), s(nullptr), n(nullptr), depth(nullptr),
    gap(nullptr), gapv(nullptr), eng(nullptr), body(nullptr), epsp(nullptr), alpha(nullptr),
    drec(nullptr), drecu(nullptr), cone(nullptr), coneu(nullptr), fric(nullptr), fricu(nullptr),
    lmp(_lmp), iepsp(-1), ialpha(-1), idrec(-1), idrecu(-1), icone(-1), iconeu(-1), ifric(-1),
    ifricu(-1)
{
  ensure(lmp);
  int flag, cols;
  irho = lmp->atom->find_custom("esph_rho", flag, cols);
  ie = lmp->atom->find_custom("esph_e", flag, cols);
  ih = lmp->atom->find_custom("esph_h", flag, cols);
  is = lmp->atom->find_custom("esph_s", flag, cols);
  in = lmp->atom->find_custom("esph_n", flag, cols);
  idepth = lmp->atom->find_custom("esph_depth", flag, cols);
  ibody = lmp->atom->find_custom("esph_body", flag, cols);
  igap = lmp->atom->find_custom("esph_gap", flag, cols);
  igapv = lmp->atom->find_custom("esph_gapv", flag, cols);
  ieng = lmp->atom->find_custom("esph_eng", flag, cols);
  if (irho < 0 || ie < 0 || ih < 0 || is < 0 || in < 0 || idepth < 0 || ibody < 0 || igap < 0 ||
      igapv < 0 || ieng < 0)
    lmp->error->all(FLERR, Error::NOLASTLINE, "ESPH per-atom state in fix {} is incomplete",
                    FIX_ID);
  fetch();
}

/* ---------------------------------------------------------------------- */

void ESPHState::clear_atom(int i)
{
  fetch();
  const auto &created = lmp->atom->avec->fields_create;
  if (rmass && std::find(created.begin(), created.end(), "rmass") == created.end()) rmass[i] = 0.0;
  rho[i] = e[i] = h[i] = depth[i] = gapv[i] = eng[i] = 0.0;
  gap[i] = ESPH::GAP_NONE;
  body[i] = 0;
  for (int k = 0; k < 6; k++) s[i][k] = 0.0;
  for (int k = 0; k < 3; k++) n[i][k] = 0.0;
  if (epsp) epsp[i] = 0.0;
  if (alpha) alpha[i] = 0.0;
  for (double **a : {drec, drecu, cone, coneu})
    if (a)
      for (int k = 0; k < 6; k++) a[i][k] = 0.0;
  for (double **a : {fric, fricu})
    if (a)
      for (int k = 0; k < 3; k++) a[i][k] = 0.0;
}

/* ---------------------------------------------------------------------- */

void ESPHState::fetch()
{
  Atom *atom = lmp->atom;
  rmass = atom->rmass;
  rho = atom->dvector[irho];
  e = atom->dvector[ie];
  h = atom->dvector[ih];
  s = atom->darray[is];
  n = atom->darray[in];
  depth = atom->dvector[idepth];
  gap = atom->dvector[igap];
  gapv = atom->dvector[igapv];
  eng = atom->dvector[ieng];
  body = atom->ivector[ibody];
  // optional: looked up each time (created when plasticity is defined)
  int flag, cols;
  iepsp = atom->find_custom("esph_epsp", flag, cols);
  epsp = (iepsp >= 0) ? atom->dvector[iepsp] : nullptr;
  ialpha = atom->find_custom("esph_alpha", flag, cols);
  alpha = (ialpha >= 0) ? atom->dvector[ialpha] : nullptr;
  idrec = atom->find_custom("esph_drec", flag, cols);
  // a restart file of ESPH before the split kept both in one 12-column d2_esph_drec
  if (idrec >= 0 && cols != 6)
    lmp->error->all(FLERR, Error::NOLASTLINE,
                    "ESPH per-atom property d2_esph_drec has {} columns, expected 6 (a restart "
                    "or data file of an older ESPH version: rerun its input with this version)",
                    cols);
  idrecu = atom->find_custom("esph_drec_used", flag, cols);
  drec = (idrec >= 0 && idrecu >= 0) ? atom->darray[idrec] : nullptr;
  drecu = (idrec >= 0 && idrecu >= 0) ? atom->darray[idrecu] : nullptr;
  icone = atom->find_custom("esph_cone", flag, cols);
  iconeu = atom->find_custom("esph_cone_used", flag, cols);
  cone = (icone >= 0 && iconeu >= 0) ? atom->darray[icone] : nullptr;
  coneu = (icone >= 0 && iconeu >= 0) ? atom->darray[iconeu] : nullptr;
  ifric = atom->find_custom("esph_fric", flag, cols);
  ifricu = atom->find_custom("esph_fric_used", flag, cols);
  fric = (ifric >= 0 && ifricu >= 0) ? atom->darray[ifric] : nullptr;
  fricu = (ifric >= 0 && ifricu >= 0) ? atom->darray[ifricu] : nullptr;
}
