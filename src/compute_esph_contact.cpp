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
   Contact bookkeeping per pair of bodies (global array, one row per pair
   of bodies that has touched), kept by fix esph/integrate from the pair
   style's tallies of every step.
------------------------------------------------------------------------- */

#include "compute_esph_contact.h"

#include "error.h"
#include "fix_esph_integrate.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

ComputeESPHContact::ComputeESPHContact(LAMMPS *lmp, int narg, char **arg) :
    Compute(lmp, narg, arg), fix_int(nullptr), nrows_alloc(0)
{
  if (narg != 3) error->all(FLERR, "Illegal compute esph/contact command: it takes no arguments");
  array_flag = 1;
  // the scalar: the number of rows (pairs of bodies that have touched), so that an input
  // can ask before it names a row
  scalar_flag = 1;
  extscalar = 0;
  size_array_cols = NCOLS;
  size_array_rows = 0;
  size_array_rows_variable = 1;
  extarray = 0;
  array = nullptr;
}

/* ---------------------------------------------------------------------- */

ComputeESPHContact::~ComputeESPHContact()
{
  memory->destroy(array);
}

/* ---------------------------------------------------------------------- */

void ComputeESPHContact::init()
{
  auto fixes = modify->get_fix_by_style("^esph/integrate");
  if (fixes.empty())
    error->all(FLERR, Error::NOLASTLINE, "Compute esph/contact requires fix esph/integrate");
  fix_int = dynamic_cast<FixESPHIntegrate *>(fixes[0]);
}

/* ----------------------------------------------------------------------
   the number of rows now, as a scalar (c_ID in thermo, variables, if)
------------------------------------------------------------------------- */

double ComputeESPHContact::compute_scalar()
{
  invoked_scalar = update->ntimestep;
  if (!fix_int) init();
  scalar = (double) fix_int->body_pairs.size();
  return scalar;
}

/* ----------------------------------------------------------------------
   the number of rows now (fix ave/time mode vector sizes its columns by it)
------------------------------------------------------------------------- */

int ComputeESPHContact::lock_length()
{
  if (invoked_array != update->ntimestep) compute_array();
  return size_array_rows;
}

/* ----------------------------------------------------------------------
   columns: 1, 2 bodies I < J; 3 touching pairs, 4 interacting pairs,
   5 normal force now; 6 impulse so far; 7 first touch, 8 end of the first
   contact episode (-1 before), 9 its duration (-1 before it ends once),
   10 number of episodes, 11 peak normal force; 12-14 net force on body I
   from J now (vector, friction included), 15-17 its time integral (the
   momentum J gave I)
------------------------------------------------------------------------- */

void ComputeESPHContact::compute_array()
{
  invoked_array = update->ntimestep;
  if (!fix_int) init();
  const auto &pairs = fix_int->body_pairs;
  const auto &recs = fix_int->body_records;
  const int n = pairs.size();
  if (n > nrows_alloc) {
    memory->destroy(array);
    nrows_alloc = n;
    memory->create(array, nrows_alloc, NCOLS, "esph/contact:array");
  }
  size_array_rows = n;
  for (int p = 0; p < n; p++) {
    const auto &r = recs[p];
    double *a = array[p];
    a[0] = pairs[p].first;
    a[1] = pairs[p].second;
    a[2] = r.ntouch;
    a[3] = r.nint;
    a[4] = r.force;
    a[5] = r.impulse;
    a[6] = r.tfirst;
    a[7] = r.tlast;
    a[8] = (r.tlast >= 0.0 && r.tfirst >= 0.0) ? r.tlast - r.tfirst : -1.0;
    a[9] = r.nepisodes;
    a[10] = r.fpeak;
    for (int d = 0; d < 3; d++) {
      a[11 + d] = r.fnet[d];
      a[14 + d] = r.jnet[d];
    }
  }
}
