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

// Equations of state for the ESPH package (seed paper section 2.4).
// Pressure is positive in compression; e is the specific internal energy.
// Pure math, no LAMMPS dependency: unit-tested alone.

#ifndef LMP_ESPH_EOS_H
#define LMP_ESPH_EOS_H

#include <cmath>

namespace ESPH {

enum EOSType { EOS_LINEAR = 0, EOS_MIE_GRUNEISEN = 1 };

struct EOS {
  int type;
  double rho0;      // reference density
  double K;         // linear: bulk modulus
  double c0;        // Mie-Grueneisen: bulk sound speed
  double s;         // Mie-Grueneisen: slope of U_s = c0 + s u_p
  double gamma0;    // Mie-Grueneisen: Grueneisen parameter

  /* pressure P(rho, e) and the squared bulk sound speed c2 = dP/drho|_s
     = dP/drho|_e + P/rho^2 dP/de|_rho (eq. 23) */

  void compute(double rho, double e, double &P, double &c2) const
  {
    if (type == EOS_LINEAR) {
      // P = K (rho/rho0 - 1), c^2 = K / rho0
      P = K * (rho / rho0 - 1.0);
      c2 = K / rho0;
      return;
    }

    // Mie-Grueneisen with a linear U_s-u_p Hugoniot (eqs. 19-22),
    // eta = 1 - rho0/rho. Compression: P_H = rho0 c0^2 eta / (1 - s eta)^2.
    // Tension (eta < 0): the linear branch P_H = rho0 c0^2 eta.
    // Hugoniot energy from Rankine-Hugoniot: E_H = P_H eta / (2 rho0)
    // (the seed paper's eq. 21 prints eta* = rho/rho0 - 1 in place of eta).
    // Gamma rho = Gamma0 rho0, so P = P_H + Gamma0 rho0 (e - E_H).
    const double eta = 1.0 - rho0 / rho;
    const double k0 = rho0 * c0 * c0;
    double PH, dPH;    // P_H and dP_H/deta
    if (eta > 0.0) {
      const double d = 1.0 - s * eta;
      PH = k0 * eta / (d * d);
      dPH = k0 * (1.0 + s * eta) / (d * d * d);
    } else {
      PH = k0 * eta;
      dPH = k0;
    }
    const double g = gamma0 * rho0;
    const double EH = 0.5 * PH * eta / rho0;
    const double dEH = 0.5 * (PH + eta * dPH) / rho0;
    P = PH + g * (e - EH);
    const double detadrho = rho0 / (rho * rho);
    c2 = detadrho * (dPH - g * dEH) + P / (rho * rho) * g;
  }
};

}    // namespace ESPH

#endif
