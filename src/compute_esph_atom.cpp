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
   Per-atom derived quantities of the ESPH state for output: pressure from
   the equation of state of pair esph/solid, von Mises and Cauchy stress,
   volumetric strain, sound speed, plastic strain, and the per-particle
   contact of the last force computation.
------------------------------------------------------------------------- */

#include "compute_esph_atom.h"

#include "atom.h"
#include "error.h"
#include "esph_state.h"
#include "esph_strength.h"
#include "force.h"
#include "memory.h"
#include "pair_esph_solid.h"
#include "update.h"

#include <cmath>
#include <cstring>

using namespace LAMMPS_NS;

// keywords in the order of the enum Value
static const char *const KEYWORDS[] = {"pressure",     "vonmises",    "stress/xx",      "stress/yy",
                                       "stress/zz",    "stress/xy",   "stress/xz",      "stress/yz",
                                       "strain/vol",   "speed/sound", "strain/plastic", "contact",
                                       "contact/force"};
static constexpr const char *EXPECTED =
    "pressure, vonmises, stress/xx, stress/yy, stress/zz, stress/xy, stress/xz, stress/yz, "
    "stress/*, strain/vol, speed/sound, strain/plastic, contact or contact/force";

/* ---------------------------------------------------------------------- */

ComputeESPHAtom::ComputeESPHAtom(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), contact_flag(0), nmax(0), vec(nullptr), arr(nullptr), pair(nullptr),
    state(nullptr)
{
  // no keywords: every quantity, in the order of the enum
  if (narg == 3)
    for (int v = 0; v < NVALUES; v++) values.push_back(v);
  for (int iarg = 3; iarg < narg; iarg++) {
    if (strcmp(arg[iarg], "stress/*") == 0) {
      for (int v = SXX; v <= SYZ; v++) values.push_back(v);
      continue;
    }
    int found = -1;
    for (int v = 0; v < NVALUES; v++)
      if (strcmp(arg[iarg], KEYWORDS[v]) == 0) found = v;
    if (found < 0)
      error->all(FLERR, iarg, "Unknown compute esph/atom keyword {}: expected {}", arg[iarg],
                 EXPECTED);
    values.push_back(found);
  }
  for (int v : values)
    if (v == CONTACT || v == CONTACT_FORCE) contact_flag = 1;

  peratom_flag = 1;
  size_peratom_cols = (values.size() == 1) ? 0 : values.size();
}

/* ---------------------------------------------------------------------- */

ComputeESPHAtom::~ComputeESPHAtom()
{
  memory->destroy(vec);
  memory->destroy(arr);
  delete state;
}

/* ---------------------------------------------------------------------- */

void ComputeESPHAtom::init()
{
  pair = dynamic_cast<PairESPHSolid *>(force->pair_match("^esph/solid", 0));
  if (!pair)
    error->all(FLERR, Error::NOLASTLINE,
               "Compute esph/atom requires pair style esph/solid (its equation of state, "
               "materials and contact), found pair style {}",
               force->pair_style ? force->pair_style : "none");
  if (!state) state = new ESPHState(lmp);
  // the pair accumulates the per-atom contact sums only while asked (its init_style()
  // clears the request before this)
  if (contact_flag) pair->atom_contact_flag = 1;
}

/* ---------------------------------------------------------------------- */

void ComputeESPHAtom::compute_peratom()
{
  invoked_peratom = update->ntimestep;
  if (!pair) init();

  if (atom->nmax > nmax) {
    nmax = atom->nmax;
    if (size_peratom_cols == 0) {
      memory->destroy(vec);
      memory->create(vec, nmax, "esph/atom:vector");
      vector_atom = vec;
    } else {
      memory->destroy(arr);
      memory->create(arr, nmax, size_peratom_cols, "esph/atom:array");
      array_atom = arr;
    }
  }

  state->fetch();
  const int nlocal = atom->nlocal;
  const int *mask = atom->mask;
  const int *type = atom->type;
  const double *rmass = state->rmass;
  const double *epsp = state->epsp;
  const ESPH::EOS *eos = pair->eos;
  // the contact sums of the last force computation, if it made them for these atoms
  double **catom =
      (pair->atom_contact_flag && pair->atom_contact_nmax >= nlocal) ? pair->atom_contact : nullptr;
  const int ncols = values.size();
  double out[NVALUES];

  for (int i = 0; i < nlocal; i++) {
    double *row = (size_peratom_cols == 0) ? vec + i : arr[i];
    // atoms outside the group and boundary particles (no mass, no material state): 0
    if (!(mask[i] & groupbit) || rmass[i] <= 0.0) {
      for (int k = 0; k < ncols; k++) row[k] = 0.0;
      continue;
    }
    // as the pair style evaluates them: P and c^2 from the EOS of the type, c^2 >= 0
    const ESPH::EOS &eq = eos[type[i]];
    const double rho = state->rho[i];
    double P, c2;
    eq.compute(rho, state->e[i] * pair->units.energy_in, P, c2);
    // in pressure units, as the stress d2_esph_s
    P *= pair->units.pressure;
    const double *s = state->s[i];
    out[PRESSURE] = P;
    out[VONMISES] = ESPH::von_mises(s);
    // Cauchy stress sigma = -P I + S, tension positive
    out[SXX] = s[0] - P;
    out[SYY] = s[1] - P;
    out[SZZ] = s[2] - P;
    out[SXY] = s[3];
    out[SXZ] = s[4];
    out[SYZ] = s[5];
    // (V - V0) / V0 at constant mass
    out[STRAIN_VOL] = eq.rho0 / rho - 1.0;
    out[SPEED_SOUND] = (c2 > 0.0) ? sqrt(c2) : 0.0;
    out[STRAIN_PLASTIC] = epsp ? epsp[i] : 0.0;
    out[CONTACT] = (catom && catom[i][0] > 0.0) ? 1.0 : 0.0;
    out[CONTACT_FORCE] = catom ? catom[i][1] : 0.0;
    for (int k = 0; k < ncols; k++) row[k] = out[values[k]];
  }
}

/* ---------------------------------------------------------------------- */

double ComputeESPHAtom::memory_usage()
{
  return (double) nmax * MAX((int) values.size(), 1) * sizeof(double);
}
