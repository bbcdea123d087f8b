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

// Plugin loader of the ESPH package: registers every style for
// "plugin load esphplugin.so" or LAMMPS_PLUGIN_PATH autoloading.

#include "lammpsplugin.h"
#include "version.h"

#include "compute_esph_atom.h"
#include "compute_esph_contact.h"
#include "fix_esph_boundary.h"
#include "fix_esph_integrate.h"
#include "fix_esph_integrate_omp.h"
#include "pair_esph_solid.h"
#include "pair_esph_solid_omp.h"

using namespace LAMMPS_NS;

static Pair *pair_esph_solid_creator(LAMMPS *lmp)
{
  return new PairESPHSolid(lmp);
}

static Pair *pair_esph_solid_omp_creator(LAMMPS *lmp)
{
  return new PairESPHSolidOMP(lmp);
}

static Fix *fix_esph_integrate_omp_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixESPHIntegrateOMP(lmp, argc, argv);
}

static Fix *fix_esph_integrate_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixESPHIntegrate(lmp, argc, argv);
}

static Fix *fix_esph_boundary_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new FixESPHBoundary(lmp, argc, argv);
}

static Compute *compute_esph_atom_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new ComputeESPHAtom(lmp, argc, argv);
}

static Compute *compute_esph_contact_creator(LAMMPS *lmp, int argc, char **argv)
{
  return new ComputeESPHContact(lmp, argc, argv);
}

extern "C" void lammpsplugin_init(void *lmp, void *handle, void *regfunc)
{
  lammpsplugin_t plugin;
  auto register_plugin = (lammpsplugin_regfunc) regfunc;

  plugin.version = LAMMPS_VERSION;
  plugin.author = "ESPH developers";
  plugin.handle = handle;

  plugin.style = "pair";
  plugin.name = "esph/solid";
  plugin.info = "ESPH elastic solid SPH pair style with contact v0.1";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_esph_solid_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "esph/solid/omp";
  plugin.info = "ESPH elastic solid SPH pair style with contact, OpenMP threads v0.1";
  plugin.creator.v1 = (lammpsplugin_factory1 *) &pair_esph_solid_omp_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "fix";
  plugin.name = "esph/integrate";
  plugin.info = "ESPH time integration v0.1";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_esph_integrate_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "esph/integrate/omp";
  plugin.info = "ESPH time integration, OpenMP threads v0.1";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_esph_integrate_omp_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "esph/boundary";
  plugin.info = "ESPH non-mass boundary particles with normals v0.1";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &fix_esph_boundary_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.style = "compute";
  plugin.name = "esph/contact";
  plugin.info = "ESPH contact bookkeeping per pair of bodies v0.1";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &compute_esph_contact_creator;
  (*register_plugin)(&plugin, lmp);

  plugin.name = "esph/atom";
  plugin.info = "ESPH per-atom pressure, stress, strain, sound speed and contact v0.1";
  plugin.creator.v2 = (lammpsplugin_factory2 *) &compute_esph_atom_creator;
  (*register_plugin)(&plugin, lmp);
}
