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
   pair esph/solid: the bulk pairs in vector registers (keyword simd)

   A bulk pair is one of two real particles of the same body (of any two
   bodies with contact off), or of a boundary and a real particle of one
   body: the pairs that most neighbours are
   and that need none of the contact logic. With simd yes, on a CPU with
   AVX-512, the scalar loop (pair_esph_solid_loop.cpp) takes only the
   other pairs, from the half list split by simd_split(), and this pass
   takes the bulk pairs from a full neighbour list (each particle's
   neighbours ordered by simd_split(): partners first): eight neighbours
   of one particle per vector, read from the rows of the hoisted array
   (hq, laid out in blocks of 8; simd_pack() adds position, mass and body)
   by row loads and a transpose, with only the particle's own sums
   written (no writes to j, so no scatter and no conflicts; every pair is
   computed from both sides, each side with the scalar loop's formulas).
   The answer is the scalar loop's to round-off: the sums are in another
   order and the compiler may fuse multiply-adds.
------------------------------------------------------------------------- */

#include "pair_esph_solid.h"
#include "pair_esph_solid_slots.h"

#include "atom.h"
#include "esph_kernel.h"
#include "esph_prefetch.h"
#include "esph_state.h"
#include "esph_threads.h"
#include "force.h"
#include "memory.h"
#include "neigh_list.h"
#include "neighbor.h"

#include <vector>

#if defined(__x86_64__) && defined(__GNUC__) && !defined(__INTEL_COMPILER)
#define ESPH_SIMD_AVX512 1
#include <immintrin.h>
#endif

using namespace LAMMPS_NS;
using namespace ESPH;
using namespace ESPHSolid;

// the rows of the vector pass are hq's (slots Q_* of pair_esph_solid_slots.h), read in
// blocks of 8 doubles: Q_X .. Q_RHO, Q_C .. Q_BODY, Q_D .. Q_H, Q_E .. Q_ENG; a boundary
// particle's normal and gap are also in its stress slots (Q_BN .. Q_BGAPV), so that the
// first two blocks hold what a lane of it needs
static constexpr int BLK1 = 8, BLK2 = 16, BLK3 = 24;

/* ----------------------------------------------------------------------
   the CPU runs the vector pass (valgrind reports no AVX-512: scalar there)
------------------------------------------------------------------------- */

bool PairESPHSolid::simd_cpu()
{
#ifdef ESPH_SIMD_AVX512
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
      __builtin_cpu_supports("avx512dq");
#else
  return false;
#endif
}

#ifdef ESPH_SIMD_AVX512

namespace {

// what one particle's bulk pairs read
struct BulkCtx {
  const double *pk;    // rows (hq: Q_*), stride doubles per atom
  int stride;
  double norm_hinv, hinv, h0, epsh2;    // kernel and viscosity constants (constant h)
  double alpha, beta, beta_ratio, fconv;
  int recon;    // RECON_OFF, RECON_VANLEER, RECON_MINMOD
  int vswitch, heat;
  int bnd;      // boundary-real pairs of one body here too (not in the scalar loop)
  int solid;    // contact solid: the gap sums of those
  int cone;     // contact/normal cone: and the cone sums
  double norm;
};

#define ESPH_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma")))
#define ESPH_AVX512_INLINE ESPH_AVX512 static inline __attribute__((always_inline))

ESPH_AVX512_INLINE __m512d bcast(double a)
{
  return _mm512_set1_pd(a);
}

/* ----------------------------------------------------------------------
   columns c[0..7] of 8 columns [off, off + 8) of the rows of atoms
   j[0..7]: eight row loads and an 8 x 8 transpose (24 shuffles), which
   costs less than eight gathers
------------------------------------------------------------------------- */

ESPH_AVX512_INLINE void load_cols(const double *pk, int stride, const int *j, int off, __m512d *c)
{
  const __m512d r0 = _mm512_loadu_pd(pk + (size_t) j[0] * stride + off);
  const __m512d r1 = _mm512_loadu_pd(pk + (size_t) j[1] * stride + off);
  const __m512d r2 = _mm512_loadu_pd(pk + (size_t) j[2] * stride + off);
  const __m512d r3 = _mm512_loadu_pd(pk + (size_t) j[3] * stride + off);
  const __m512d r4 = _mm512_loadu_pd(pk + (size_t) j[4] * stride + off);
  const __m512d r5 = _mm512_loadu_pd(pk + (size_t) j[5] * stride + off);
  const __m512d r6 = _mm512_loadu_pd(pk + (size_t) j[6] * stride + off);
  const __m512d r7 = _mm512_loadu_pd(pk + (size_t) j[7] * stride + off);
  const __m512d t0 = _mm512_unpacklo_pd(r0, r1), t1 = _mm512_unpackhi_pd(r0, r1);
  const __m512d t2 = _mm512_unpacklo_pd(r2, r3), t3 = _mm512_unpackhi_pd(r2, r3);
  const __m512d t4 = _mm512_unpacklo_pd(r4, r5), t5 = _mm512_unpackhi_pd(r4, r5);
  const __m512d t6 = _mm512_unpacklo_pd(r6, r7), t7 = _mm512_unpackhi_pd(r6, r7);
  const __m512d u0 = _mm512_shuffle_f64x2(t0, t2, 0x88), u1 = _mm512_shuffle_f64x2(t1, t3, 0x88);
  const __m512d u2 = _mm512_shuffle_f64x2(t0, t2, 0xdd), u3 = _mm512_shuffle_f64x2(t1, t3, 0xdd);
  const __m512d u4 = _mm512_shuffle_f64x2(t4, t6, 0x88), u5 = _mm512_shuffle_f64x2(t5, t7, 0x88);
  const __m512d u6 = _mm512_shuffle_f64x2(t4, t6, 0xdd), u7 = _mm512_shuffle_f64x2(t5, t7, 0xdd);
  c[0] = _mm512_shuffle_f64x2(u0, u4, 0x88);
  c[4] = _mm512_shuffle_f64x2(u0, u4, 0xdd);
  c[1] = _mm512_shuffle_f64x2(u1, u5, 0x88);
  c[5] = _mm512_shuffle_f64x2(u1, u5, 0xdd);
  c[2] = _mm512_shuffle_f64x2(u2, u6, 0x88);
  c[6] = _mm512_shuffle_f64x2(u2, u6, 0xdd);
  c[3] = _mm512_shuffle_f64x2(u3, u7, 0x88);
  c[7] = _mm512_shuffle_f64x2(u3, u7, 0xdd);
}

/* ----------------------------------------------------------------------
   the lane sums of a[0..7] added to out[0..7]: 14 shuffles and adds, where
   eight horizontal sums take about 50
------------------------------------------------------------------------- */

ESPH_AVX512_INLINE void reduce_add8(const __m512d *a, double *out)
{
  const __m512d r01 = _mm512_unpacklo_pd(a[0], a[1]) + _mm512_unpackhi_pd(a[0], a[1]);
  const __m512d r23 = _mm512_unpacklo_pd(a[2], a[3]) + _mm512_unpackhi_pd(a[2], a[3]);
  const __m512d r45 = _mm512_unpacklo_pd(a[4], a[5]) + _mm512_unpackhi_pd(a[4], a[5]);
  const __m512d r67 = _mm512_unpacklo_pd(a[6], a[7]) + _mm512_unpackhi_pd(a[6], a[7]);
  const __m512d s0 = _mm512_shuffle_f64x2(r01, r23, 0x88) + _mm512_shuffle_f64x2(r01, r23, 0xdd);
  const __m512d s1 = _mm512_shuffle_f64x2(r45, r67, 0x88) + _mm512_shuffle_f64x2(r45, r67, 0xdd);
  const __m512d t = _mm512_shuffle_f64x2(s0, s1, 0x88) + _mm512_shuffle_f64x2(s0, s1, 0xdd);
  _mm512_storeu_pd(out, _mm512_loadu_pd(out) + t);
}

// recon_slope() of pair_esph_solid_slots.h: x . D x with D in Voigt order
ESPH_AVX512_INLINE __m512d slope(const __m512d *d, __m512d x0, __m512d x1, __m512d x2)
{
  return d[0] * x0 * x0 + d[1] * x1 * x1 + d[2] * x2 * x2 +
      2.0 * (d[3] * x0 * x1 + d[4] * x0 * x2 + d[5] * x1 * x2);
}

/* ----------------------------------------------------------------------
   the neighbours jlist[b .. b + 8) of a particle: their indices in js and
   the first two blocks of their rows in c0, c1; the lanes past
   jnum read atom 0's row and are off the returned mask
------------------------------------------------------------------------- */

// the first three blocks of the rows of neighbours jlist[from .. to) into the cache
ESPH_AVX512_INLINE void prefetch_rows(const BulkCtx &c, const int *jlist, int from, int to)
{
  for (int e = from; e < to; e++) {
    const double *row = c.pk + (size_t) (jlist[e] & NEIGHMASK) * c.stride;
    _mm_prefetch((const char *) row, _MM_HINT_T0);
    _mm_prefetch((const char *) (row + BLK1), _MM_HINT_T0);
    _mm_prefetch((const char *) (row + BLK2), _MM_HINT_T0);
  }
}

ESPH_AVX512_INLINE __mmask8 load_chunk(const BulkCtx &c, const int *jlist, int jnum, int b, int *js,
                                       __m512d *c0, __m512d *c1)
{
  const int n = (jnum - b < 8) ? jnum - b : 8;
  const __mmask8 m = (__mmask8) ((1u << n) - 1u);
  // the next chunk's rows on their way to the cache (the neighbours of a particle span
  // more rows than the core's own cache holds)
  prefetch_rows(c, jlist, b + 8, jnum < b + 16 ? jnum : b + 16);
  _mm256_store_si256(
      (__m256i *) js,
      _mm256_and_si256(_mm256_maskz_loadu_epi32(m, jlist + b), _mm256_set1_epi32(NEIGHMASK)));
  load_cols(c.pk, c.stride, js, 0, c0);
  load_cols(c.pk, c.stride, js, BLK1, c1);
  return m;
}

// the cubic B-spline (kernel_eval()) at q < 2, t = 2 - q, near = q < 1: W / norm and dW/dq
ESPH_AVX512_INLINE __m512d cubic_w(__mmask8 near, __m512d q, __m512d t)
{
  return _mm512_mask_blend_pd(near, 0.25 * t * t * t, 1.0 - 1.5 * q * q + 0.75 * q * q * q);
}

ESPH_AVX512_INLINE __m512d cubic_dwdq(__mmask8 near, __m512d q, __m512d t)
{
  return _mm512_mask_blend_pd(near, -0.75 * t * t, -3.0 * q + 2.25 * q * q);
}

/* ----------------------------------------------------------------------
   the bulk pairs of particle i, its full list's first nbulk neighbours
   jlist (simd_split()), eight at a time: the scalar loop's same-body
   branch (stress force, Monaghan-Gingold viscosity with its
   reconstruction or switch, G, viscous heating, M of gradient corrected,
   heat transfer), i's side only, into fi and ai; then its sums over the
   boundary particles of its body, the next nbnd neighbours. A lane
   beyond the kernel's support or past the list has dW = 0 (W = 0) and
   mask-zeroed viscosity and heat: it adds exact zeros
------------------------------------------------------------------------- */

template <int CORR>
ESPH_AVX512 void bulk_atom(const BulkCtx &c, int i, const int *jlist, int nbulk, int nbnd,
                           double *fi, double *ai)
{
  const double *pi_ = c.pk + (size_t) i * c.stride;
  const __m512d zero = _mm512_setzero_pd(), one = bcast(1.0), two = bcast(2.0);
  const __m512d xi = bcast(pi_[Q_X]), yi = bcast(pi_[Q_X + 1]), zi = bcast(pi_[Q_X + 2]);
  const __m512d vi0 = bcast(pi_[Q_V]), vi1 = bcast(pi_[Q_V + 1]), vi2 = bcast(pi_[Q_V + 2]);
  const __m512d rhoi = bcast(pi_[Q_RHO]), ci = bcast(pi_[Q_C]), mi = bcast(pi_[Q_M]);
  const __m512d hinv = bcast(c.hinv), nh = bcast(c.norm_hinv), h0 = bcast(c.h0);
  const __m512d epsh2 = bcast(c.epsh2);
  __m512d Ai[6], Di[6];
  for (int k = 0; k < 6; k++) Ai[k] = bcast(pi_[Q_A + k]);
  for (int k = 0; k < 6; k++) Di[k] = bcast(c.recon ? pi_[Q_D + k] : 0.0);
  const __m512d alphai = bcast(c.vswitch ? pi_[Q_ALPHA] : 0.0);
  const __m512d ei = bcast(c.heat ? pi_[Q_E] : 0.0), zetai = bcast(c.heat ? pi_[Q_ZETA] : 0.0);

  __m512d sf0 = zero, sf1 = zero, sf2 = zero, savh = zero, sheat = zero;
  __m512d sg0 = zero, sg1 = zero, sg2 = zero, sg3 = zero, sg4 = zero, sg5 = zero, sg6 = zero,
          sg7 = zero, sg8 = zero;
  __m512d sm0 = zero, sm1 = zero, sm2 = zero, sm4 = zero, sm5 = zero, sm8 = zero;

  alignas(32) int js[8];
  for (int b = 0; b < nbulk; b += 8) {
    __m512d c0[8], c1[8];
    const __mmask8 m = load_chunk(c, jlist, nbulk, b, js, c0, c1);
    const __m512d d0 = xi - c0[Q_X], d1 = yi - c0[Q_X + 1], d2 = zi - c0[Q_X + 2];
    const __m512d mj = c0[Q_M];
    const __m512d rsq = d0 * d0 + d1 * d1 + d2 * d2;
    // the bulk partners (simd_split() put them first) within the support and not
    // coinciding (there the gradient vanishes); the cubic B-spline's dW/dr / r
    // (kernel_eval), 0 in every other lane
    // (1 / r as r / r^2: the division starts with the square root, not after it; the
    // divisions here are latency, not throughput: each one that waits for another result
    // holds up the chunk)
    const __m512d r = _mm512_sqrt_pd(rsq);
    const __m512d rsqinv = one / rsq;
    const __m512d q = r * hinv;
    const __mmask8 in = _mm512_mask_cmp_pd_mask(m, q, two, _CMP_LT_OQ);
    const __mmask8 live = _mm512_mask_cmp_pd_mask(in, r, zero, _CMP_GT_OQ);
    const __mmask8 near = _mm512_cmp_pd_mask(q, one, _CMP_LT_OQ);
    const __m512d t = two - q;
    if (!live) continue;
    const __m512d dwdq = cubic_dwdq(near, q, t);
    const __m512d dw = _mm512_maskz_mul_pd(live, nh * dwdq * r, rsqinv);
    const __m512d g0 = dw * d0, g1 = dw * d1, g2 = dw * d2;
    const __m512d v0 = vi0 - c0[Q_V], v1 = vi1 - c0[Q_V + 1], v2 = vi2 - c0[Q_V + 2];
    const __m512d rhoj = c0[Q_RHO], cj = c1[Q_C - BLK1];
    const __m512d *Aj = c1 + (Q_A - BLK1);

    // stress force per m_i m_j: (sigma_i / rho_i^2 + sigma_j / rho_j^2) grad_i W
    const __m512d T0 = Ai[0] + Aj[0], T1 = Ai[1] + Aj[1], T2 = Ai[2] + Aj[2];
    const __m512d T3 = Ai[3] + Aj[3], T4 = Ai[4] + Aj[4], T5 = Ai[5] + Aj[5];
    // (lanes past the partners read atom 0's row: finite, times g = 0)
    const __m512d Tg0 = T0 * g0 + T3 * g1 + T4 * g2;
    const __m512d Tg1 = T3 * g0 + T1 * g1 + T5 * g2;
    const __m512d Tg2 = T4 * g0 + T5 * g1 + T2 * g2;

    // Monaghan-Gingold viscosity of the approaching pairs (eqs. 4-7)
    const __m512d vr = v0 * d0 + v1 * d1 + v2 * d2;
    const __mmask8 appr = _mm512_mask_cmp_pd_mask(live, vr, zero, _CMP_LT_OQ);
    __m512d c2[8], c3[8];
    if (appr && (c.recon || c.vswitch)) load_cols(c.pk, c.stride, js, BLK2, c2);
    if (c.heat) load_cols(c.pk, c.stride, js, BLK3, c3);
    __m512d pi = zero;
    if (appr) {
      // 1 / (D^2 rho_bar), D = r^2 + eps h^2: the one division of pi below, started before
      // the velocity is reconstructed
      const __m512d dd = rsq + epsh2;
      const __m512d vinv = _mm512_maskz_div_pd(appr, one, dd * dd * (0.5 * (rhoi + rhoj)));
      __m512d vrv = vr;
      if (c.recon) {
        // the velocities reconstructed to the pair's midpoint, limited (recon_vr())
        const __m512d a_i = slope(Di, d0, d1, d2), a_j = slope(c2 + (Q_D - BLK2), d0, d1, d2);
        const __m512d p = a_i * a_j;
        const __mmask8 pos = _mm512_mask_cmp_pd_mask(appr, p, zero, _CMP_GT_OQ);
        if (pos) {
          if (c.recon == 1) {    // RECON_VANLEER: phi (a_i + a_j) / 2 = 2 p / (a_i + a_j)
            vrv = _mm512_mask_sub_pd(vr, pos, vr, _mm512_maskz_div_pd(pos, 2.0 * p, a_i + a_j));
          } else {
            const __m512d fa = _mm512_abs_pd(a_i), fb = _mm512_abs_pd(a_j);
            const __m512d phi =
                _mm512_maskz_div_pd(pos, _mm512_min_pd(fa, fb), _mm512_max_pd(fa, fb));
            vrv = _mm512_mask_sub_pd(vr, pos, vr, 0.5 * phi * (a_i + a_j));
          }
        }
        vrv = _mm512_min_pd(vrv, zero);
      }
      __m512d al = bcast(c.alpha), be = bcast(c.beta);
      if (c.vswitch) {
        al = 0.5 * (alphai + c2[Q_ALPHA - BLK2]);
        be = c.beta_ratio * al;
      }
      // pi = (-alpha c_bar mu + beta mu^2) / rho_bar with mu = X / D, X = h v_r:
      // X (beta X - alpha c_bar D) / (D^2 rho_bar)
      const __m512d X = h0 * vrv;
      pi = _mm512_maskz_mul_pd(appr, X * (be * X - al * 0.5 * (ci + cj) * dd), vinv);
    }
    const __m512d avh = 0.5 * pi * (v0 * g0 + v1 * g1 + v2 * g2);
    const __m512d mm = mi * mj * c.fconv;
    sf0 += mm * (Tg0 - pi * g0);
    sf1 += mm * (Tg1 - pi * g1);
    sf2 += mm * (Tg2 - pi * g2);

    // G = sum_j m_j (v_j - v_i) (x) grad_i W
    const __m512d w0 = -mj * v0, w1 = -mj * v1, w2 = -mj * v2;
    sg0 += w0 * g0;
    sg1 += w0 * g1;
    sg2 += w0 * g2;
    sg3 += w1 * g0;
    sg4 += w1 * g1;
    sg5 += w1 * g2;
    sg6 += w2 * g0;
    sg7 += w2 * g1;
    sg8 += w2 * g2;
    savh += mj * avh;
    if (CORR == 1) {
      // M = sum_j m_j (x_j - x_i) (x) grad_i W = -sum_j m_j dW/dr / r (x_i - x_j) (x)
      // (x_i - x_j): symmetric, its upper triangle
      const __m512d x0 = -mj * d0, x1 = -mj * d1, x2 = -mj * d2;
      sm0 += x0 * g0;
      sm1 += x0 * g1;
      sm2 += x0 * g2;
      sm4 += x1 * g1;
      sm5 += x1 * g2;
      sm8 += x2 * g2;
    }
    if (c.heat) {
      // artificial heat transfer (eqs. 8-10)
      const __m512d zbar = 0.5 * (zetai + c3[Q_ZETA - BLK3]);
      const __m512d rbar = 0.5 * (rhoi + rhoj);
      const __m512d heat = _mm512_maskz_div_pd(
          live, 2.0 * zbar / rbar * (ei - c3[Q_E - BLK3]) * dw * rsq, rsq + epsh2);
      sheat += mj * heat;
    }
  }

  // the normal and gap sums from i's own body's boundary particles, next in the list
  // (add_normal_sums(), add_gap_sums()): n W, (x_k - x_i).n W, W; W flag, W gap, W gap rate
  if (nbnd > 0) {
    __m512d sb[14];
    for (int k = 0; k < 14; k++) sb[k] = zero;
    const int *blist = jlist + nbulk;
    for (int b = 0; b < nbnd; b += 8) {
      __m512d c0[8], c1[8];
      const __mmask8 m = load_chunk(c, blist, nbnd, b, js, c0, c1);
      const __m512d d0 = xi - c0[Q_X], d1 = yi - c0[Q_X + 1], d2 = zi - c0[Q_X + 2];
      const __m512d q = _mm512_sqrt_pd(d0 * d0 + d1 * d1 + d2 * d2) * hinv;
      const __mmask8 bk = _mm512_mask_cmp_pd_mask(m, q, two, _CMP_LT_OQ);
      if (!bk) continue;
      const __mmask8 near = _mm512_cmp_pd_mask(q, one, _CMP_LT_OQ);
      const __m512d w = _mm512_maskz_mov_pd(bk, c.norm * cubic_w(near, q, two - q));
      const __m512d n0 = c1[Q_BN - BLK1], n1 = c1[Q_BN + 1 - BLK1], n2 = c1[Q_BN + 2 - BLK1];
      sb[0] += w * n0;
      sb[1] += w * n1;
      sb[2] += w * n2;
      sb[3] += w * (-d0 * n0 - d1 * n1 - d2 * n2);
      sb[4] += w;
      if (c.solid) {
        sb[5] += w * c1[Q_BGFLAG - BLK1];
        sb[6] += w * c1[Q_BGAP - BLK1];
        sb[7] += w * c1[Q_BGAPV - BLK1];
        if (c.cone) {
          // add_cone_sums(): W n_k (x) n_k (Voigt)
          sb[8] += w * n0 * n0;
          sb[9] += w * n1 * n1;
          sb[10] += w * n2 * n2;
          sb[11] += w * n0 * n1;
          sb[12] += w * n0 * n2;
          sb[13] += w * n1 * n2;
        }
      }
    }
    double bs[8] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
    reduce_add8(sb, bs);
    for (int k = 0; k < 5; k++) ai[A_NSUM + k] += bs[k];
    if (c.solid) {
      ai[A_GW] += bs[5];
      ai[A_GG] += bs[6];
      ai[A_GV] += bs[7];
      if (c.cone)
        for (int k = 0; k < 6; k++) ai[A_NN + k] += _mm512_reduce_add_pd(sb[8 + k]);
    }
  }

  // the sums in the slot order of acc (A_G .. A_AVHEAT, A_HEAT; A_M)
  const __m512d g8[8] = {sg0, sg1, sg2, sg3, sg4, sg5, sg6, sg7};
  reduce_add8(g8, ai + A_G);
  ai[A_G + 8] += _mm512_reduce_add_pd(sg8);
  ai[A_AVHEAT] += _mm512_reduce_add_pd(savh);
  if (c.heat) ai[A_HEAT] += _mm512_reduce_add_pd(sheat);
  if (CORR == 1) {
    const __m512d m8[8] = {sm0, sm1, sm2, sm1, sm4, sm5, sm2, sm5};
    reduce_add8(m8, ai + A_M);
    ai[A_M + 8] += _mm512_reduce_add_pd(sm8);
  }
  fi[0] += _mm512_reduce_add_pd(sf0);
  fi[1] += _mm512_reduce_add_pd(sf1);
  fi[2] += _mm512_reduce_add_pd(sf2);
}

/* ----------------------------------------------------------------------
   boundary particle k: its sums over the real particles p of its body
   within the support, its full list's first jnum neighbours jlist
   (simd_split()) (the scalar loop's boundary branch, k's side): with
   V_p = m_p / rho_p, sum V_p v_p (x) grad_k W, V_p grad_k W, V_p W v_p,
   V_p W, V_p (x_p - x_k) (x) grad_k W, V_p W (x_p - x_k)
------------------------------------------------------------------------- */

ESPH_AVX512 void bnd_atom(const BulkCtx &c, int k, const int *jlist, int jnum, double *ak)
{
  const double *pk_ = c.pk + (size_t) k * c.stride;
  const __m512d zero = _mm512_setzero_pd(), one = bcast(1.0), two = bcast(2.0);
  const __m512d xk = bcast(pk_[Q_X]), yk = bcast(pk_[Q_X + 1]), zk = bcast(pk_[Q_X + 2]);
  const __m512d hinv = bcast(c.hinv), nh = bcast(c.norm_hinv);
  // B_A (9), B_B (3), B_VSUM (3), B_WSUM, B_M (9), B_XSUM (3): slots B_A + 0 .. 27
  __m512d s[28];
  for (int a = 0; a < 28; a++) s[a] = zero;
  alignas(32) int js[8];
  for (int b = 0; b < jnum; b += 8) {
    __m512d c0[8], c1[8];
    // the real particles of k's body (simd_split() put them first)
    const __mmask8 real = load_chunk(c, jlist, jnum, b, js, c0, c1);
    const __m512d mp = c0[Q_M];
    const __m512d d0 = xk - c0[Q_X], d1 = yk - c0[Q_X + 1], d2 = zk - c0[Q_X + 2];
    const __m512d rsq = d0 * d0 + d1 * d1 + d2 * d2;
    // (1 / r as r / r^2, as in bulk_atom())
    const __m512d r = _mm512_sqrt_pd(rsq);
    const __m512d rsqinv = one / rsq;
    const __m512d q = r * hinv;
    const __mmask8 in = _mm512_mask_cmp_pd_mask(real, q, two, _CMP_LT_OQ);
    if (!in) continue;
    const __mmask8 live = _mm512_mask_cmp_pd_mask(in, r, zero, _CMP_GT_OQ);
    const __mmask8 near = _mm512_cmp_pd_mask(q, one, _CMP_LT_OQ);
    const __m512d t = two - q;
    const __m512d w = _mm512_maskz_mov_pd(in, c.norm * cubic_w(near, q, t));
    const __m512d dwdq = cubic_dwdq(near, q, t);
    const __m512d dw = _mm512_maskz_mul_pd(live, nh * dwdq * r, rsqinv);
    const __m512d g0 = dw * d0, g1 = dw * d1, g2 = dw * d2;
    // V_p, 0 in the lanes off the mask
    const __m512d Vp = _mm512_maskz_div_pd(in, mp, c0[Q_RHO]);
    const __m512d va0 = Vp * c0[Q_V], va1 = Vp * c0[Q_V + 1], va2 = Vp * c0[Q_V + 2];
    s[0] += va0 * g0;
    s[1] += va0 * g1;
    s[2] += va0 * g2;
    s[3] += va1 * g0;
    s[4] += va1 * g1;
    s[5] += va1 * g2;
    s[6] += va2 * g0;
    s[7] += va2 * g1;
    s[8] += va2 * g2;
    s[9] += Vp * g0;
    s[10] += Vp * g1;
    s[11] += Vp * g2;
    const __m512d Vw = Vp * w;
    s[12] += Vw * c0[Q_V];
    s[13] += Vw * c0[Q_V + 1];
    s[14] += Vw * c0[Q_V + 2];
    s[15] += Vw;
    // x_p - x_k = -dx; (x_p - x_k) (x) grad_k W is symmetric (grad_k W = dW/dr / r dx):
    // its upper triangle, the rest after the loop
    const __m512d xa0 = -Vp * d0, xa1 = -Vp * d1, xa2 = -Vp * d2;
    s[16] += xa0 * g0;
    s[17] += xa0 * g1;
    s[18] += xa0 * g2;
    s[20] += xa1 * g1;
    s[21] += xa1 * g2;
    s[24] += xa2 * g2;
    s[25] += xa0 * w;
    s[26] += xa1 * w;
    s[27] += xa2 * w;
  }
  s[19] = s[17];
  s[22] = s[18];
  s[23] = s[21];
  reduce_add8(s, ak + B_A);
  reduce_add8(s + 8, ak + B_A + 8);
  reduce_add8(s + 16, ak + B_A + 16);
  for (int a = 24; a < 28; a++) ak[B_A + a] += _mm512_reduce_add_pd(s[a]);
}

}    // namespace

#endif

/* ----------------------------------------------------------------------
   the vector pass is usable in this force computation: set up for this
   run, the options still the ones it serves, the full list next to the
   half one
------------------------------------------------------------------------- */

bool PairESPHSolid::simd_ready() const
{
  // (a run with pre no after a pair_style that turned on an option the pass does not
  // serve has no init_style in between: the scalar loop then takes every pair)
  return simd_flag && simd_set && simd_physics() && listfull && list &&
      listfull->inum == list->inum;
}

/* ----------------------------------------------------------------------
   the slots of the rows (hq) that only the vector pass reads, for the
   ghost atoms (hoist() writes the owned atoms' with the rest of their
   rows): position, mass, body
------------------------------------------------------------------------- */

void PairESPHSolid::simd_pack()
{
  const int nlocal = atom->nlocal;
  const int nall = nlocal + atom->nghost;
  double **x = atom->x;
  const double *rmass = state->rmass;
  const int *body = state->body;
  double **const q = hq;
  ESPH::for_chunks(nthreads, nall - nlocal, [=](int from, int to, int) {
    for (int i = nlocal + from; i < nlocal + to; i++) {
      double *p = q[i];
      p[Q_X] = x[i][0];
      p[Q_X + 1] = x[i][1];
      p[Q_X + 2] = x[i][2];
      p[Q_M] = rmass[i];
      p[Q_BODY] = body ? body[i] : 0.0;
    }
  });
}

/* ----------------------------------------------------------------------
   the half list without its bulk pairs (the scalar loop's list), made
   anew with each new neighbour list: the pairs of a boundary and a real
   particle of one body, those across bodies
------------------------------------------------------------------------- */

void PairESPHSolid::simd_split(int bnd)
{
  const int sep = bnd && (contact != CONTACT_OFF);
  // the boundary-real pairs of one body go to the vector pass too (with the normal cones
  // their cone sums as well)
  simd_bnd = bnd;
  const int inum = list->inum;
  // made anew when the lists were built for this computation (neighbor->ago is 0 then, also
  // in a rerun, which sets ncalls back to 0 at each frame), after an init (a run with pre no
  // keeps the lists, not the bodies or types) or when the partners changed (the options, the
  // contact rule)
  const int key = sep + 2 * simd_bnd + 4 * contact;
  if (neighbor->ago > 0 && !simd_resplit && simd_sep == key &&
      (int) simd_first.size() == inum + 1 && (int) simd_nbulk.size() == atom->nlocal)
    return;
  simd_resplit = 0;
  simd_sep = key;
  const double *rmass = state->rmass;
  const int *body = state->body;
  const int *ilist = list->ilist;
  const int *numneigh = list->numneigh;
  int **firstneigh = list->firstneigh;
  simd_first.resize(inum + 1);
  simd_j.clear();
  for (int ii = 0; ii < inum; ii++) {
    simd_first[ii] = (int) simd_j.size();
    const int i = ilist[ii];
    const int ireal = rmass[i] > 0.0;
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < numneigh[i]; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int jreal = rmass[j] > 0.0;
      const int same = (body[j] == body[i]);
      // the vector pass's
      if (ireal && jreal && (!sep || same)) continue;
      // pairs the scalar loop skips: two boundary particles of one body (or with another
      // rule than contact solid), a boundary and a real particle of different bodies
      if (bnd && !ireal && !jreal && (contact != CONTACT_SOLID || same)) continue;
      if (bnd && (ireal != jreal) && (!same || simd_bnd)) continue;
      simd_j.push_back(jlist[jj]);
    }
  }
  simd_first[inum] = (int) simd_j.size();

  // the full list's neighbours of each particle in the order of the vector pass: first
  // the bulk partners of a real particle (the real particles of a boundary particle's
  // body), then (simd_bnd) the boundary particles of a real particle's body, then the
  // others, which the pass skips. In place (only the order within each particle's
  // neighbours changes; the half list was derived from it when both were built), unless
  // another style's list is a copy of it (compute centro/atom and the like pick their
  // nearest neighbours in the list's order): then into a copy of the pass's own
  simd_own = 0;
  for (int m = 0; m < neighbor->nlist; m++)
    if (neighbor->lists[m] && neighbor->lists[m] != listfull &&
        neighbor->lists[m]->listcopy == listfull)
      simd_own = 1;
  simd_own_first.assign(simd_own ? atom->nlocal : 0, 0);
  simd_own_j.clear();
  const int *ilistf = listfull->ilist;
  const int *numf = listfull->numneigh;
  int **firstf = listfull->firstneigh;
  simd_nbulk.assign(atom->nlocal, 0);
  simd_nbnd.assign(atom->nlocal, 0);
  std::vector<int> part[3];
  for (int ii = 0; ii < listfull->inum; ii++) {
    const int i = ilistf[ii];
    const int ireal = rmass[i] > 0.0;
    if (!ireal && !simd_bnd) continue;
    int *jlist = firstf[i];
    const int jnum = numf[i];
    for (auto &p : part) p.clear();
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const int jreal = rmass[j] > 0.0;
      const int same = (body[j] == body[i]);
      int cls = 2;
      if (ireal && jreal && (!sep || same))
        cls = 0;
      else if (ireal && simd_bnd && !jreal && same)
        cls = 1;
      else if (!ireal && jreal && same)
        cls = 0;
      part[cls].push_back(jlist[jj]);
    }
    if (simd_own) {
      simd_own_first[i] = (int) simd_own_j.size();
      for (int k = 0; k < 2; k++)
        simd_own_j.insert(simd_own_j.end(), part[k].begin(), part[k].end());
    } else {
      int n = 0;
      for (auto &p : part)
        for (const int j : p) jlist[n++] = j;
    }
    simd_nbulk[i] = (int) part[0].size();
    simd_nbnd[i] = (int) part[1].size();
  }
}

/* ----------------------------------------------------------------------
   the bulk pairs of the real particles of the half list's entries
   [iifrom, iito) (the rows of out are theirs), from the full list
------------------------------------------------------------------------- */

void PairESPHSolid::bulk_pass(LoopOut &out)
{
#ifdef ESPH_SIMD_AVX512
  const double *rmass = state->rmass;
  const int *ilist = list->ilist;
  int **firstneigh = listfull->firstneigh;
  const int *nbulk = simd_nbulk.data(), *nbnd = simd_nbnd.data();
  // the partners in the full list's own rows, or in the pass's copy (simd_split())
  const int *own_j = simd_own ? simd_own_j.data() : nullptr;
  const int *own_first = simd_own ? simd_own_first.data() : nullptr;
  auto partners = [&](int i) -> const int * {
    return own_j ? own_j + own_first[i] : firstneigh[i];
  };

  BulkCtx c;
  c.pk = hq[0];
  c.stride = hq_cols;
  c.hinv = 1.0 / h0;
  c.norm_hinv = kernel_norm(kernel, dim, h0) * c.hinv;
  c.h0 = h0;
  c.epsh2 = eps * h0 * h0;
  c.alpha = alpha;
  c.beta = beta;
  c.beta_ratio = (vswitch_flag && alpha > 0.0) ? beta / alpha : 0.0;
  c.fconv = units.force;
  c.recon = recon_flag;
  c.vswitch = vswitch_flag;
  c.heat = heat_flag;
  c.bnd = simd_bnd;
  c.solid = (contact == CONTACT_SOLID);
  c.cone = c.solid && (qcol_n >= 0);
  c.norm = kernel_norm(kernel, dim, h0);
  const int corr = (correct_flag == CORRECT_RATE);
  // the real particles' sums over their boundary particles only where needed (surface_sums())
  const int surf = surf_on;

  const int ncols = acc_cols;
  for (int ii = out.iifrom; ii < out.iito; ii++) {
    const int i = ilist[ii];
    // (the rows this particle's sums go to, a few particles ahead: esph_prefetch.h)
    if (ii + ESPH::PREFETCH_AHEAD < out.iito) {
      const int ip = ilist[ii + ESPH::PREFETCH_AHEAD];
      ESPH::prefetch_write(out.acc[ip], ncols);
      ESPH::prefetch_write(out.f[ip], 3);
    }
    if (!(rmass[i] > 0.0)) {
      if (c.bnd) bnd_atom(c, i, partners(i), nbulk[i], out.acc[i]);
      continue;
    }
    if (corr)
      bulk_atom<1>(c, i, partners(i), nbulk[i], surf ? nbnd[i] : 0, out.f[i], out.acc[i]);
    else
      bulk_atom<0>(c, i, partners(i), nbulk[i], surf ? nbnd[i] : 0, out.f[i], out.acc[i]);
  }
#else
  (void) out;
#endif
}
