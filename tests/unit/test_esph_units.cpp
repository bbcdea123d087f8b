// Unit tests of the LAMMPS-independent pieces of the ESPH package:
// kernel, equation of state, Jaumann stress rate, contact rule, unit conversion.

#include "esph_bodies.h"
#include "esph_contact.h"
#include "esph_eos.h"
#include "esph_kernel.h"
#include "esph_strength.h"
#include "esph_units.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>

using namespace ESPH;

static constexpr double PI = 3.14159265358979323846;

// integral of W over its support by a fine midpoint rule in radial coordinates
static double kernel_integral(int k, int dim, double h)
{
  const double norm = kernel_norm(k, dim, h);
  const int n = 200000;
  const double rmax = KERNEL_SUPPORT * h, dr = rmax / n;
  double sum = 0.0;
  for (int i = 0; i < n; i++) {
    const double r = (i + 0.5) * dr;
    double w, dw;
    kernel_eval(k, dim, norm, 1.0 / h, r, w, dw);
    const double shell = (dim == 1) ? 2.0 : (dim == 2) ? 2.0 * PI * r : 4.0 * PI * r * r;
    sum += w * shell * dr;
  }
  return sum;
}

// Normalisation: the midpoint rule with 2e5 intervals is accurate to ~1e-10,
// so 1e-8 tests the constants sigma_D exactly enough to catch any slip.
TEST(Kernel, Normalisation)
{
  for (int k : {CUBIC, WENDLAND})
    for (int dim = 1; dim <= 3; dim++)
      for (double h : {1.0e-4, 0.7, 3.0}) EXPECT_NEAR(kernel_integral(k, dim, h), 1.0, 1.0e-8);
}

// Gradient against a central finite difference of W (step 1e-6 h: error ~1e-10 relative).
TEST(Kernel, GradientMatchesFiniteDifference)
{
  const double h = 0.3;
  for (int k : {CUBIC, WENDLAND})
    for (int dim = 1; dim <= 3; dim++) {
      const double norm = kernel_norm(k, dim, h);
      for (double q = 0.05; q < 2.0; q += 0.0731) {
        const double r = q * h, dr = 1.0e-6 * h;
        double w, dw, wp, wm, tmp;
        kernel_eval(k, dim, norm, 1.0 / h, r, w, dw);
        kernel_eval(k, dim, norm, 1.0 / h, r + dr, wp, tmp);
        kernel_eval(k, dim, norm, 1.0 / h, r - dr, wm, tmp);
        const double fd = (wp - wm) / (2.0 * dr);
        EXPECT_NEAR(dw * r, fd, 1.0e-6 * fabs(norm / h))
            << "k=" << k << " dim=" << dim << " q=" << q;
      }
    }
}

TEST(Kernel, CubicAnalyticValues)
{
  // cubic B-spline, 3D, h = 1: W(0) = 1/pi, W(1) = 1/(4 pi), W(2) = 0
  double w, dw;
  kernel_eval(CUBIC, 3, kernel_norm(CUBIC, 3, 1.0), 1.0, 0.0, w, dw);
  EXPECT_DOUBLE_EQ(w, 1.0 / PI);
  EXPECT_DOUBLE_EQ(dw, 0.0);
  kernel_eval(CUBIC, 3, kernel_norm(CUBIC, 3, 1.0), 1.0, 1.0, w, dw);
  EXPECT_DOUBLE_EQ(w, 0.25 / PI);
  EXPECT_DOUBLE_EQ(dw, -0.75 / PI);    // dW/dq = -3q + 9/4 q^2 = -0.75 at q = 1
  EXPECT_FALSE(kernel_eval(CUBIC, 3, kernel_norm(CUBIC, 3, 1.0), 1.0, 2.0, w, dw));
  EXPECT_EQ(w, 0.0);
}

// Partition of unity on a lattice: sum_j V W_ij over a cubic lattice with h = 1.3 dx
// (a common choice) is 1 within the discretisation error of the kernel sum; 1e-2
// covers the measured 2.7e-3 (3D) with margin, and catches a wrong sigma_D (factor > 1.2).
TEST(Kernel, PartitionOfUnityOnLattice)
{
  const double dx = 1.0, h = 1.3 * dx;
  for (int dim = 1; dim <= 3; dim++) {
    const double norm = kernel_norm(CUBIC, dim, h);
    double sum = 0.0, gsum = 0.0;
    const int n = 4;
    for (int a = -n; a <= n; a++)
      for (int b = (dim > 1 ? -n : 0); b <= (dim > 1 ? n : 0); b++)
        for (int c = (dim > 2 ? -n : 0); c <= (dim > 2 ? n : 0); c++) {
          const double x[3] = {a * dx + 0.1, b * dx, c * dx};
          const double r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
          double w, dw;
          kernel_eval(CUBIC, dim, norm, 1.0 / h, r, w, dw);
          const double vol = pow(dx, dim);
          sum += vol * w;
          gsum += vol * dw * x[0];
        }
    EXPECT_NEAR(sum, 1.0, 1.0e-2) << "dim " << dim;
    EXPECT_NEAR(gsum, 0.0, 2.0e-2) << "dim " << dim;    // gradient of a constant
  }
}

// Iron, the seed paper's Table 1. Hand computation:
// eta = 1 - rho0/rho; P_H = rho0 c0^2 eta/(1 - s eta)^2; E_H = P_H eta/(2 rho0);
// P = P_H + Gamma0 rho0 (e - E_H). At rho = 7888.4 (eta = 4.8692e-3), e = 0:
// rho0 c0^2 = 7850*3574^2 = 1.002717e11 Pa; P_H = 1.002717e11*4.8680e-3/(1-1.92*4.8680e-3)^2
static EOS iron()
{
  return EOS{EOS_MIE_GRUNEISEN, 7850.0, 0.0, 3574.0, 1.92, 1.69};
}

TEST(EOS, MieGruneisenIronHandValues)
{
  const EOS eq = iron();
  double P, c2;
  // reference state
  eq.compute(7850.0, 0.0, P, c2);
  EXPECT_DOUBLE_EQ(P, 0.0);
  EXPECT_NEAR(sqrt(c2), 3574.0, 1.0e-9);

  // compression with eta = 4.87e-3 (rho = 7888.416): hand values
  // P_H = 7850*3574^2*4.87e-3/(1-1.92*4.87e-3)^2 = 4.97585e8 Pa (REFERENCES.md 0: 497.6 MPa)
  // E_H = P_H eta/(2 rho0) = 154.35 J/kg, P = P_H - 1.69*7850*E_H = 4.95537e8 Pa
  const double rho = 7850.0 / (1.0 - 4.87e-3);
  eq.compute(rho, 0.0, P, c2);
  EXPECT_NEAR(P, 4.95537e8, 0.00001e8);
  double PH, tmp;
  EOS lin = eq;
  lin.gamma0 = 0.0;
  lin.compute(rho, 0.0, PH, tmp);
  EXPECT_NEAR(PH, 4.97585e8, 0.00001e8);

  // energy term: + Gamma0 rho0 e
  double P2;
  eq.compute(rho, 1000.0, P2, c2);
  EXPECT_NEAR(P2 - P, 1.69 * 7850.0 * 1000.0, 1.0e-6);

  // tension: linear branch P = rho0 c0^2 eta
  eq.compute(7800.0, 0.0, P, c2);
  const double et = 1.0 - 7850.0 / 7800.0;
  const double k0 = 7850.0 * 3574.0 * 3574.0;
  EXPECT_NEAR(P, k0 * et - 1.69 * 7850.0 * 0.5 * k0 * et * et / 7850.0, 1.0e-6 * fabs(P));
}

// Sound speed c^2 = dP/drho|_s checked against a finite difference along an isentrope
// de = P/rho^2 drho (central difference with drho = 1e-4: error ~1e-8 relative).
TEST(EOS, SoundSpeedIsIsentropicDerivative)
{
  const EOS eq = iron();
  for (double rho : {7700.0, 7850.0, 8000.0, 8500.0}) {
    const double e = 2000.0, d = 1.0e-4;
    double P, c2, Pp, Pm, tmp;
    eq.compute(rho, e, P, c2);
    eq.compute(rho + d, e + P / (rho * rho) * d, Pp, tmp);
    eq.compute(rho - d, e - P / (rho * rho) * d, Pm, tmp);
    EXPECT_NEAR(c2, (Pp - Pm) / (2.0 * d), 1.0e-6 * c2) << "rho " << rho;
  }
}

TEST(EOS, Linear)
{
  const EOS eq{EOS_LINEAR, 7850.0, 1.0e11, 0.0, 0.0, 0.0};
  double P, c2;
  eq.compute(7850.0 * 1.001, 123.0, P, c2);
  EXPECT_NEAR(P, 1.0e8, 1.0e-3);
  EXPECT_DOUBLE_EQ(c2, 1.0e11 / 7850.0);
}

// Objectivity of the Jaumann rate (REFERENCES.md 4A): rigid rotation about z,
// L = [[0,-w,0],[w,0,0],[0,0,0]], S0 = diag(tau,-tau,0). Exact: S_xy = tau sin 2wt.
// Integrated with RK4 at 2000 steps per quarter turn: error < 1e-10 tau.
TEST(Strength, JaumannRigidRotation)
{
  const double w = 1.0e4, tau = 1.0e8, G = 8.0e10;
  Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
  L(0, 1) = -w;
  L(1, 0) = w;
  double s[6] = {tau, -tau, 0.0, 0.0, 0.0, 0.0};
  const int nsteps = 2000;
  const double T = 0.5 * PI / w, dt = T / nsteps;
  auto rate = [&](const double *y, double *k) {
    jaumann_rate(L, y, G, k);
  };
  for (int n = 0; n < nsteps; n++) {
    double k1[6], k2[6], k3[6], k4[6], y[6];
    rate(s, k1);
    for (int c = 0; c < 6; c++) y[c] = s[c] + 0.5 * dt * k1[c];
    rate(y, k2);
    for (int c = 0; c < 6; c++) y[c] = s[c] + 0.5 * dt * k2[c];
    rate(y, k3);
    for (int c = 0; c < 6; c++) y[c] = s[c] + dt * k3[c];
    rate(y, k4);
    for (int c = 0; c < 6; c++) s[c] += dt / 6.0 * (k1[c] + 2 * k2[c] + 2 * k3[c] + k4[c]);
    if (n + 1 == nsteps / 2) {
      // 45 degrees: S_xy = +tau (a spin-sign error gives -tau)
      EXPECT_NEAR(s[3], tau, 1.0e-10 * tau);
      EXPECT_NEAR(s[0], 0.0, 1.0e-10 * tau);
    }
  }
  EXPECT_NEAR(s[0], -tau, 1.0e-10 * tau);
  EXPECT_NEAR(s[1], tau, 1.0e-10 * tau);
  EXPECT_NEAR(s[3], 0.0, 1.0e-10 * tau);
  EXPECT_NEAR(s[2], 0.0, 1.0e-10 * tau);
}

// Hooke part: uniaxial strain rate D = diag(d,0,0) gives dS = 2G (2/3 d, -1/3 d, -1/3 d)
TEST(Strength, HookeDeviator)
{
  Eigen::Matrix3d L = Eigen::Matrix3d::Zero();
  L(0, 0) = 3.0;
  double s[6] = {0, 0, 0, 0, 0, 0}, ds[6];
  jaumann_rate(L, s, 2.0, ds);
  EXPECT_DOUBLE_EQ(ds[0], 8.0);
  EXPECT_DOUBLE_EQ(ds[1], -4.0);
  EXPECT_DOUBLE_EQ(ds[2], -4.0);
  EXPECT_DOUBLE_EQ(ds[3], 0.0);
}

// The written-out rate against its definition dS/dt = 2 G (D - tr(D)/3 I) + W S - S W in
// matrix form, for general (non-symmetric) L and S: every component and sign, to round-off
// (1e-14 of the largest term)
TEST(Strength, JaumannMatchesMatrixForm)
{
  const double Ls[9] = {0.3, -1.7, 2.2, 0.9, -0.4, 1.3, -2.6, 0.8, 1.1};
  const double s[6] = {1.5, -0.7, 2.9, -1.2, 0.6, 2.4};
  const double G = 3.7;
  Eigen::Matrix3d L;
  for (int r = 0; r < 3; r++)
    for (int c = 0; c < 3; c++) L(r, c) = Ls[3 * r + c];
  const Eigen::Matrix3d D = 0.5 * (L + L.transpose()), W = 0.5 * (L - L.transpose());
  const Eigen::Matrix3d S = voigt_to_matrix(s);
  const Eigen::Matrix3d R =
      2.0 * G * (D - D.trace() / 3.0 * Eigen::Matrix3d::Identity()) + W * S - S * W;
  double ds[6];
  jaumann_rate(L, s, G, ds);
  const double expect[6] = {R(0, 0), R(1, 1), R(2, 2), R(0, 1), R(0, 2), R(1, 2)};
  for (int k = 0; k < 6; k++) EXPECT_NEAR(ds[k], expect[k], 1.0e-14 * 40.0) << "component " << k;
  // the matrix form is symmetric: its lower triangle is the stored upper one
  EXPECT_NEAR(R(1, 0), R(0, 1), 1.0e-13);
  EXPECT_NEAR(R(2, 1), R(1, 2), 1.0e-13);
}

// Contact rule: the common normal, the surface gap from boundary particles, the weight.
TEST(Contact, NormalGapWeight)
{
  // i in the left body (normal +x), j in the right body (normal -x), one spacing apart
  const double ni[3] = {1, 0, 0}, nj[3] = {-1, 0, 0}, xij[3] = {-1.0, 0.3, 0};
  double nc[3];
  contact_normal(ni, nj, xij, nc);
  EXPECT_DOUBLE_EQ(nc[0], 1.0);
  EXPECT_DOUBLE_EQ(nc[1], 0.0);

  // boundary particles a (left body, normal +x) and b (right body) 0.2 apart along x and
  // 0.7 across: the gap is the distance of the faces, whatever the lateral offset
  const double vab[3] = {-3.0, 1.0, 0.0};    // b approaches at 3, slides at 1
  double c, g, gd;
  const double xab[3] = {0.2, 0.7, 0.0};
  ASSERT_TRUE(contact_bnd_gap(ni, nj, xab, vab, 0.0, 0.0, 0, c, g, gd));
  EXPECT_DOUBLE_EQ(g, 0.2);
  EXPECT_DOUBLE_EQ(gd, -3.0);
  EXPECT_NEAR(c, 1.0 + 0.2 / sqrt(0.53), 1e-15);
  // seen from b: the same gap and rate
  const double xba[3] = {-0.2, -0.7, 0.0}, vba[3] = {3.0, -1.0, 0.0};
  double c2, g2, gd2;
  ASSERT_TRUE(contact_bnd_gap(nj, ni, xba, vba, 0.0, 0.0, 0, c2, g2, gd2));
  EXPECT_DOUBLE_EQ(g2, g);
  EXPECT_DOUBLE_EQ(gd2, gd);
  EXPECT_DOUBLE_EQ(c2, c);
  // a face rotated by 30 degrees: still the face distance
  const double t = M_PI / 6, ra[3] = {cos(t), sin(t), 0}, rb[3] = {-cos(t), -sin(t), 0};
  const double xr[3] = {0.2 * cos(t) - 0.7 * sin(t), 0.2 * sin(t) + 0.7 * cos(t), 0.0};
  ASSERT_TRUE(contact_bnd_gap(ra, rb, xr, vab, 0.0, 0.0, 0, c, g, gd));
  EXPECT_NEAR(g, 0.2, 1e-15);
  // overlap: negative gap
  const double xo[3] = {-0.1, 0.0, 0.0};
  ASSERT_TRUE(contact_bnd_gap(ni, nj, xo, vab, 0.0, 0.0, 0, c, g, gd));
  EXPECT_DOUBLE_EQ(g, -0.1);
  EXPECT_DOUBLE_EQ(c, 2.0);
  // coincident partners score 2 and so do partners a round-off distance apart (a rotated
  // scene): the score is continuous at r = 0
  const double x0[3] = {0.0, 0.0, 0.0}, xeps[3] = {1e-19, -2e-19, 3e-20};
  ASSERT_TRUE(contact_bnd_gap(ni, nj, x0, vab, 1e-6, 0.0, 0, c, g, gd));
  EXPECT_DOUBLE_EQ(c, 2.0);
  ASSERT_TRUE(contact_bnd_gap(ni, nj, xeps, vab, 1e-6, 0.0, 0, c2, g2, gd2));
  EXPECT_NEAR(c2, 2.0, 1e-12);
  // side by side surfaces (normals within 60 degrees) do not face each other
  const double ns[3] = {cos(0.9), sin(0.9), 0.0};
  EXPECT_FALSE(contact_bnd_gap(ni, ns, xab, vab, 0.0, 0.0, 0, c, g, gd));
  // the reach (here 2, reach2 = 4): a partner within it counts as without a limit, one
  // beyond it not at all; 0: no limit
  double c3, g3, gd3;
  ASSERT_TRUE(contact_bnd_gap(ni, nj, xab, vab, 0.0, 4.0, 0, c3, g3, gd3));
  EXPECT_NEAR(c3, 1.0 + 0.2 / sqrt(0.53), 1e-15);
  EXPECT_DOUBLE_EQ(g3, 0.2);
  const double x21[3] = {0.2, 2.1, 0.0};
  EXPECT_FALSE(contact_bnd_gap(ni, nj, x21, vab, 0.0, 4.0, 0, c3, g3, gd3));
  EXPECT_TRUE(contact_bnd_gap(ni, nj, x21, vab, 0.0, 0.0, 0, c3, g3, gd3));
  // why: an edge (normal at 45 degrees) whose partner on a face lies 0.32 below and 2.5
  // sideways (the face ends before it) has a negative projection along the tilted normal
  // difference (-0.66); the face's tangent plane sees the edge 0.32 in front: open, and
  // beyond the reach not a candidate at all
  const double ne[3] = {0.0, M_SQRT1_2, M_SQRT1_2}, nf[3] = {0.0, -1.0, 0.0};
  const double xef[3] = {0.0, 0.32, -2.5};
  ASSERT_TRUE(contact_bnd_gap(ne, nf, xef, vab, 0.0, 0.0, 0, c3, g3, gd3));
  EXPECT_LT(g3, -0.6);
  EXPECT_FALSE(contact_bnd_gap(ne, nf, xef, vab, 0.0, 4.0, 0, c3, g3, gd3));
  // contact/gap plane
  ASSERT_TRUE(contact_bnd_gap(ne, nf, xef, vab, 0.0, 0.0, 1, c3, g3, gd3));
  EXPECT_NEAR(g3, 0.32, 1e-15);
  EXPECT_DOUBLE_EQ(gd3, vab[1]);    // the rate of the face's plane distance: -(v_b - v_a).n_f
  // two faces: contact/gap plane gives the projection's gap, rate and score (open, closed,
  // rotated, sideways)
  for (const double *xx : {xab, xo, xr, x21}) {
    const double *na = (xx == xr) ? ra : ni, *nb = (xx == xr) ? rb : nj;
    double cp, gp, gdp, cq, gq, gdq;
    ASSERT_TRUE(contact_bnd_gap(na, nb, xx, vab, 0.0, 0.0, 0, cp, gp, gdp));
    ASSERT_TRUE(contact_bnd_gap(na, nb, xx, vab, 0.0, 0.0, 1, cq, gq, gdq));
    EXPECT_NEAR(gq, gp, 1e-15);
    EXPECT_NEAR(gdq, gdp, 1e-14);
    EXPECT_DOUBLE_EQ(cq, cp);
  }
  // a cube's corner 0.32 above a face, its partner one spacing inwards in x and z: the
  // projection says -0.365, the face's tangent plane 0.32 (in.gap_edge)
  const double s3 = 1.0 / sqrt(3.0);
  const double nface[3] = {0.0, 1.0, 0.0}, ncorner[3] = {-s3, -s3, -s3};
  const double xcf[3] = {-1.0, 0.32, -1.0};
  ASSERT_TRUE(contact_bnd_gap(nface, ncorner, xcf, vab, 0.0, 0.0, 0, c3, g3, gd3));
  EXPECT_LT(g3, -0.36);
  ASSERT_TRUE(contact_bnd_gap(nface, ncorner, xcf, vab, 0.0, 0.0, 1, c3, g3, gd3));
  EXPECT_NEAR(g3, 0.32, 1e-15);
  // the score is the projection's, 1 + |g| / r
  const double gproj = (0.32 * (1.0 + s3) - 2.0 * s3) / sqrt(2.0 + 2.0 * s3);
  EXPECT_LT(gproj, -0.36);
  EXPECT_NEAR(c3, 1.0 + fabs(gproj) / sqrt(2.1024), 1e-12);
  // the same corner just in contact (its plane distance -0.01): the projection, more closed,
  // gives way to the plane distance; a closed pair stays closed
  const double xcc[3] = {-1.0, -0.01, -1.0};
  ASSERT_TRUE(contact_bnd_gap(nface, ncorner, xcc, vab, 0.0, 0.0, 1, c3, g3, gd3));
  EXPECT_NEAR(g3, -0.01, 1e-15);
  // where the projection is closed and a plane open, min(D, -g): continuous at g = 0
  const double ncs[3] = {-M_SQRT1_2, -M_SQRT1_2, 0.0};
  double gprev = -1.0;
  for (int k = -20; k <= 20; k++) {
    const double xk[3] = {-0.5 + 0.01 * k, 0.3, 0.0};
    ASSERT_TRUE(contact_bnd_gap(nface, ncs, xk, vab, 0.0, 0.0, 1, c3, g3, gd3));
    if (k > -20) EXPECT_LT(fabs(g3 - gprev), 0.02);
    gprev = g3;
  }

  // the candidates' mean weighted by exp(KAPPA (c - c_max)): a tie shares, a clearly worse
  // candidate (0.4 below) does not count; any order, and split into partial states merged
  // later (MPI), gives the same result to round-off
  const double cand[3][3] = {{1.5, 0.3, 1.0}, {1.9, 0.4, 2.0}, {1.9, 0.2, 3.0}};
  double best1[GAP_SLOTS] = {0, 0, 0, 0}, best2[GAP_SLOTS] = {0, 0, 0, 0};
  double part_a[GAP_SLOTS] = {0, 0, 0, 0}, part_b[GAP_SLOTS] = {0, 0, 0, 0};
  for (int k = 0; k < 3; k++) contact_bnd_keep(best1, cand[k][0], cand[k][1], cand[k][2]);
  for (int k = 2; k >= 0; k--) contact_bnd_keep(best2, cand[k][0], cand[k][1], cand[k][2]);
  contact_bnd_keep(part_a, cand[1][0], cand[1][1], cand[1][2]);
  contact_bnd_keep(part_b, cand[0][0], cand[0][1], cand[0][2]);
  contact_bnd_keep(part_b, cand[2][0], cand[2][1], cand[2][2]);
  contact_bnd_merge(part_a, part_b);
  const double w0 = exp(GAP_KAPPA * (1.5 - 1.9));
  const double gref = (0.4 + 0.2 + w0 * 0.3) / (2.0 + w0);
  const double dref = (2.0 + 3.0 + w0 * 1.0) / (2.0 + w0);
  for (const double *b : {best1, best2, part_a}) {
    double gg, dd;
    ASSERT_TRUE(contact_bnd_result(b, gg, dd));
    EXPECT_NEAR(gg, gref, 1e-15);
    EXPECT_NEAR(dd, dref, 1e-15);
    EXPECT_NEAR(gg, 0.3, 1e-15);
  }
  // a near tie moves the gap continuously: a score change of 1e-12 changes it by ~1e-11
  double tie1[GAP_SLOTS] = {0, 0, 0, 0}, tie2[GAP_SLOTS] = {0, 0, 0, 0};
  contact_bnd_keep(tie1, 1.8, 0.0, 0.0);
  contact_bnd_keep(tie1, 1.8, -0.5, 0.0);
  contact_bnd_keep(tie2, 1.8 + 1e-12, 0.0, 0.0);
  contact_bnd_keep(tie2, 1.8, -0.5, 0.0);
  double g1, gt2, d1;
  ASSERT_TRUE(contact_bnd_result(tie1, g1, d1));
  ASSERT_TRUE(contact_bnd_result(tie2, gt2, d1));
  EXPECT_NEAR(g1, -0.25, 1e-15);
  EXPECT_LT(fabs(g1 - gt2), 1e-10);
  // no candidate
  const double none[GAP_SLOTS] = {0, 0, 0, 0};
  EXPECT_FALSE(contact_bnd_result(none, g1, d1));

  // the pair's gap: either particle's closed gap closes it
  EXPECT_EQ(contact_gap_pair(0.3, -0.1), -0.1);
  EXPECT_EQ(contact_gap_pair(GAP_NONE, 0.2), 0.2);
  EXPECT_EQ(contact_gap_pair(GAP_NONE, GAP_NONE), GAP_NONE);
  // engagement: grows by 1/onset per step while the gap is closed, falls as fast when open
  double eng = 0.0;
  for (int k = 0; k < 4; k++) eng = contact_engage(eng, -1e-3, 10);
  EXPECT_NEAR(eng, 0.4, 1e-15);
  for (int k = 0; k < 20; k++) eng = contact_engage(eng, -1e-3, 10);
  EXPECT_EQ(eng, 1.0);
  eng = contact_engage(eng, 1e-3, 10);
  EXPECT_NEAR(eng, 0.9, 1e-15);
  for (int k = 0; k < 20; k++) eng = contact_engage(eng, 1e-3, 10);
  EXPECT_EQ(eng, 0.0);
  EXPECT_EQ(contact_engage(0.0, -1e-9, 0), 1.0);
  EXPECT_EQ(contact_engage(1.0, 0.0, 0), 0.0);
  // pair weight: the smoothed engagement of the more engaged one, 0 beyond the cap
  EXPECT_EQ(contact_pair_weight(0.06, 0.05, 1.0, 1.0), 0.0);
  EXPECT_EQ(contact_pair_weight(0.01, 0.05, 1.0, 0.0), 1.0);
  EXPECT_EQ(contact_pair_weight(-0.1, 0.05, 0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(contact_pair_weight(-0.1, 0.05, 0.5, 0.2), 0.5);
  // paper rule: approaching along nc
  EXPECT_TRUE(contact_approach(+1.0, -1.0));
  EXPECT_FALSE(contact_approach(-1.0, -1.0));
  // a product of round-off size does not count (the tolerance)
  EXPECT_FALSE(contact_approach(1.0e-20, -1.0, 1.0e-12));
  EXPECT_TRUE(contact_approach(1.0e-6, -1.0, 1.0e-12));
  // normals that cancel: fall back on the separation direction
  const double n0[3] = {0, 0, 0};
  contact_normal(n0, n0, xij, nc);
  EXPECT_NEAR(nc[0], 1.0 / sqrt(1.09), 1e-15);
}

// second moment (Voigt) of a set of unit normals with weights
static void second_moment(const double (*n)[3], const double *w, int k, double *s)
{
  double sw = 0.0;
  for (int a = 0; a < 6; a++) s[a] = 0.0;
  for (int q = 0; q < k; q++) {
    const double *v = n[q];
    s[0] += w[q] * v[0] * v[0];
    s[1] += w[q] * v[1] * v[1];
    s[2] += w[q] * v[2] * v[2];
    s[3] += w[q] * v[0] * v[1];
    s[4] += w[q] * v[0] * v[2];
    s[5] += w[q] * v[1] * v[2];
    sw += w[q];
  }
  for (int a = 0; a < 6; a++) s[a] /= sw;
}

// contact/normal cone: the cone of a face is its normal, of an edge the plane of its faces'
// normals; an edge against a face gives the face's normal exactly (the mean normal is
// tilted towards the edge), in any orientation; two faces or two alike curved surfaces
// give the mean normal's direction; crossing edges the normal of both edges
// A boundary normal turned by its spin (eq. 17): rotate_by_spin() against Rodrigues'
// formula with the unit axis and sin/cos, from the tiny angles of a step (its series
// branch, theta < 0.01) to a large one (sin/cos branch). Both are exact rotations, so they
// agree to round-off (1e-15 on a unit vector) and keep the length; no spin, no change.
TEST(Contact, RotateBySpin)
{
  const double n0[3] = {0.48, -0.6, 0.64};          // unit length
  const double spin[3] = {2.0e4, -1.3e4, 0.7e4};    // W_xy, W_xz, W_yz
  const double om[3] = {-spin[2], spin[1], -spin[0]};
  const double wmag = sqrt(om[0] * om[0] + om[1] * om[1] + om[2] * om[2]);
  for (double theta : {1.0e-9, 1.0e-5, 3.0e-3, 0.00999, 0.01001, 0.3, 2.5}) {
    const double dt = theta / wmag;
    double n[3] = {n0[0], n0[1], n0[2]};
    rotate_by_spin(n, spin, dt);
    const double k[3] = {om[0] / wmag, om[1] / wmag, om[2] / wmag};
    const double kn = k[0] * n0[0] + k[1] * n0[1] + k[2] * n0[2];
    const double kxn[3] = {k[1] * n0[2] - k[2] * n0[1], k[2] * n0[0] - k[0] * n0[2],
                           k[0] * n0[1] - k[1] * n0[0]};
    for (int d = 0; d < 3; d++) {
      const double ref = n0[d] * cos(theta) + kxn[d] * sin(theta) + k[d] * kn * (1.0 - cos(theta));
      EXPECT_NEAR(n[d], ref, 1.0e-15) << "theta " << theta << " component " << d;
    }
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1.0e-15) << "theta " << theta;
  }
  double n[3] = {n0[0], n0[1], n0[2]};
  const double none[3] = {0.0, 0.0, 0.0};
  rotate_by_spin(n, none, 1.0e-8);
  for (int d = 0; d < 3; d++) EXPECT_EQ(n[d], n0[d]);
}

// contact/gap touch: two real particles of different bodies touch when their cells (cubes of
// side s aligned with the box) meet: face to face at any sideways offset, along an edge and
// at a corner; a gap of more than TOUCH_TOL spacings in any one axis keeps them apart, in
// either direction and at any scale
TEST(Contact, TouchCells)
{
  const double box[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  for (double s : {1.0, 2.5e-4}) {
    // the box's cells: max(|x|, |y|, |z|) <= (1 + TOUCH_TOL) s
    auto touch = [s, &box](double x, double y, double z) {
      const double xij[3] = {x * s, y * s, z * s};
      return touch_cells(xij, box, box, s);
    };
    EXPECT_TRUE(touch(1.0, 0.0, 0.0));
    EXPECT_TRUE(touch(-1.0, 0.0, 0.0));
    EXPECT_TRUE(touch(1.0, 0.5, -0.5));    // lattices offset sideways by half a spacing
    EXPECT_TRUE(touch(1.0, 1.0, 0.0));     // cells sharing an edge
    EXPECT_TRUE(touch(-1.0, 1.0, 1.0));    // and a corner
    EXPECT_TRUE(touch(0.3, 0.2, 0.9));     // overlapping
    EXPECT_TRUE(touch(1.0 + 0.99 * TOUCH_TOL, 0.0, 0.0));
    EXPECT_FALSE(touch(1.0 + 1.01 * TOUCH_TOL, 0.0, 0.0));
    EXPECT_FALSE(touch(0.0, -1.0 - 1.01 * TOUCH_TOL, 0.0));
    EXPECT_FALSE(touch(0.2, 0.1, 1.0 + 1.01 * TOUCH_TOL));
    EXPECT_FALSE(touch(1.1, 1.1, 0.0));    // diagonal, 0.1 apart in both axes

    // two cells turned 45 degrees about z, edges head-on along x: they meet sqrt(2) s apart,
    // at any offset along the edges (z)
    const double c = sqrt(0.5);
    const double r45[9] = {c, c, 0.0, -c, c, 0.0, 0.0, 0.0, 1.0};
    for (double z : {0.0, 0.7}) {
      const double in[3] = {sqrt(2.0) * (1.0 + 0.99 * TOUCH_TOL) * s, 0.0, z * s};
      const double out[3] = {sqrt(2.0) * (1.0 + 1.01 * TOUCH_TOL) * s, 0.0, z * s};
      EXPECT_TRUE(touch_cells(in, r45, r45, s));
      EXPECT_FALSE(touch_cells(out, r45, r45, s));
    }
    // (the box's cells would meet only 1 + TOUCH_TOL spacings apart)
    const double edge[3] = {1.2 * s, 0.0, 0.0};
    EXPECT_FALSE(touch(1.2, 0.0, 0.0));
    EXPECT_TRUE(touch_cells(edge, r45, r45, s));
    // a turned edge on an aligned face: the edge lies sqrt(1/2) s below its particle, the
    // face s / 2 above its own, at any offset of the face's particle across the edge
    // (within the face) and along it
    const double rx[9] = {1.0, 0.0, 0.0, 0.0, c, c, 0.0, -c, c};    // turned about x
    for (double y : {0.0, 0.4})
      for (double xa : {0.0, 0.3}) {
        const double in[3] = {xa * s, y * s, (0.5 + c) * s * (1.0 + 0.99 * TOUCH_TOL)};
        const double out[3] = {xa * s, y * s, (0.5 + c) * s * (1.0 + 1.01 * TOUCH_TOL)};
        EXPECT_TRUE(touch_cells(in, rx, box, s));
        EXPECT_FALSE(touch_cells(out, rx, box, s));
      }
    // a corner first on an aligned face: the body diagonal along z, the corner sqrt(3) / 2 s
    // below its particle. Axes e_a = z / sqrt(3) + sqrt(2/3) (cos phi_a u + sin phi_a w),
    // phi_a = 0, 120, 240 degrees, u and w normal to z
    const double u[3] = {sqrt(0.5), -sqrt(0.5), 0.0};
    const double w[3] = {1.0 / sqrt(6.0), 1.0 / sqrt(6.0), -2.0 / sqrt(6.0)};
    double corner[9];
    for (int a = 0; a < 3; a++) {
      const double phi = a * 2.0 * atan(1.0) * 4.0 / 3.0;
      for (int q = 0; q < 3; q++)
        corner[3 * a + q] = ((q == 2) ? 1.0 / sqrt(3.0) : 0.0) +
            sqrt(2.0 / 3.0) * (cos(phi) * u[q] + sin(phi) * w[q]);
    }
    const double zc = 0.5 + 0.5 * sqrt(3.0);
    const double cin[3] = {0.0, 0.0, zc * s * (1.0 + 0.99 * TOUCH_TOL)};
    const double cout[3] = {0.0, 0.0, zc * s * (1.0 + 1.01 * TOUCH_TOL)};
    EXPECT_TRUE(touch_cells(cin, corner, box, s));
    EXPECT_FALSE(touch_cells(cout, corner, box, s));

    // bodies of different spacings si, sj (several fixes esph/boundary): cubes of sides
    // (1 + TOUCH_TOL) si and sj, meeting (1 + TOUCH_TOL) (si + sj) / 2 apart along an axis,
    // and the same seen from either side; sj = si is the one-spacing test
    const double sj = 1.25 * s;
    for (double sgn : {1.0, -1.0}) {
      const double in[3] = {sgn * 0.99 * (1.0 + TOUCH_TOL) * 0.5 * (s + sj), 0.3 * s, 0.0};
      const double out[3] = {sgn * 1.01 * (1.0 + TOUCH_TOL) * 0.5 * (s + sj), 0.3 * s, 0.0};
      EXPECT_TRUE(touch_cells(in, box, box, s, sj));
      EXPECT_TRUE(touch_cells(in, box, box, sj, s));
      EXPECT_FALSE(touch_cells(out, box, box, s, sj));
      EXPECT_FALSE(touch_cells(out, box, box, sj, s));
      // the larger cube alone would reach: with s on both sides the cells are apart
      EXPECT_FALSE(touch_cells(in, box, box, s, s));
    }
    // a turned edge of the finer body on an aligned face of the coarser one
    const double fin[3] = {0.0, 0.0, (0.5 * sj / s + c) * s * (1.0 + 0.99 * TOUCH_TOL)};
    const double fout[3] = {0.0, 0.0, (0.5 * sj / s + c) * s * (1.0 + 1.01 * TOUCH_TOL)};
    EXPECT_TRUE(touch_cells(fin, rx, box, s, sj));
    EXPECT_FALSE(touch_cells(fout, rx, box, s, sj));
  }
}

// The frame of a cell from the neighbours: a simple cubic lattice turned anyhow gives its
// axes (up to sign and order) for an inner particle, a face, an edge and a corner; in 2d a
// square lattice; neighbours of an fcc lattice, a line of particles and none give the box.
TEST(Contact, LatticeFrame)
{
  const double s = 2.0e-4;
  // a rotation about the axis (1, 2, 3) by 0.7 rad (Rodrigues)
  double k[3] = {1.0, 2.0, 3.0};
  const double kl = sqrt(14.0);
  for (double &v : k) v /= kl;
  const double th = 0.7, ct = cos(th), st = sin(th);
  double R[3][3];
  for (int a = 0; a < 3; a++)
    for (int b = 0; b < 3; b++) {
      const double K = (a == b) ? 0.0 : ((a + 1) % 3 == b ? -k[3 - a - b] : k[3 - a - b]);
      R[a][b] = ((a == b) ? ct : 0.0) + st * K + (1.0 - ct) * k[a] * k[b];
    }
  auto turned = [&](double x, double y, double z, std::vector<double> &d) {
    for (int a = 0; a < 3; a++) d.push_back(s * (R[a][0] * x + R[a][1] * y + R[a][2] * z));
  };
  // each row of the frame is parallel to a column of R
  auto check = [&](const std::vector<double> &d) {
    double f[9];
    ASSERT_TRUE(lattice_frame(d.data(), d.size() / 3, s, 3, f));
    for (int a = 0; a < 3; a++) {
      double best = 0.0;
      for (int b = 0; b < 3; b++)
        best = std::max(best,
                        fabs(f[3 * a] * R[0][b] + f[3 * a + 1] * R[1][b] + f[3 * a + 2] * R[2][b]));
      EXPECT_NEAR(best, 1.0, 1e-12);
    }
  };
  std::vector<double> inner, corner, far;
  for (int a = -1; a <= 1; a++)
    for (int b = -1; b <= 1; b++)
      for (int c = -1; c <= 1; c++)
        if (a || b || c) turned(a, b, c, inner);    // with the diagonals
  check(inner);
  turned(-1, 0, 0, corner);
  turned(0, -1, -1, corner);    // a face diagonal between
  turned(0, -1, 0, corner);
  turned(0, 0, -1, corner);
  check(corner);
  // a lattice compressed by 15 % along its first axis and 10 % along the others: two face
  // diagonals come within the shell (1.24 spacings; in the given order a diagonal is the
  // first neighbour there), the axes, shorter, are taken first
  std::vector<double> squeezed;
  for (int a = -1; a <= 1; a++)
    for (int b = -1; b <= 1; b++)
      for (int c = -1; c <= 1; c++)
        if (a || b || c) turned(0.85 * a, 0.9 * b, 0.9 * c, squeezed);
  check(squeezed);
  // fcc: the twelve nearest neighbours at one spacing, along the face diagonals
  std::vector<double> fcc;
  const double q = sqrt(0.5);
  for (int a = 0; a < 3; a++)
    for (int sa : {-1, 1})
      for (int sb : {-1, 1}) {
        double v[3] = {0.0, 0.0, 0.0};
        v[a] = sa * q * s;
        v[(a + 1) % 3] = sb * q * s;
        fcc.insert(fcc.end(), v, v + 3);
      }
  double f[9];
  EXPECT_FALSE(lattice_frame(fcc.data(), fcc.size() / 3, s, 3, f));
  for (int a = 0; a < 9; a++) EXPECT_EQ(f[a], (a % 4 == 0) ? 1.0 : 0.0);
  turned(1, 0, 0, far);
  turned(-1, 0, 0, far);
  turned(2, 0, 0, far);
  EXPECT_FALSE(lattice_frame(far.data(), far.size() / 3, s, 3, f));
  EXPECT_FALSE(lattice_frame(nullptr, 0, s, 3, f));
  // 2d: a square lattice turned by 0.3 rad about z
  const double c2 = cos(0.3), s2 = sin(0.3);
  const double sq[9] = {c2 * s, s2 * s, 0.0, -s2 * s, c2 * s, 0.0, -c2 * s, -s2 * s, 0.0};
  ASSERT_TRUE(lattice_frame(sq, 3, s, 2, f));
  EXPECT_NEAR(fabs(f[0] * c2 + f[1] * s2), 1.0, 1e-12);
  EXPECT_NEAR(fabs(f[3] * -s2 + f[4] * c2), 1.0, 1e-12);
  EXPECT_NEAR(fabs(f[8]), 1.0, 1e-12);
}

// The rigid spin of a body (fix esph/boundary turn body): a cloud of particles of unequal
// masses in a rigid motion v = V + omega x (x - c0) gives back omega from its sums
// (add_body_sum(), as body_sums() builds them) to round-off, far from
// the origin too; in 2d its z part; a line of particles the part normal to the line (a
// line cannot turn about itself); one particle none.
static void rigid_cloud(int n, int dim, double shift, const double *w, double *s)
{
  const double V[3] = {50.0, -3.0, 7.0}, c0[3] = {1.0e-3 + shift, -2.0e-3, 0.5e-3};
  for (int k = 0; k < BODY_NSUM; k++) s[k] = 0.0;
  unsigned r = 12345;
  auto rnd = [&r]() {
    r = r * 1103515245u + 12345u;
    return ((r >> 8) & 0xffff) / 65536.0 - 0.5;
  };
  for (int i = 0; i < n; i++) {
    const double x[3] = {c0[0] + 1.0e-3 * rnd(), c0[1] + (dim > 1 ? 2.0e-3 * rnd() : 0.0),
                         c0[2] + (dim > 2 ? 0.7e-3 * rnd() : 0.0)};
    const double r3[3] = {x[0] - c0[0], x[1] - c0[1], x[2] - c0[2]};
    const double v[3] = {V[0] + w[1] * r3[2] - w[2] * r3[1], V[1] + w[2] * r3[0] - w[0] * r3[2],
                         V[2] + w[0] * r3[1] - w[1] * r3[0]};
    add_body_sum(s, 1.0e-8 * (1.0 + rnd()), x, v);
  }
}

TEST(Bodies, RigidSpin)
{
  const double w[3] = {2.0e4, -1.3e4, 0.7e4};
  double s[BODY_NSUM], om[3];
  // 3d, near the origin and 0.1 m from it (50 body sizes)
  for (double shift : {0.0, 0.1}) {
    rigid_cloud(200, 3, shift, w, s);
    const BodyMotion b = body_motion(s);
    rigid_spin(b, 3, om);
    for (int d = 0; d < 3; d++)
      EXPECT_NEAR(om[d], w[d], (shift > 0.0 ? 1.0e-6 : 1.0e-10) * 2.0e4)
          << "3d, shift " << shift << ", component " << d;
    // the centre of mass moves with the rigid velocity field at its place
    const double rc[3] = {b.c[0] - 1.0e-3 - shift, b.c[1] + 2.0e-3, b.c[2] - 0.5e-3};
    EXPECT_NEAR(b.V[0], 50.0 + w[1] * rc[2] - w[2] * rc[1], 1.0e-9);
  }
  // 2d: the cloud in a plane z = const, a spin about z
  const double wz[3] = {0.0, 0.0, 0.7e4};
  rigid_cloud(100, 2, 0.0, wz, s);
  rigid_spin(body_motion(s), 2, om);
  EXPECT_EQ(om[0], 0.0);
  EXPECT_EQ(om[1], 0.0);
  EXPECT_NEAR(om[2], wz[2], 1.0e-10 * wz[2]);
  // a line along x: the part of omega normal to it
  rigid_cloud(50, 1, 0.0, w, s);
  rigid_spin(body_motion(s), 3, om);
  EXPECT_NEAR(om[0], 0.0, 1.0e-6);
  EXPECT_NEAR(om[1], w[1], 1.0e-10 * 2.0e4);
  EXPECT_NEAR(om[2], w[2], 1.0e-10 * 2.0e4);
  // 1d and one particle: no spin
  rigid_spin(body_motion(s), 1, om);
  for (int d = 0; d < 3; d++) EXPECT_EQ(om[d], 0.0);
  rigid_cloud(1, 3, 0.0, w, s);
  rigid_spin(body_motion(s), 3, om);
  for (int d = 0; d < 3; d++) EXPECT_EQ(om[d], 0.0);
}

TEST(Contact, NormalCone)
{
  const double t = PI / 6.0;
  // block face, outward normal f; rod rim: end face (1,0,0) and side (0,1,0), 70 / 30 %
  const double f[3] = {-cos(t), -sin(t), 0.0};
  const double face[1][3] = {{f[0], f[1], f[2]}}, w1[1] = {1.0};
  const double rim[2][3] = {{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}}, w2[2] = {0.7, 0.3};
  double sf[6], sr[6], cf[6], cr[6];
  second_moment(face, w1, 1, sf);
  second_moment(rim, w2, 2, sr);
  contact_cone(sf, cf);
  contact_cone(sr, cr);
  // face: f f^T
  EXPECT_NEAR(cf[0], f[0] * f[0], 1e-14);
  EXPECT_NEAR(cf[3], f[0] * f[1], 1e-14);
  EXPECT_NEAR(cf[2], 0.0, 1e-14);
  // edge: both directions in full (0.3 of 0.7 is above CONE_R0): the xy projector
  EXPECT_NEAR(cr[0], 1.0, 1e-14);
  EXPECT_NEAR(cr[1], 1.0, 1e-14);
  EXPECT_NEAR(cr[2], 0.0, 1e-14);
  EXPECT_NEAR(cr[3], 0.0, 1e-14);
  // the rim particle's mean normal (coherence 0.97) and the face's: the common normal from
  // the rim (i) into the block is -f; the mean rule tilts it by degrees, the cone rule
  // leaves only the mean normal's vote CONE_TIE of that tilt (about 5 %)
  const double ni[3] = {0.88, 0.4, 0.0}, nj[3] = {f[0], f[1], f[2]}, xij[3] = {-0.5, 0.2, 0.0};
  double nc[3];
  contact_normal(ni, nj, xij, nc);
  const double tilt_mean = acos(std::min(1.0, -(nc[0] * f[0] + nc[1] * f[1])));
  EXPECT_GT(tilt_mean, 0.04);    // 2.4 degrees
  contact_normal_cone(cr, cf, nc);
  const double tilt_cone = acos(std::min(1.0, -(nc[0] * f[0] + nc[1] * f[1] + nc[2] * f[2])));
  EXPECT_LT(tilt_cone, 1.2 * CONE_TIE * tilt_mean);
  const double nref[3] = {nc[0], nc[1], nc[2]};
  // the same scene rotated by 40 degrees about (1,2,3): the rotated answer
  const double ax[3] = {1.0 / sqrt(14.0), 2.0 / sqrt(14.0), 3.0 / sqrt(14.0)};
  const double th = 40.0 * PI / 180.0, c = cos(th), s = sin(th);
  auto rot = [&](const double *v, double *r) {
    const double kv = ax[0] * v[0] + ax[1] * v[1] + ax[2] * v[2];
    const double kx[3] = {ax[1] * v[2] - ax[2] * v[1], ax[2] * v[0] - ax[0] * v[2],
                          ax[0] * v[1] - ax[1] * v[0]};
    for (int d = 0; d < 3; d++) r[d] = v[d] * c + kx[d] * s + ax[d] * kv * (1.0 - c);
  };
  double rface[1][3], rrim[2][3], rni[3], rnj[3], rx[3], rf[3];
  rot(face[0], rface[0]);
  rot(rim[0], rrim[0]);
  rot(rim[1], rrim[1]);
  rot(ni, rni);
  rot(nj, rnj);
  rot(xij, rx);
  rot(f, rf);
  second_moment(rface, w1, 1, sf);
  second_moment(rrim, w2, 2, sr);
  contact_cone(sf, cf);
  contact_cone(sr, cr);
  contact_normal(rni, rnj, rx, nc);
  contact_normal_cone(cr, cf, nc);
  double rref[3];
  rot(nref, rref);
  for (int d = 0; d < 3; d++) EXPECT_NEAR(nc[d], rref[d], 1e-12);

  // two opposite flat faces: their normal
  const double fa[1][3] = {{1.0, 0.0, 0.0}};
  double sa[6], ca[6];
  second_moment(fa, w1, 1, sa);
  contact_cone(sa, ca);
  const double ea[3] = {1.0, 0.0, 0.0}, eb[3] = {-1.0, 0.0, 0.0}, xab[3] = {-1.0, 0.3, 0.0};
  contact_normal(ea, eb, xab, nc);
  contact_normal_cone(ca, ca, nc);
  EXPECT_NEAR(nc[0], 1.0, 1e-14);
  EXPECT_NEAR(nc[1], 0.0, 1e-14);

  // two alike curved patches (normals within 5 degrees: below the edge threshold), mirror
  // images about the x axis: the axis, as the mean rule gives
  const double a5 = 5.0 * PI / 180.0;
  const double ca5 = cos(a5), sa5 = sin(a5);
  const double pi_[3][3] = {{1, 0, 0}, {ca5, sa5, 0}, {ca5, -sa5, 0}};
  const double pj_[3][3] = {{-1, 0, 0}, {-ca5, sa5, 0}, {-ca5, -sa5, 0}};
  const double w3[3] = {0.5, 0.3, 0.2};
  double si[6], sj[6], ci[6], cj[6];
  second_moment(pi_, w3, 3, si);
  second_moment(pj_, w3, 3, sj);
  contact_cone(si, ci);
  contact_cone(sj, cj);
  const double ni2[3] = {0.5 + 0.5 * ca5, 0.1 * sa5, 0.0},
               nj2[3] = {-(0.5 + 0.5 * ca5), 0.1 * sa5, 0.0};
  contact_normal(ni2, nj2, xab, nc);
  contact_normal_cone(ci, cj, nc);
  EXPECT_NEAR(nc[0], 1.0, 1e-14);
  EXPECT_NEAR(nc[1], 0.0, 1e-14);

  // crossing edges: x-y edge plane (normals (1,0,0), (0,1,0)) against the plane of (1,0,0)
  // and (0,0,1): their common direction x, from a mean normal 20 degrees off to within the
  // mean normal's vote CONE_TIE: tilt about CONE_TIE sin(20) cos(20) = 0.016 rad
  const double e2[2][3] = {{-1.0, 0.0, 0.0}, {0.0, 0.0, -1.0}}, w5[2] = {0.5, 0.5};
  double s2[6], c2[6];
  second_moment(e2, w5, 2, s2);
  contact_cone(s2, c2);
  second_moment(rim, w5, 2, sr);
  contact_cone(sr, cr);
  nc[0] = cos(0.35);
  nc[1] = sin(0.35);
  nc[2] = 0.0;
  contact_normal_cone(cr, c2, nc);
  EXPECT_LT(atan2(nc[1], nc[0]), 0.02);
  EXPECT_GT(atan2(nc[1], nc[0]), 0.0);
  EXPECT_NEAR(nc[2], 0.0, 1e-14);

  // continuity: a small change of the cone moves the normal a little (no eigenvector jump)
  double sr2[6], cr2[6], n1[3], n2[3];
  const double w6[2] = {0.7, 0.3 + 1e-9};
  second_moment(rim, w2, 2, sr);
  second_moment(rim, w6, 2, sr2);
  contact_cone(sr, cr);
  contact_cone(sr2, cr2);
  second_moment(face, w1, 1, sf);
  contact_cone(sf, cf);
  for (double *n : {n1, n2}) {
    n[0] = 0.9;
    n[1] = 0.43588989435406733;
    n[2] = 0.0;
  }
  contact_normal_cone(cr, cf, n1);
  contact_normal_cone(cr2, cf, n2);
  EXPECT_LT(fabs(n1[0] - n2[0]) + fabs(n1[1] - n2[1]), 1e-8);
}

// radial return: a deviator beyond the von Mises surface is scaled back onto it, one inside
// is untouched, Y = 0 means elastic
TEST(Strength, RadialReturn)
{
  double s[6] = {2.0e8, -1.0e8, -1.0e8, 0.5e8, 0.0, 0.0};
  const double seq0 = sqrt(1.5 * (4e16 + 1e16 + 1e16 + 2 * 0.25e16));
  radial_return(s, 1.0e8);
  const double seq = sqrt(
      1.5 *
      (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
  EXPECT_NEAR(seq, 1.0e8, 1e-6);
  EXPECT_NEAR(s[0] / s[3], 4.0, 1e-12);    // direction kept
  double t[6] = {1.0e7, -1.0e7, 0.0, 0.0, 0.0, 0.0};
  radial_return(t, 1.0e8);
  EXPECT_DOUBLE_EQ(t[0], 1.0e7);
  radial_return(t, 0.0);
  EXPECT_DOUBLE_EQ(t[0], 1.0e7);
  EXPECT_GT(seq0, 1.0e8);
}

// radial return with linear hardening: the plastic strain increment solves
// sigma_trial - 3 G depsp = Y0 + H (epsp + depsp), and the returned deviator lies on the
// grown surface; a second call with the updated epsp leaves it there (consistency)
TEST(Strength, RadialReturnHardening)
{
  const double G = 40.0e9, H = 1.0e9, Y0 = 4.0e8, epsp0 = 0.01;
  double s[6] = {6.0e8, -3.0e8, -3.0e8, 0.0, 0.0, 0.0};
  const double trial = sqrt(1.5 * (36e16 + 9e16 + 9e16));    // 9e8
  const double dep = radial_return(s, Y0, H, G, epsp0);
  EXPECT_NEAR(dep, (trial - (Y0 + H * epsp0)) / (3.0 * G + H), 1e-18);
  const double seq = sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
  EXPECT_NEAR(seq, Y0 + H * (epsp0 + dep), 1e-4);
  EXPECT_NEAR(seq, trial - 3.0 * G * dep, 1e-4);
  EXPECT_NEAR(radial_return(s, Y0, H, G, epsp0 + dep), 0.0, 1e-15);
  // perfect plasticity: the same scaling as without G and H
  double a[6] = {6.0e8, -3.0e8, -3.0e8, 1.0e8, 0.0, 0.0}, b[6];
  for (int k = 0; k < 6; k++) b[k] = a[k];
  radial_return(a, Y0);
  radial_return(b, Y0, 0.0, G, 0.5);
  for (int k = 0; k < 6; k++) EXPECT_DOUBLE_EQ(a[k], b[k]);
}

// Unit conversion: with LAMMPS's constants of units si (all 1) every factor is exactly 1.0
// (results bitwise those without conversion); in metal the internal pressure unit
// (g/mol)/(Angstrom ps^2) is mvv2e nktv2p = 166.05 bar, force and energy agree
// (ftm2v = 1/mvv2e: force = energy/distance), and the factors invert each other
TEST(Units, SiIsIdentityMetalFactors)
{
  Units u;
  u.set(1.0, 1.0, 1.0);
  EXPECT_EQ(u.force, 1.0);
  EXPECT_EQ(u.energy, 1.0);
  EXPECT_EQ(u.pressure, 1.0);
  EXPECT_EQ(u.energy_in, 1.0);
  EXPECT_EQ(u.pressure_in, 1.0);
  const double mvv2e = 1.0364269e-4, nktv2p = 1.6021765e6;
  u.set(1.0 / mvv2e, mvv2e, nktv2p);
  EXPECT_NEAR(u.pressure, 166.0539, 1e-4);
  EXPECT_NEAR(u.force / u.energy, 1.0, 1e-15);
  EXPECT_NEAR(u.energy * u.energy_in, 1.0, 1e-15);
  EXPECT_NEAR(u.pressure * u.pressure_in, 1.0, 1e-15);
  // a stress of 1 GPa = 1e4 bar in internal units, and back
  EXPECT_NEAR(1.0e4 * u.pressure_in * u.pressure, 1.0e4, 1e-11);
}
