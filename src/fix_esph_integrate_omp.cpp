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
   fix esph/integrate/omp: fix esph/integrate with its per-atom passes in
   OpenMP threads (package omp N, or -sf omp -pk omp N)
------------------------------------------------------------------------- */

#include "fix_esph_integrate_omp.h"

#include "comm.h"

using namespace LAMMPS_NS;

/* ---------------------------------------------------------------------- */

FixESPHIntegrateOMP::FixESPHIntegrateOMP(LAMMPS *lmp, int narg, char **arg) :
    FixESPHIntegrate(lmp, narg, arg)
{
}

/* ---------------------------------------------------------------------- */

void FixESPHIntegrateOMP::init()
{
  FixESPHIntegrate::init();
  nthreads = comm->nthreads;
}
