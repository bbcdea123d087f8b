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

// Per-atom state of the ESPH package, kept in internal fix property/atom instances
// with the fixed IDs ESPH_STATE, ESPH_STRESS (d2_esph_s) and ESPH_NORMAL (d2_esph_n)
// (a plugin cannot add an atom style):
//   rmass          per-atom mass (added only if the atom style lacks it); 0 = boundary particle
//   d_esph_rho     density
//   d_esph_e       specific internal energy
//   d_esph_h       smoothing length
//   d2_esph_s[6]   deviatoric Cauchy stress, Voigt order xx yy zz xy xz yz
//   i_esph_body    body ID (particles of different bodies meet through the contact rule)
//   d2_esph_n[3]   unit outward surface normal (boundary particles: carried; real: eq. 30)
//   d_esph_depth   depth of a real particle below its body's surface (from boundary particles)
//   d_esph_gap     surface gap to another body (see esph_contact.h): at a boundary particle
//                  from the facing boundary particle of the other body, at a real particle the
//                  mean over its own body's boundary particles; GAP_NONE = no other body near
//   d_esph_gapv    its rate of change
//   d_esph_eng     engagement of a real particle with another body (0..1, see esph_contact.h)
//   d_esph_epsp    equivalent plastic strain (fix ESPH_PLASTIC, only with plasticity)
//   d_esph_alpha   coefficient of the switched artificial viscosity (fix ESPH_VISC, only with
//                  pair_style esph/solid visc/switch; 0 = unset)
//   d2_esph_drec[6] strain rate D = sym(L) of the last force computation (Voigt) for the
//                  reconstructed viscosity (fix ESPH_RECON, only with pair_style esph/solid
//                  visc/recon), d2_esph_drec_used[6] the D that computation used (fix
//                  ESPH_RECON_USED: two fixes, so that data-file lines stay below read_data's
//                  256 characters)
//   d2_esph_cone[6] cone of a real particle's boundary normals found by the last force
//                  computation (Voigt; fix ESPH_CONE, only with pair_style esph/solid
//                  contact/normal cone), d2_esph_cone_used[6] the cone that computation used
//                  (fix ESPH_CONE_USED: two fixes, so that data-file lines stay below
//                  read_data's 256 characters)
//   d2_esph_fric[3] static part of the friction force on a real particle found by the last
//                  force computation (fix ESPH_FRIC, only with pair_style esph/solid friction),
//                  d2_esph_fric_used[3] the one that computation used (fix ESPH_FRIC_USED)
// The fix is created by the first ESPH style that needs it and is never deleted by them,
// so redefining a pair style or fix keeps the state. It is restored by read_restart when
// any ESPH style is defined again afterwards, and written by write_data.

#ifndef LMP_ESPH_STATE_H
#define LMP_ESPH_STATE_H

namespace LAMMPS_NS {
class LAMMPS;

class ESPHState {
 public:
  static constexpr const char *FIX_ID = "ESPH_STATE";
  static constexpr const char *FIX_ID_STRESS = "ESPH_STRESS";
  static constexpr const char *FIX_ID_NORMAL = "ESPH_NORMAL";
  static constexpr const char *FIX_ID_PLASTIC = "ESPH_PLASTIC";
  static constexpr const char *FIX_ID_VISC = "ESPH_VISC";
  static constexpr const char *FIX_ID_RECON = "ESPH_RECON";
  static constexpr const char *FIX_ID_RECON_USED = "ESPH_RECON_USED";
  static constexpr const char *FIX_ID_CONE = "ESPH_CONE";
  static constexpr const char *FIX_ID_CONE_USED = "ESPH_CONE_USED";
  static constexpr const char *FIX_ID_FRIC = "ESPH_FRIC";
  static constexpr const char *FIX_ID_FRIC_USED = "ESPH_FRIC_USED";

  // create the state fix if it does not exist yet
  static void ensure(LAMMPS *lmp);
  // create the plastic-strain fix (d_esph_epsp) if it does not exist yet: only scenes
  // with plasticity carry it
  static void ensure_plastic(LAMMPS *lmp);
  // create the viscosity-switch fix (d_esph_alpha) if it does not exist yet: only scenes
  // with visc/switch carry it
  static void ensure_visc(LAMMPS *lmp);
  // create the reconstruction fix (d2_esph_drec) if it does not exist yet: only scenes
  // with visc/recon carry it
  static void ensure_recon(LAMMPS *lmp);
  // deletes internal fix fixid where it exists and holds ESPH's per-atom property name (a
  // user's fix of that ID is left alone)
  static void drop_optional(LAMMPS *lmp, const char *fixid, const char *name);
  // deletes ESPH_RECON and ESPH_RECON_USED where they exist and are ESPH's
  static void drop_recon(LAMMPS *lmp);
  // create the normal-cone fix (d2_esph_cone) if it does not exist yet: only scenes with
  // pair_style esph/solid contact/normal cone carry it
  static void ensure_cone(LAMMPS *lmp);
  // create the friction memory fix (d2_esph_fric) if it does not exist yet: only scenes with
  // pair_style esph/solid friction carry it
  static void ensure_fric(LAMMPS *lmp);

  // per-atom array pointers, to be re-fetched every step (they move when atoms grow)
  explicit ESPHState(LAMMPS *lmp);
  void fetch();
  // a new atom (create_atoms, read_data add, fix deposit, ...): the state of a fresh box
  // (fix property/atom zeroes only newly grown memory; a slot reused after a sort, an
  // exchange or a deletion keeps the values of the atom that held it). The mass too where
  // ESPH added it (the atom style's own rmass is set by the style)
  void clear_atom(int i);

  double *rmass, *rho, *e, *h, **s, **n, *depth, *gap, *gapv, *eng;
  double *epsp;      // equivalent plastic strain, nullptr without plasticity
  double *alpha;     // switched viscosity coefficient, nullptr without visc/switch
  double **drec;     // strain rates of visc/recon found by the last computation (6 per atom),
                     // nullptr without it
  double **drecu;    // and the ones the last computation used (6 per atom)
  double **cone;     // normal cones of contact/normal cone found (6 per atom), nullptr without
  double **coneu;    // and the ones the last computation used (6 per atom)
  double **fric;     // static part of the friction force on a real particle found (3 per atom,
                     // force units), nullptr without friction
  double **fricu;    // and the one the last computation used (3 per atom)
  int *body;

 private:
  LAMMPS *lmp;
  int irho, ie, ih, is, in, idepth, ibody, igap, igapv, ieng, iepsp, ialpha, idrec, idrecu, icone,
      iconeu, ifric, ifricu;
};

}    // namespace LAMMPS_NS

#endif
