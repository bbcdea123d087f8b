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

#ifdef PAIR_CLASS
// clang-format off
PairStyle(esph/solid,PairESPHSolid);
// clang-format on
#else

#ifndef LMP_PAIR_ESPH_SOLID_H
#define LMP_PAIR_ESPH_SOLID_H

#include "pair.h"

#include "esph_eos.h"
#include "esph_units.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairESPHSolid : public Pair {
  friend class FixESPHIntegrate;
  friend class ComputeESPHAtom;

 public:
  PairESPHSolid(class LAMMPS *);
  ~PairESPHSolid() override;
  void compute(int, int) override;
  void stagger_rates();
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  void init_list(int, class NeighList *) override;
  double init_one(int, int) override;
  void setup() override;
  int pack_forward_comm(int, int *, double *, int, int *) override;
  void unpack_forward_comm(int, int, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;
  void *extract(const char *, int &) override;
  bool geometry_used(int, double *) const;

  // accumulator slots (real particles | boundary particles), see compute()
  static constexpr int NACC = 41;
  // hoisted per-particle quantities (slots Q_* of pair_esph_solid_slots.h)
  static constexpr int NHQ = 32;
  // more hoisted quantities per atom with the artificial stress (R and its flag)
  static constexpr int NHQ_AST = 7;

 protected:
  void init_recon();
  void init_cone();
  void contact_couple();
  void couple_rate(const double *, const double *, double *) const;
  void body_range(int &, int &, int &);
  void drop_unused_state();
  void drop_if_zero(const char *, const char *);
  // the gradient keyword's kernel-gradient correction: plain, corrected (the velocity
  // gradient), bonet/lok (also the forces and the energy), torquefree (corrected, and the
  // plain forces less their torque)
  enum { CORRECT_PLAIN = 0, CORRECT_RATE = 1, CORRECT_BONETLOK = 2, CORRECT_TORQUEFREE = 3 };
  // the visc/recon keyword's slope limiter of the reconstructed viscosity velocities
  enum { RECON_OFF = 0, RECON_VANLEER = 1, RECON_MINMOD = 2 };

  // global settings
  double h0;                  // initial smoothing length
  double cut_global;          // neighbour cutoff = support * h0 * hmax
  int kernel;                 // ESPH::KernelType
  int dim;                    // kernel dimension (1, 2, 3)
  double alpha, beta, eps;    // Monaghan-Gingold viscosity
  // the CFL estimate shrinks by VISC_CFL_ALPHA / alpha for alpha above it: the viscous limit
  // (cfl 0.3, two blocks at 50 m/s, 1000 steps: alpha 3 +0.28 % energy, 5 +94 %, 10 lost
  // atoms; with the factor +0.06 / +0.07 / +0.10 %, alpha 20 +0.12 %; alpha 1-2 unchanged)
  static constexpr double VISC_CFL_ALPHA = 2.5;
  // a light particle against a heavy one of another body: its interface stiffness is the
  // heavy body's, on its own small mass; the step of the pair is visc_cfl h_l / (CROSS_DT_K
  // c_L,heavy sqrt(m_heavy / m_light) + |v_l|) (measured: cross_dt())
  static constexpr double CROSS_DT_K = 0.6;
  // a boundary particle whose body's real particles lie less than this many spacings behind
  // it (about half a spacing on a surface) was left behind by its body (left_behind())
  static constexpr double SURFACE_LEFT = 0.15;
  int vswitch_flag;      // Morris-Monaghan switch: per-particle alpha_i (d_esph_alpha)
  double vswitch_min;    // its floor alpha_min (the ceiling is alpha)
  double vswitch_l;      // its decay constant l: tau_i = h_i / (l c_i)
  int recon_set;         // visc/recon as set: RECON_OFF, RECON_VANLEER (default), RECON_MINMOD
  int recon_flag;        // the reconstruction in use (init_recon()): recon_set, or off where
                         // no real particle is of a deformable type without a yield stress
  int recon_given;       // visc/recon was given (not the default)
  int recon_warned;      // the warning that visc/recon has no effect was given
  // the type pairs this style was given by init_one() in this run's init (under pair_style
  // hybrid only those mapped to it), flat (ntypes + 1)^2; hybrid_warned: said once
  std::vector<char> one_seen;
  int hybrid_warned;
  void check_hybrid();
  int heat_flag;    // artificial heat transfer (eqs. 8-10)
  double g1, g2;
  int hvar_flag;        // variable smoothing length (eq. 24)
  double hmax;          // allowed growth of h (cutoff factor)
  int contact;          // ESPH::ContactRule
  double gaptol;        // largest open gap a releasing contact pair may push across (of h0)
  double gap_reach2;    // squared reach of a surface-gap partner (GAP_REACH spacings)
  int onset;            // steps over which a newly touching particle's coupling builds up
  static constexpr int ONSET_WARN = 20;           // a longer ramp is warned (settings())
  static constexpr double MG_SLOPE_WARN = 5.0;    // a steeper Hugoniot is warned (coeff())
  int cone_flag;      // contact/normal: 1 cone (common normal of the cones), 0 mean
  int cone_on;        // the cones in use (init_cone()): cone under contact solid without
                      // friction and rigid types, in a scene with boundary particles and
                      // more than one body
  int couple_flag;    // contact/couple: the contact force acts at the contact point
  int gap_plane;      // contact/gap: 1 plane (bounded by the tangent planes), 0 projection
  int couple_on;      // in use (init_style()): given, with contact, in 2d or 3d
  // contact/gap: touch (update_touch()) on the projection, else the projection alone; the
  // touch in use where contact solid meets two bodies or more (init_style())
  int gap_touch, touch_on_run;
  // the bodies that touch another body or have an engaged real particle, and the pairs of
  // bodies that touch (touch_key()), on every rank
  std::vector<int> touch_bodies;
  std::vector<long long> touch_pairs;
  // the real particles take their surface sums (normal, depth, gap, cone) in this
  // computation: under contact/gap touch only while some body touches (surface_sums())
  int surf_on;
  // ... per atom: marked for a look at its cell, and its cell's frame (touch_frames())
  std::vector<double> touch_mark, touch_frame;
  // the spacings of the bodies (body, spacing; sorted), the smallest and largest
  std::vector<std::pair<int, double>> body_spacings;
  double spacing_lo, spacing_hi;
  // contact/couple per atom: 0..2 the couple T, then u = J^-1 T; 3..8 J (Voigt); 9 the
  // power of the forces that carry it; the columns [couple_k0, couple_k1) communicated
  double **cpl;
  std::vector<char> cflag;    // the atoms with a couple (contact_couple())
  int couple_k0, couple_k1;
  int correct_flag;      // gradient keyword: CORRECT_*
  int astress_flag;      // Monaghan (2000) artificial stress against the tensile instability
  double astress_eps;    // its strength epsilon
  int astress_n;         // its exponent n in f_ij^n, f_ij = W(r_ij) / W(dp)
  double astress_dp;     // the initial particle spacing dp
  int xsph_flag;         // XSPH: particles move with the velocity smoothed over their body
  double xsph_eps;       // its strength
  double friction;       // Coulomb friction coefficient between bodies (0: frictionless)
  int simd_set;          // simd keyword: the bulk pairs in vector registers where possible
  int simd_flag;         // this run uses the vector pass (init_style(): simd_set, the CPU
                         // and the physics allow it); it has a full list next to the half one
  int simd_active;       // this force computation uses it (simd_ready())
  class NeighList *listfull;    // full neighbour list of the vector pass, or nullptr
  // the half list's other pairs, for the scalar loop: those of entry ii at
  // simd_j[simd_first[ii] .. simd_first[ii + 1]) (simd_split(), at each new list)
  std::vector<int> simd_first, simd_j;
  // per owned atom: its bulk partners and then its boundary partners, the first entries of
  // its full list's neighbours (simd_split() orders them)
  std::vector<int> simd_nbulk, simd_nbnd;
  // another style shares the full list: the partners are copied into simd_own_j (those of
  // atom i from simd_own_first[i]) instead of ordered in place
  int simd_own;
  std::vector<int> simd_own_first, simd_own_j;
  int simd_resplit;    // init_style() was called: simd_split() must order the lists anew
  int simd_sep;
  int simd_bnd;    // the boundary-real pairs of one body are the vector pass's too

  // per-type material
  ESPH::EOS *eos;
  double *shear;
  double *yield;        // von Mises yield stress, 0 = elastic (no plasticity)
  double *hardening;    // linear isotropic hardening modulus (d yield / d plastic strain)
  int rigid_flag;       // some type is rigid (init_style)
  int *rigid;           // 1: rigid type, the mirror image of its contact partner (pair_coeff rigid)
  int *matset;
  // LAMMPS's force, energy and pressure units <-> the internal mechanical units; the EOS
  // works in the internal ones (its bulk modulus K is converted by pair_coeff)
  ESPH::Units units;

  // per-atom work arrays
  int nmax;
  double **acc;                    // accumulated sums, acc_cols per atom (reverse communicated)
  double **hq;                     // hoisted quantities, hq_cols per atom (forward communicated)
  int acc_cols;                    // columns of acc: A_NN, NACC with the normal cones
  double *drho, *de, *dh, **ds;    // rates for the integrator
  double *dalpha;                  // rate of d_esph_alpha, only with visc/switch
  double **bvel, **bspin;          // boundary particles: interpolated velocity, spin W (xy xz yz)
  double **xsph;                   // XSPH velocity correction eps sum_j ..., only with xsph
  int hq_cols;       // columns of hq: NHQ, + NHQ_AST with the artificial stress, + 9 with
                     // the gradient correction bonet/lok (B_i), + 6 with the normal cones
  int qcol_b;        // first column of B_i = (sigma_i / rho_i) M_i^-T (row major), or -1
  int qcol_n;        // contact/normal cone: first column of the cone C_i (Voigt), or -1
  int qcol_d;        // visc/recon: Q_D, the strain rate D_i (Voigt) it uses, or -1
  int cone_keep;     // contact/normal cone: the same for the cones
  int fric_keep;     // friction: the same for the static part of the friction
  int recon_keep;    // visc/recon: the next computation re-evaluates the last one: keep
                     // the strain rates that one used
  int comm_stage;
  int comm_bnd;    // forward communication carries the contact geometry
  int nforward, nreverse;

  int pred_valid;       // the integrator's predicted end-of-step state is valid (inside a step,
                        // and in the setup of a run that continues the previous one)
  int normals_valid;    // the stored real-particle normals are the ones to use
  double dt_cfl;        // local CFL time step estimate (min h / (c_L + |v|))
  double dt_step;       // time step of the step of this force computation (gap forecast)
  int dt_keep;          // the next computation re-evaluates the last one: keep dt_step
  // fix esph/integrate scheme staggered: what the rate pass must leave as it found it
  std::vector<double> stagger_f, stagger_geom;    // forces; n, gap, gapv, eng, depth, cone,
                                                  // friction
  static constexpr int NGEOM = 25;
  int stagger_flags[2];
  void stagger_save();
  void stagger_restore();
  int ncontact_pairs;    // cross-body pairs interacting in the last compute (local)
  int ntouch_pairs;      // cross-body pairs whose surfaces touch (gap <= tolerance)
  double fcontact;       // sum of transmitted compressive normal pair forces (local)
  // per pair of bodies (I < J) of the last compute: touching pairs, interacting pairs,
  // transmitted compressive normal force (local sums)
  // per pair of bodies and step: touching, interacting pairs, normal force, net force (3)
  static constexpr int NTALLY = 6;
  using BodyTally = std::map<std::pair<int, int>, std::array<double, NTALLY>>;
  BodyTally body_tally;
  bigint nboundary;    // number of boundary (zero-mass) particles, counted at setup
  // fix esph/boundary turn body: the bodies (sorted) whose rigid spin turns their boundary
  // normals, instead of the spin interpolated around each boundary particle
  int turn_body;
  std::vector<int> turn_bodies;
  std::vector<double> turn_ref;    // a point of each, moving with its centre of mass

  // per-atom contact output for compute esph/atom, only while one asks for it (its init()
  // sets the flag, init_style() clears it): interacting cross-body pairs and the sum of
  // their transmitted compressive normal forces (reverse communicated)
  int atom_contact_flag;
  int atom_contact_nmax;
  double **atom_contact;

  class ESPHState *state;
  class FixESPHIntegrate *fix_int;
  int nthreads;    // threads of the per-atom passes and the pair loop (1; /omp: package omp)

  // an interacting cross-body pair whose friction friction_pass() applies: its particles
  // (j's rows written where jown; rig: 0, or 1 / 2 where i / j is rigid), the Coulomb force
  // mu |f_n| (force units), the reduced mass (force units), mm = m_i m_j (force units), the
  // share of the friction work heating the pair's two particles' rows (1/2 each, 1 against
  // a rigid particle), the tally weight, the slip velocity v_t of i against j, the pair
  // vector x_i - x_j and the contact normal
  struct FricPair {
    int i, j, jown, rig;
    double fc, mred, mm, heat, wnet;
    double vt[3], dx[3], nc[3];
  };
  // one pass of the pair loop: the neighbour list entries [iifrom, iito) it takes, the rows
  // it adds to (of acc, atom->f and atom_contact: the arrays themselves, or for a thread of
  // pair esph/solid/omp its private rows of the atoms it does not own) and its tallies
  struct LoopOut {
    int iifrom, iito;
    double **acc, **f, **catom;
    BodyTally *tally;
    int ncontact, ntouch;
    double fcontact;
    // the time step the pairs of real particles of different bodies allow (cross_dt())
    double dtcross = 1.0e300;
    // friction: the pass's interacting cross-body pairs (friction_pass())
    std::vector<FricPair> *fric = nullptr;
  };
  std::vector<FricPair> fric_pairs;
  // friction: per atom (owned and ghost) the static friction the computation uses, and the
  // one it finds (friction_pass())
  double **fric_held, **fric_found;
  int fric_nmax;
  // friction: the force of each recorded pair bounded by the stop force of both its
  // particles' pairs together, then applied (forces, heating, couples, tallies)
  void friction_pass();
  // the step a pair of real particles of different bodies and masses allows
  double cross_dt(int i, int j, double mi, double mj) const;
  // the longitudinal wave speed of the CFL estimate, from the squared bulk sound speed c2
  // and the density (internal units) of a particle of type t
  double long_speed(double c2, double rho, int t) const
  {
    return std::sqrt(c2 + 4.0 * shear[t] * units.pressure_in / (3.0 * rho));
  }
  // the viscous limit of the CFL estimate (alpha is the switch's ceiling with visc/switch)
  double visc_cfl_factor() const { return (alpha > VISC_CFL_ALPHA) ? VISC_CFL_ALPHA / alpha : 1.0; }
  // across bodies of materials of different reference densities the sums weigh the partner
  // by its volume: s_i = rho0_i / rho0_j, s_j = 1 / s_i (pair loop and correction pass
  // alike); false, and s = 1, for one rho0
  bool volume_ratio(int ti, int tj, double &si, double &sj) const
  {
    const double r0i = eos[ti].rho0, r0j = eos[tj].rho0;
    if (r0i == r0j) return false;
    si = r0i / r0j;
    sj = r0j / r0i;
    return true;
  }

  virtual void allocate();
  void set_defaults();
  void grow_work();
  // fix esph/boundary (nullptr without it: the first with several) and the particle spacing
  // of the bodies: the smallest of the fixes (0 without one); each body's own (init_spacings(),
  // spacing_of(): several fixes may give bodies on lattices of different spacings)
  class FixESPHBoundary *boundary_fix() const;
  double boundary_spacing() const { return spacing_lo; }
  void init_spacings();
  double spacing_of(int body) const;
  void hoist();
  void finalize(int eflag);
  void init_turn();
  void turn_with_bodies();
  void compute_normals(int);
  void update_touch(int);
  void touch_frames(double, const double *);
  bool touch_body(int) const;
  int surface_sums() const;
  // bodies a and b touch: their real particles may interact (in the pair loop, per
  // cross-body pair: inline)
  bool touch_pair_on(int a, int b) const
  {
    return std::binary_search(touch_pairs.begin(), touch_pairs.end(), touch_key(a, b));
  }
  // bodies a and b are kept apart by the touch (in use, and they do not touch): their
  // cross-body pairs have no gap, in the pair loop and the correction alike
  bool touch_apart(int a, int b) const { return touch_on_run && !touch_pair_on(a, b); }
  // two ints in one 64-bit key (a in the high half) and back; touch_key() the pair of
  // bodies in either order
  static long long pack_key(int a, int b)
  {
    return (long long) (((unsigned long long) (unsigned) a << 32) | (unsigned) b);
  }
  static void unpack_key(long long k, int &a, int &b)
  {
    a = (int) (unsigned) ((unsigned long long) k >> 32);
    b = (int) (unsigned) ((unsigned long long) k & 0xffffffffULL);
  }
  static long long touch_key(int a, int b) { return (a < b) ? pack_key(a, b) : pack_key(b, a); }
  void store_bnd_gap(int);
  static std::array<double, NTALLY> &tally_bodies(BodyTally &, int, int);
  void combine_acc_row(double *, const double *, int, int, int) const;
  void store_normal(int);
  void left_behind(bigint, tagint, double, int);
  int left_warned;    // left_behind() warned in this run
  void store_cone(int);
  void artificial_stress();
  void atom_contact_clear();
  virtual void pair_pass(int);
  void run_pair_loop(int, LoopOut &);
  // the bulk pairs in vector registers (pair_esph_solid_simd.cpp)
  static bool simd_cpu();
  bool simd_physics() const;
  bool simd_fits();
  bool simd_ready() const;
  void simd_pack();
  void simd_split(int);
  void bulk_pass(LoopOut &);
  template <int BND> void run_hvar(LoopOut &);
  template <int BND, int HVAR> void run_heat(LoopOut &);
  template <int BND, int HVAR, int HEAT> void run_corr(LoopOut &);
  void correction();
  // the correction sums over the neighbor list (/omp: in threads); one range of it into rows
  virtual void correction_pass();
  void run_correction_loop(int, int, double **);
  template <int HVAR> void correction_loop(int, int, double **);
  template <int BND, int HVAR, int HEAT, int CORR> void pair_loop_extra(LoopOut &);
  template <int BND, int HVAR, int HEAT, int CORR, int CONTACT_EXTRA>
  void pair_loop_select(int, LoopOut &);
  template <int BND, int HVAR, int HEAT, int CORR, int EXTRA> void pair_loop(LoopOut &);
};

}    // namespace LAMMPS_NS

#endif
#endif
