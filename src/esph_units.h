/* -*- c++ -*- ----------------------------------------------------------
   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator
   https://www.lammps.org/, Sandia National Laboratories
   LAMMPS development team: developers@lammps.org

   Copyright (2003) Sandia Corporation.  Under the terms of Contract
   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains
   certain rights in this software.  This software is distributed under
   the GNU General Public License.

   See the README file in the top-level LAMMPS directory.
------------------------------------------------------------------------- */

// Unit conversion of the ESPH package, in one place. The mechanics (EOS, forces,
// rates, time step) run in the consistent units of the unit style's mass, distance and
// time: force = mass distance/time^2, specific energy = velocity^2, pressure =
// mass/(distance time^2). LAMMPS's force, energy and pressure units differ from these
// in units metal and real; the factors below convert, from LAMMPS's own constants
// (force->ftm2v, mvv2e, nktv2p). Input and output (pair_coeff moduli, per-atom stress
// and energy, atom->f, pe, computes) are in LAMMPS's units. In units with all three
// constants 1 (si, cgs, micro, nano, lj) every factor is exactly 1.0, so that the
// results are bitwise those without conversion.
// Pure math, no LAMMPS dependency: unit-tested alone.

#ifndef LMP_ESPH_UNITS_H
#define LMP_ESPH_UNITS_H

namespace ESPH {

struct Units {
  double force;          // internal force -> force units (1 / ftm2v)
  double energy;         // internal (specific) energy -> energy (/mass) units (mvv2e)
  double pressure;       // internal pressure -> pressure units (mvv2e nktv2p)
  double energy_in;      // energy (/mass) units -> internal (1 / mvv2e)
  double pressure_in;    // pressure units -> internal (1 / (mvv2e nktv2p))

  void set(double ftm2v, double mvv2e, double nktv2p)
  {
    force = 1.0 / ftm2v;
    energy = mvv2e;
    pressure = mvv2e * nktv2p;
    energy_in = 1.0 / mvv2e;
    pressure_in = 1.0 / pressure;
  }
};

}    // namespace ESPH

#endif
