// Residual forces and greatest direct stiffnesses (eq. 3.4) of every element
// at given positions: bars (eq. 3.32-3.35), spline-beam hinges
// (eq. 3.41-3.43) and 6-DOF beams (eq. 3.44-3.50). The integrators evaluate
// them at the step's positions and at their intermediate stages.
// Bars run chunk by chunk on the lean buffers of bar_chunks.hpp, on every
// thread; the other elements follow on one thread, in the model's order.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "physics/element_forces.hpp"
#include "physics/element_sinks.hpp"
#include "physics/numerical_errors.hpp"
#include "physics/simd_clones.hpp"
#include "physics/solver.hpp"
#include "physics/workers.hpp"

namespace tendril {

Solver::Solver(Model& model) : model_(model), workers_(std::make_unique<Workers>()) {}
Solver::~Solver() = default;

const BarChunks& Solver::bar_chunks() const {
  bar_chunks_.update(model_);
  return bar_chunks_;
}

namespace {

// Bars are evaluated in blocks: the chords are gathered, then one loop
// without memory indirection or branches (vectorised: `omp simd`, with
// -fno-math-errno and -fno-trapping-math so that square roots, divisions
// and selects stay in vectors) finds each bar's length, force on i and
// stiffness, then the forces are scattered. Per bar the arithmetic is
// exactly that of one bar at a time: T / L is divided once and, with the
// default geometric factor 1, g T / L is that same quotient (1 * T is T); a
// bar of no positive length (coincident or non-finite ends) gets a zero
// force, which adds nothing (scatter_bars).
constexpr std::uint32_t kBarBlock = BarChunks::kBlock;

struct BarBlock {
  alignas(64) double dx[kBarBlock], dy[kBarBlock], dz[kBarBlock];
  alignas(64) double fx[kBarBlock], fy[kBarBlock], fz[kBarBlock], s[kBarBlock];
};

// Eq. 3.32 (no tension in a slack cable), eq. 3.33's T / L and eq. 3.35,
// in three copies (simd_clones.hpp). Without cables (kCables false: none in
// the chunk) T is T0 and the cable column is not streamed. A block of bars
// that share their constants (kSame, BarChunks::same) reads the first's.
template <bool kUnitFactor, bool kCables, bool kSame>
TENDRIL_SIMD_CLONES void bar_block(BarBlock& b, std::uint32_t n, const double* __restrict k,
                                   const double* __restrict rest, const double* __restrict pre,
                                   const std::uint64_t* __restrict cable, double gf) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    const std::uint32_t at = kSame ? 0 : m;
    const double dx = b.dx[m], dy = b.dy[m], dz = b.dz[m];
    const double L = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double T0 = pre[at] + k[at] * (L - rest[at]);
    const double T = kCables && cable[at] && T0 < 0 ? 0.0 : T0;
    const double c = T / L;
    const double g = kUnitFactor ? c : gf * T / L;
    b.s[m] = k[at] + (L > 0 && T > 0 ? g : 0.0);
    b.fx[m] = L > 0 ? c * dx : 0.0;
    b.fy[m] = L > 0 ? c * dy : 0.0;
    b.fz[m] = L > 0 ? c * dz : 0.0;
  }
}

// bar_block's copy for the geometric factor (1: T / L once).
template <bool kCables, bool kSame>
inline void bar_block_for(bool unit_factor, BarBlock& b, std::uint32_t n, const double* k, const double* rest,
                          const double* pre, const std::uint64_t* cable, double gf) {
  if (unit_factor) bar_block<true, kCables, kSame>(b, n, k, rest, pre, cable, gf);
  else bar_block<false, kCables, kSame>(b, n, k, rest, pre, cable, gf);
}

// Spline-beam hinges the same way (eq. 3.41-3.43): the three chords
// gathered, one vectorised loop for lengths, stiffnesses and the two shear
// forces, then the scatter in the model's order. Term for term the
// arithmetic of hinge_forces (element_forces.hpp), Eigen's norm and cross
// written out in their order; a straight or degenerate hinge (no plane)
// gets +0 forces, as hinge_forces returns. Four divisions a hinge (the
// reciprocals of both links, of |a x b| and the curvature's), not twelve:
// the loop waited on the divider (stop 38, docs/performance.md).
constexpr std::uint32_t kHingeBlock = HingeChunks::kBlock;

struct HingeBlock {
  alignas(64) double ax[kHingeBlock], ay[kHingeBlock], az[kHingeBlock];
  alignas(64) double bx[kHingeBlock], by[kHingeBlock], bz[kHingeBlock];
  alignas(64) double cx[kHingeBlock], cy[kHingeBlock], cz[kHingeBlock];
  alignas(64) double EI[kHingeBlock], rest[kHingeBlock];
  alignas(64) double k[kHingeBlock], fix[kHingeBlock], fiy[kHingeBlock], fiz[kHingeBlock];
  alignas(64) double fkx[kHingeBlock], fky[kHingeBlock], fkz[kHingeBlock];
};

// EI and rest curvature are read from `stiffness` and `curvature` (the
// block's own copies, or the chunk's columns in place; kSame: a block of
// hinges that share them, HingeChunks::same, reads the first's).
template <bool kSame>
TENDRIL_SIMD_CLONES void hinge_block(HingeBlock& h, const double* __restrict stiffness,
                                     const double* __restrict curvature, std::uint32_t n) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    const std::uint32_t at = kSame ? 0 : m;
    const double ax = h.ax[m], ay = h.ay[m], az = h.az[m], bx = h.bx[m], by = h.by[m], bz = h.bz[m];
    const double cx = h.cx[m], cy = h.cy[m], cz = h.cz[m], EI = stiffness[at];
    const double La = std::sqrt(ax * ax + ay * ay + az * az), Lb = std::sqrt(bx * bx + by * by + bz * bz),
                 Lc = std::sqrt(cx * cx + cy * cy + cz * cz);
    const double inv_La = 1.0 / La, inv_Lb = 1.0 / Lb;
    const double ka = 4 * EI * (inv_La * inv_La * inv_La), kb = 4 * EI * (inv_Lb * inv_Lb * inv_Lb);
    h.k[m] = ka + kb;
    const double nx = ay * bz - az * by, ny = az * bx - ax * bz, nz = ax * by - ay * bx;  // a x b
    const double nn = std::sqrt(nx * nx + ny * ny + nz * nz);
    const bool bends = !(nn <= 0 || Lc <= 0);
    const double M = EI * (hinge_curvature(nn, inv_La, inv_Lb, Lc) - curvature[at]);
    // a x nrm and b x nrm, of norms La |nrm| and Lb |nrm|
    const double ux = ay * nz - az * ny, uy = az * nx - ax * nz, uz = ax * ny - ay * nx;
    const double vx = by * nz - bz * ny, vy = bz * nx - bx * nz, vz = bx * ny - by * nx;
    const double inv_nn = 1.0 / nn;
    const double Ma = M * (inv_La * inv_La * inv_nn), Mb = M * (inv_Lb * inv_Lb * inv_nn);
    h.fix[m] = bends ? Ma * ux : 0.0;
    h.fiy[m] = bends ? Ma * uy : 0.0;
    h.fiz[m] = bends ? Ma * uz : 0.0;
    h.fkx[m] = bends ? Mb * vx : 0.0;
    h.fky[m] = bends ? Mb * vy : 0.0;
    h.fkz[m] = bends ? Mb * vz : 0.0;
  }
}

// 6-DOF beams the same way (eq. 3.44-3.50): the chord and both nodes'
// frames gathered, then one vectorised loop, reading the beam-end
// orientations and the element's constants in place (Beam6Plan, in the
// order of evaluation), for each end's frame q * end (Eigen's
// SSE2 quaternion product, as beam6_ends computes it), the rotation
// matrices, the element frame, the included angles, the end moments, the
// forces and the direct stiffnesses, then the scatter in the model's order.
// Term for term the arithmetic of beam6_ends (element_forces.hpp): Eigen's
// quaternion product, toRotationMatrix, norm, dot and cross written out in
// their order. An element the loop cannot finish (no length, or ends whose
// mean z lies along the chord, where element_frame takes another axis) is
// marked and evaluated again by beam6_ends in the scatter. A block (of
// kBeam6Block, beam6_plan.hpp) inside a run of the same constants, or of the
// same beam-end frames, reads its first entry's.

// How far ahead beam6_forces asks for the plan's columns (two blocks), and
// from how many entries: with 40 000 (5.4 MB of plan, in this machine's
// caches) the prefetches cost 4 %, with 80 000 they gained 16 %.
constexpr std::uint32_t kBeam6Prefetch = 2 * kBeam6Block;
constexpr std::size_t kBeam6PrefetchFrom = std::size_t(1) << 16;

struct Beam6Block {
  alignas(64) double dx[kBeam6Block], dy[kBeam6Block], dz[kBeam6Block];
  alignas(64) double qix[kBeam6Block], qiy[kBeam6Block], qiz[kBeam6Block], qiw[kBeam6Block];  // q[i]
  alignas(64) double qjx[kBeam6Block], qjy[kBeam6Block], qjz[kBeam6Block], qjw[kBeam6Block];  // q[j]
  alignas(64) double k[kBeam6Block], kr[kBeam6Block], fx[kBeam6Block], fy[kBeam6Block], fz[kBeam6Block];
  alignas(64) double tax[kBeam6Block], tay[kBeam6Block], taz[kBeam6Block];
  alignas(64) double tbx[kBeam6Block], tby[kBeam6Block], tbz[kBeam6Block];
  alignas(64) double redo[kBeam6Block];  // 1: beam6_ends takes it (a double: a byte would keep the loop scalar)
};

// Eigen's quaternion product a * b for doubles with SSE2 (Geometry_SIMD.h's
// quat_product), then toRotationMatrix of it.
inline TENDRIL_INLINE void frame_matrix(double ax, double ay, double az, double aw, double bx, double by, double bz,
                                        double bw, double (&E)[3][3]) {
  const double x = (aw * bx + ay * bz) - (az * by - ax * bw);
  const double y = (aw * by + ay * bw) + (az * bx - ax * bz);
  const double z = (aw * bz - ay * bx) + (az * bw + ax * by);
  const double w = (aw * bw - ay * by) - (az * bz + ax * bx);
  const double tx = 2.0 * x, ty = 2.0 * y, tz = 2.0 * z;
  const double twx = tx * w, twy = ty * w, twz = tz * w, txx = tx * x, txy = ty * x, txz = tz * x;
  const double tyy = ty * y, tyz = tz * y, tzz = tz * z;
  E[0][0] = 1.0 - (tyy + tzz), E[0][1] = txy - twz, E[0][2] = txz + twy;
  E[1][0] = txy + twz, E[1][1] = 1.0 - (txx + tzz), E[1][2] = tyz - twx;
  E[2][0] = txz - twy, E[2][1] = tyz + twx, E[2][2] = 1.0 - (txx + tyy);
}

template <bool kSameConstants, bool kSameEnds>
TENDRIL_SIMD_CLONES void beam6_block(Beam6Block& b, const Beam6Plan& plan, std::uint32_t first, std::uint32_t n,
                                     double gf) {
  const double *__restrict eix = plan.end_i[0].data() + first, *__restrict eiy = plan.end_i[1].data() + first,
                           *__restrict eiz = plan.end_i[2].data() + first, *__restrict eiw = plan.end_i[3].data() + first;
  const double *__restrict ejx = plan.end_j[0].data() + first, *__restrict ejy = plan.end_j[1].data() + first,
                           *__restrict ejz = plan.end_j[2].data() + first, *__restrict ejw = plan.end_j[3].data() + first;
  const double *__restrict rest = plan.L.data() + first, *__restrict axial = plan.EA.data() + first,
                           *__restrict pre = plan.prestress.data() + first;
  const double *__restrict k_static = plan.k_static.data() + first, *__restrict kr = plan.kr.data() + first;
  const double *__restrict c_z = plan.cz.data() + first, *__restrict c_y = plan.cy.data() + first,
                           *__restrict torsion = plan.torsion.data() + first;
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    // The entry whose constants and ends are read: the block's first when
    // the block lies in a run of the same ones.
    const std::uint32_t c = kSameConstants ? 0 : m, o = kSameEnds ? 0 : m;
    const double L = rest[c], EA = axial[c];
    const double dx = b.dx[m], dy = b.dy[m], dz = b.dz[m];
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    const double N = pre[c] + EA * (l - L) / L;  // eq. 3.32 with K = EA / L
    b.k[m] = k_static[c] + (l > 0 && N > 0 ? gf * N / l : 0.0);  // eq. 3.47
    b.kr[m] = kr[c];                                             // eq. 3.49
    // Ea, Eb: the rotation matrices of q[i] * end_i and q[j] * end_j.
    double Ea[3][3], Eb[3][3];
    frame_matrix(b.qix[m], b.qiy[m], b.qiz[m], b.qiw[m], eix[o], eiy[o], eiz[o], eiw[o], Ea);
    frame_matrix(b.qjx[m], b.qjy[m], b.qjz[m], b.qjw[m], ejx[o], ejy[o], ejz[o], ejw[o], Eb);
    const double ux0 = dx / l, ux1 = dy / l, ux2 = dz / l;  // eq. 3.45
    // element_frame: y = (Ea z + Eb z) x ux, normalized; z = ux x y.
    const double s0 = Ea[0][2] + Eb[0][2], s1 = Ea[1][2] + Eb[1][2], s2 = Ea[2][2] + Eb[2][2];
    const double y0 = s1 * ux2 - s2 * ux1, y1 = s2 * ux0 - s0 * ux2, y2 = s0 * ux1 - s1 * ux0;
    const double yn = std::sqrt(y0 * y0 + y1 * y1 + y2 * y2);
    b.redo[m] = !(l > 0) || !(yn > 1e-12) ? 1.0 : 0.0;
    const double uy0 = y0 / yn, uy1 = y1 / yn, uy2 = y2 / yn;
    const double uz0 = ux1 * uy2 - ux2 * uy1, uz1 = ux2 * uy0 - ux0 * uy2, uz2 = ux0 * uy1 - ux1 * uy0;
    // Eq. 3.44.
    const double za = Ea[0][0] * uy0 + Ea[1][0] * uy1 + Ea[2][0] * uy2;
    const double zb = Eb[0][0] * uy0 + Eb[1][0] * uy1 + Eb[2][0] * uy2;
    const double ya = -(Ea[0][0] * uz0 + Ea[1][0] * uz1 + Ea[2][0] * uz2);
    const double yb = -(Eb[0][0] * uz0 + Eb[1][0] * uz1 + Eb[2][0] * uz2);
    const double twist = 0.5 * ((Eb[0][1] * Ea[0][2] + Eb[1][1] * Ea[1][2] + Eb[2][1] * Ea[2][2]) -
                                (Ea[0][1] * Eb[0][2] + Ea[1][1] * Eb[1][2] + Ea[2][1] * Eb[2][2]));
    // Eq. 3.46.
    const double cz = c_z[c], cy = c_y[c];
    const double Mza = cz * (2 * za + zb), Mzb = cz * (za + 2 * zb);
    const double Mya = cy * (2 * ya + yb), Myb = cy * (ya + 2 * yb);
    const double Mx = torsion[c] * twist;
    const double ta0 = Mx * ux0 - Mya * uy0 - Mza * uz0, ta1 = Mx * ux1 - Mya * uy1 - Mza * uz1,
                 ta2 = Mx * ux2 - Mya * uy2 - Mza * uz2;
    const double tb0 = -Mx * ux0 - Myb * uy0 - Mzb * uz0, tb1 = -Mx * ux1 - Myb * uy1 - Mzb * uz1,
                 tb2 = -Mx * ux2 - Myb * uy2 - Mzb * uz2;
    b.tax[m] = ta0, b.tay[m] = ta1, b.taz[m] = ta2;
    b.tbx[m] = tb0, b.tby[m] = tb1, b.tbz[m] = tb2;
    const double t0 = ta0 + tb0, t1 = ta1 + tb1, t2 = ta2 + tb2;
    b.fx[m] = (ux1 * t2 - ux2 * t1) / l - N * ux0;
    b.fy[m] = (ux2 * t0 - ux0 * t2) / l - N * ux1;
    b.fz[m] = (ux0 * t1 - ux1 * t0) / l - N * ux2;
  }
}

// One thread's hinges: elements items[0 .. count) (kShared) or 0 .. count,
// in the model's order, their forces added into the particles it owns.
// Returns the index of the first degenerate hinge (no plane can be found:
// a zero-length link), or kNone.
template <bool kShared>
std::uint32_t hinge_forces(const Hinge* hinges, const std::uint32_t* items, std::uint32_t count, Owned<kShared> own,
                           const Vec3* x, Vec3* F, double* S) {
  HingeBlock hb;
  for (std::uint32_t e0 = 0; e0 < count; e0 += kHingeBlock) {
    const std::uint32_t n = std::min(kHingeBlock, count - e0);
    for (std::uint32_t m = 0; m < n; ++m) {
      const Hinge& h = hinges[kShared ? items[e0 + m] : e0 + m];
      const Vec3 a = x[h.j] - x[h.i], b = x[h.k] - x[h.j], c = x[h.k] - x[h.i];
      hb.ax[m] = a.x(), hb.ay[m] = a.y(), hb.az[m] = a.z();
      hb.bx[m] = b.x(), hb.by[m] = b.y(), hb.bz[m] = b.z();
      hb.cx[m] = c.x(), hb.cy[m] = c.y(), hb.cz[m] = c.z();
      hb.EI[m] = h.EI;
      hb.rest[m] = h.rest_curvature;
    }
    hinge_block<false>(hb, hb.EI, hb.rest, n);
    for (std::uint32_t m = 0; m < n; ++m) {
      const std::uint32_t e = kShared ? items[e0 + m] : e0 + m;
      const Hinge& h = hinges[e];
      if (!std::isfinite(hb.k[m])) [[unlikely]]
        return e;
      const Vec3 fi(hb.fix[m], hb.fiy[m], hb.fiz[m]), fk(hb.fkx[m], hb.fky[m], hb.fkz[m]);
      if (own(h.j)) S[h.j] += hb.k[m];
      if (own(h.i)) F[h.i] += fi;
      if (own(h.k)) F[h.k] += fk;
      if (own(h.j)) F[h.j] -= fi + fk;
    }
  }
  return kNone;
}

// One thread's (or chunk's) 6-DOF elements, the plan's entries first ..
// first + count, in its order, into `out` (element_sinks.hpp), as
// hinge_forces adds. F - f is F + (-f) exactly.
template <bool kShared, class Sink>
TENDRIL_SIMD_CLONES void beam6_forces(const Beam6Plan& plan, const Beam6* beams, std::uint32_t first,
                                      std::uint32_t count, Owned<kShared> own, const Vec3* x, const Quat* q,
                                      double gf, Sink out) {
  const ParticleId *pi = plan.i.data(), *pj = plan.j.data();
  Beam6Block bb;
  for (std::uint32_t e0 = first; e0 < first + count; e0 += kBeam6Block) {
    const std::uint32_t n = std::min(kBeam6Block, first + count - e0);
    for (std::uint32_t m = 0; m < n; ++m) {
      const ParticleId i = pi[e0 + m], j = pj[e0 + m];
      const Vec3 d = x[j] - x[i];
      const Quat &qi = q[i], &qj = q[j];
      bb.dx[m] = d.x(), bb.dy[m] = d.y(), bb.dz[m] = d.z();
      bb.qix[m] = qi.x(), bb.qiy[m] = qi.y(), bb.qiz[m] = qi.z(), bb.qiw[m] = qi.w();
      bb.qjx[m] = qj.x(), bb.qjy[m] = qj.y(), bb.qjz[m] = qj.z(), bb.qjw[m] = qj.w();
    }
    // A block inside a run of the same constants, or of the same ends, reads
    // them once (Beam6Plan::same_*_to): a member's elements share them.
    const bool same_constants = plan.same_constants(e0, n), same_ends = plan.same_ends(e0, n);
    // The plan's columns two blocks ahead that beam6_block will read in
    // place: the hardware's own prefetching falls behind on sixteen streams
    // at once (the 100K 6-DOF grid waited on them). Written here, not in a
    // function of their own: GCC compiled such a function to a bare return.
    const std::size_t entries = plan.L.size();
    if (const std::uint32_t ahead = e0 + kBeam6Prefetch;
        entries >= kBeam6PrefetchFrom && std::size_t(ahead) + kBeam6Block <= entries) {
      if (!plan.same_ends(ahead, kBeam6Block))
        for (const double* column : plan.end_columns())
          for (std::uint32_t m = 0; m < kBeam6Block; m += 8) __builtin_prefetch(column + ahead + m, 0, 2);  // 8 a line
      if (!plan.same_constants(ahead, kBeam6Block))
        for (const double* column : plan.constant_columns())
          for (std::uint32_t m = 0; m < kBeam6Block; m += 8) __builtin_prefetch(column + ahead + m, 0, 2);
    }
    if (same_constants) {
      if (same_ends) beam6_block<true, true>(bb, plan, e0, n, gf);
      else beam6_block<true, false>(bb, plan, e0, n, gf);
    } else {
      if (same_ends) beam6_block<false, true>(bb, plan, e0, n, gf);
      else beam6_block<false, false>(bb, plan, e0, n, gf);
    }
    for (std::uint32_t m = 0; m < n; ++m) {
      const ParticleId i = pi[e0 + m], j = pj[e0 + m];
      Beam6Ends r;
      if (bb.redo[m] != 0) [[unlikely]] {
        r = beam6_ends(beams[plan.element(e0 + m)], x, q, gf);
      } else {
        r.k = bb.k[m], r.kr = bb.kr[m];
        r.fj = Vec3(bb.fx[m], bb.fy[m], bb.fz[m]);
        r.ta = Vec3(bb.tax[m], bb.tay[m], bb.taz[m]);
        r.tb = Vec3(bb.tbx[m], bb.tby[m], bb.tbz[m]);
      }
      const bool own_i = own(i), own_j = own(j);
      // Each lane of an end takes one addition (i != j), so its force and
      // stiffness go together: the element pass's sums, bit for bit.
      if (own_i) out.force_stiffness(i, -r.fj, r.k);
      if (own_j) out.force_stiffness(j, r.fj, r.k);
      if (own_i) out.torque_stiffness(i, r.ta, r.kr);
      if (own_j) out.torque_stiffness(j, r.tb, r.kr);
    }
  }
}

// A chunk's bars into its particles' sums (indexed from the chunk's first
// id): an interior bar into both ends, a crossing one into i and, when
// `slots` is set, its slot. A bar of no length adds f = +0, which leaves a
// sum as skipping its force did, but for the sign of a zero (only a -0
// load component plus a -0 weight gives a -0 sum). S - (-s) is S + s
// exactly, so the stiffness rides in the fourth lane of j's subtraction.
TENDRIL_SIMD_CLONES void scatter_bars(const BarBlock& b, std::uint32_t n, std::uint32_t interior,
                                      const ParticleId* __restrict bi, const ParticleId* __restrict bj, ParticleId base,
                                      ForceSum* __restrict sums, Vec3* slot_f, double* slot_s) {
  const ForceSum flip = {1.0, 1.0, 1.0, -1.0};
  // Four bars' columns turned into their rows at once, then added bar after
  // bar, end after end, as one bar at a time adds them.
  std::uint32_t m = 0;
  for (; m + 4 <= interior; m += 4) {
    ForceSum r[4];
    __builtin_memcpy(&r[0], b.fx + m, sizeof(ForceSum));
    __builtin_memcpy(&r[1], b.fy + m, sizeof(ForceSum));
    __builtin_memcpy(&r[2], b.fz + m, sizeof(ForceSum));
    __builtin_memcpy(&r[3], b.s + m, sizeof(ForceSum));
    transpose(r[0], r[1], r[2], r[3]);
#pragma GCC unroll 4
    for (std::uint32_t l = 0; l < 4; ++l) {
      sums[bi[m + l] - base] += r[l];
      sums[bj[m + l] - base] -= r[l] * flip;
    }
  }
  for (; m < interior; ++m) {
    const ForceSum r = {b.fx[m], b.fy[m], b.fz[m], b.s[m]};
    sums[bi[m] - base] += r;
    sums[bj[m] - base] -= r * flip;
  }
  for (std::uint32_t m = interior; m < n; ++m) {  // j is another chunk's: its share waits in the slot
    const ForceSum r = {b.fx[m], b.fy[m], b.fz[m], b.s[m]};
    sums[bi[m] - base] += r;
    if (slot_f) {
      slot_f[m - interior] = Vec3(b.fx[m], b.fy[m], b.fz[m]);
      slot_s[m - interior] = b.s[m];
    }
  }
}

// A block of a chunk's hinges into its particles' sums (chunk_hinge_sums),
// compiled as scatter_bars is, so that each end takes one 4-lane load,
// addition and store; returns how many it added, stopping at the first
// hinge that cannot be evaluated.
TENDRIL_SIMD_CLONES std::uint32_t scatter_hinges(const HingeBlock& hb, std::uint32_t n, const ParticleId* __restrict hi,
                                                 const ParticleId* __restrict hj, const ParticleId* __restrict hk,
                                                 Owned<true> own, ForceSum* __restrict sums) {
  const ParticleId base = own.lo;
  // Four hinges' columns turned into their rows at once, then added hinge
  // after hinge, end after end, as the loop below adds them; a group with a
  // stiffness that is not finite is left to that loop, which stops there.
  std::uint32_t m = 0;
  for (; m + 4 <= n; m += 4) {
    Lanes k, ri[4], rk[4];
    __builtin_memcpy(&k, hb.k + m, sizeof(Lanes));
    const Lanes finite = k - k;  // 0 where k is finite, NaN elsewhere
    if (!(finite[0] == 0 && finite[1] == 0 && finite[2] == 0 && finite[3] == 0)) [[unlikely]]
      break;
    __builtin_memcpy(&ri[0], hb.fix + m, sizeof(Lanes));
    __builtin_memcpy(&ri[1], hb.fiy + m, sizeof(Lanes));
    __builtin_memcpy(&ri[2], hb.fiz + m, sizeof(Lanes));
    ri[3] = Lanes{0, 0, 0, 0};
    transpose(ri[0], ri[1], ri[2], ri[3]);
    __builtin_memcpy(&rk[0], hb.fkx + m, sizeof(Lanes));
    __builtin_memcpy(&rk[1], hb.fky + m, sizeof(Lanes));
    __builtin_memcpy(&rk[2], hb.fkz + m, sizeof(Lanes));
    rk[3] = Lanes{0, 0, 0, 0};
    transpose(rk[0], rk[1], rk[2], rk[3]);
#pragma GCC unroll 4
    for (std::uint32_t l = 0; l < 4; ++l) {
      const ParticleId i = hi[m + l], j = hj[m + l], kk = hk[m + l];
      if (own(i)) sums[i - base] += ri[l];
      if (own(kk)) sums[kk - base] += rk[l];
      if (own(j)) {
        Lanes rj = ri[l] + rk[l];
        rj[3] = -k[l];
        sums[j - base] -= rj;
      }
    }
  }
  for (; m < n; ++m) {
    if (!std::isfinite(hb.k[m])) [[unlikely]]
      return m;
    const ParticleId i = hi[m], j = hj[m], k = hk[m];
    if (own(i)) sums[i - base] += ForceSum{hb.fix[m], hb.fiy[m], hb.fiz[m], 0.0};
    if (own(k)) sums[k - base] += ForceSum{hb.fkx[m], hb.fky[m], hb.fkz[m], 0.0};
    if (own(j))
      sums[j - base] -= ForceSum{hb.fix[m] + hb.fkx[m], hb.fiy[m] + hb.fky[m], hb.fiz[m] + hb.fkz[m], -hb.k[m]};
  }
  return n;
}

// Each thread's sums of the chunk it evaluated last, named by the pass and
// the chunk: a chunk's late part on the same thread right after its body
// finds them. A chunk whose late part waits for the end of its thread's
// range (for_chunks) keeps its sums in a second scratch, so that they are
// still there; one whose sums are gone (or run on another thread)
// evaluates the chunk's bars again, the same numbers, its slots untouched.
struct ChunkSumsScratch {
  std::uint64_t pass = 0;
  std::uint32_t chunk = 0;
  // alignas in a struct: the allocator ignores a vector type's own
  // alignment, and the sums are stored with aligned 32-byte moves.
  struct alignas(32) Slot {
    ForceSum sum;
  };
  std::vector<Slot> sums;
  ForceSum* data() { return &sums.data()->sum; }
};
thread_local ChunkSumsScratch chunk_sums_scratch[2];  // [1]: a chunk whose late part waits
std::atomic<std::uint64_t> chunk_passes{0};

// Whether chunk c's late part waits for the end of its thread's range under
// the split `first` (for_chunks): its inbox draws on an earlier range.
bool late_waits(const BarChunks& B, const std::vector<std::uint32_t>& first, std::uint32_t c) {
  std::size_t t = 0;
  while (t + 2 < first.size() && first[t + 1] <= c) ++t;
  return t + 1 < first.size() && B.chunks[c].first_source < first[t];
}

}  // namespace

std::uint64_t Solver::new_chunk_pass() { return ++chunk_passes; }

TENDRIL_SIMD_CLONES ForceSum* Solver::chunk_bar_sums(std::uint32_t chunk, const Vec3* x, std::uint64_t pass,
                                                  bool fill_slots) const {
  const BarChunks& B = bar_chunks_;
  const BarChunks::Chunk& c = B.chunks[chunk];
  // Under the last split over threads (stale when none: a scratch used in
  // vain).
  ChunkSumsScratch& scratch = chunk_sums_scratch[late_waits(B, chunk_balance_.first(), chunk) ? 1 : 0];
  const std::size_t chunk_size = std::size_t(1) << B.shift;
  if (scratch.sums.size() < chunk_size) scratch.sums.resize(chunk_size);
  ForceSum* sums = scratch.data();
  const ParticleId base = ParticleId(chunk) << B.shift;
  const Particles& P = model_.particles;
  const Vec3 g = model_.gravity;
  const Vec3* load = P.load.data();
  const double *point_mass = P.point_mass.data(), *lumped_mass = P.lumped_mass.data();
  // Without gravity the weight m * (+0) is a zero (masses are finite), so
  // load + 0 gives the same values without streaming the masses (at most
  // the sign of a zero component differs, where rounding left a lumped mass
  // a hair below zero).
  const bool weightless = g.x() == 0 && g.y() == 0 && g.z() == 0 && !std::signbit(g.x()) &&
                          !std::signbit(g.y()) && !std::signbit(g.z());
  if (weightless)
    for (std::uint32_t n = c.particles_begin; n < c.particles_end; ++n) {
      const ParticleId p = B.particles[n];
      const Vec3 f = load[p] + Vec3::Zero();
      sums[p - base] = ForceSum{f.x(), f.y(), f.z(), 0.0};
    }
  else
    for (std::uint32_t n = c.particles_begin; n < c.particles_end; ++n) {
      const ParticleId p = B.particles[n];
      const Vec3 f = load[p] + (point_mass[p] + lumped_mass[p]) * g;
      sums[p - base] = ForceSum{f.x(), f.y(), f.z(), 0.0};
    }
  const double gf = settings.geometric_factor;
  const bool unit_factor = gf == 1;
  const ParticleId *bi = B.i.data(), *bj = B.j.data();
  BarBlock b;
  for (std::uint32_t e0 = c.bars_begin; e0 < c.bars_end; e0 += kBarBlock) {
    const std::uint32_t n = std::min(kBarBlock, c.bars_end - e0);
    for (std::uint32_t m = 0; m < n; ++m) {
      const Vec3 d = x[bj[e0 + m]] - x[bi[e0 + m]];
      b.dx[m] = d.x();
      b.dy[m] = d.y();
      b.dz[m] = d.z();
    }
    const double *k = B.k.data() + e0, *rest = B.rest.data() + e0, *pre = B.prestress.data() + e0;
    const std::uint64_t* cable = B.cable.data() + e0;
    const bool same = B.same_block(c, e0);
    if (c.cables) {
      if (same) bar_block_for<true, true>(unit_factor, b, n, k, rest, pre, cable, gf);
      else bar_block_for<true, false>(unit_factor, b, n, k, rest, pre, cable, gf);
    } else {
      if (same) bar_block_for<false, true>(unit_factor, b, n, k, rest, pre, cable, gf);
      else bar_block_for<false, false>(unit_factor, b, n, k, rest, pre, cable, gf);
    }
    // The block's interior bars [0, interior), then its crossing ones.
    const std::uint32_t interior = std::clamp(c.crossing_begin, e0, e0 + n) - e0;
    const std::uint32_t first_slot = c.slot_begin + (e0 + interior - c.crossing_begin);
    const bool crossing = fill_slots && interior < n;
    scatter_bars(b, n, interior, bi + e0, bj + e0, base, sums,
                 crossing ? bar_chunks_.slot_force.data() + first_slot : nullptr,
                 crossing ? bar_chunks_.slot_stiffness.data() + first_slot : nullptr);
  }
  scratch.pass = pass;
  scratch.chunk = chunk;
  return sums;
}

TENDRIL_SIMD_CLONES ForceSum* Solver::chunk_force_sums(std::uint32_t chunk, const Vec3* x,
                                                    std::uint64_t pass) const {
  ForceSum* sums = nullptr;
  for (ChunkSumsScratch& scratch : chunk_sums_scratch)
    if (scratch.pass == pass && scratch.chunk == chunk) sums = scratch.data();
  if (!sums) sums = chunk_bar_sums(chunk, x, pass, false);
  const BarChunks& B = bar_chunks_;
  const BarChunks::Chunk& c = B.chunks[chunk];
  const ParticleId base = ParticleId(chunk) << B.shift;
  for (std::uint32_t n = c.inbox_begin; n < c.inbox_end; ++n) {
    const Vec3& f = B.slot_force[B.inbox_slot[n]];
    sums[B.inbox_particle[n] - base] -= ForceSum{f.x(), f.y(), f.z(), -B.slot_stiffness[B.inbox_slot[n]]};
  }
  return sums;
}

const HingeChunks& Solver::hinge_chunks() const {
  const BarChunks& B = bar_chunks();
  hinge_chunks_.update(model_, B.shift, B.chunks.size());
  return hinge_chunks_;
}

// hinge_forces' arithmetic and order into a chunk's sums: per particle its
// hinges in the model's order, i's and k's pull then j's, whose stiffness
// rides in the fourth lane (S - (-k) is S + k exactly; the + 0 added to i's
// and k's is exact too, a sum that starts at +0 never being -0).
TENDRIL_SIMD_CLONES std::uint32_t Solver::chunk_hinge_sums(std::uint32_t chunk, const Vec3* x, ForceSum* sums) const {
  const HingeChunks& H = hinge_chunks_;
  const std::uint32_t shift = bar_chunks_.shift;
  const ParticleId base = ParticleId(chunk) << shift;
  const Owned<true> own{base, base + (ParticleId(1) << shift)};
  const ParticleId *hi = H.i.data(), *hj = H.j.data(), *hk = H.k.data();
  const std::uint32_t first = H.begin[chunk], last = H.end[chunk];
  HingeBlock hb;
  for (std::uint32_t e0 = first; e0 < last; e0 += kHingeBlock) {
    const std::uint32_t n = std::min(kHingeBlock, last - e0);
    for (std::uint32_t m = 0; m < n; ++m) {
      const std::uint32_t e = e0 + m;
      const Vec3 a = x[hj[e]] - x[hi[e]], b = x[hk[e]] - x[hj[e]], c = x[hk[e]] - x[hi[e]];
      hb.ax[m] = a.x(), hb.ay[m] = a.y(), hb.az[m] = a.z();
      hb.bx[m] = b.x(), hb.by[m] = b.y(), hb.bz[m] = b.z();
      hb.cx[m] = c.x(), hb.cy[m] = c.y(), hb.cz[m] = c.z();
    }
    if (H.same_block(chunk, e0))
      hinge_block<true>(hb, H.EI.data() + e0, H.rest.data() + e0, n);
    else
      hinge_block<false>(hb, H.EI.data() + e0, H.rest.data() + e0, n);
    const std::uint32_t done = scatter_hinges(hb, n, hi + e0, hj + e0, hk + e0, own, sums);
    if (done < n) [[unlikely]]
      return H.hinge[e0 + done];
  }
  return kNone;
}

const std::vector<ParticleId>& Solver::chunk_bounds() const {
  const BarChunks& B = bar_chunks();
  chunk_bound_.resize(B.chunks.size() + 1);
  for (std::size_t c = 0; c < chunk_bound_.size(); ++c) chunk_bound_[c] = ParticleId(c) << B.shift;
  return chunk_bound_;
}

void Solver::prepare_beam6_chunks() const {
  beam6_plan_.update(model_);
  const Beam6Plan& plan = beam6_plan_;
  const BarChunks& B = bar_chunks();
  beam6_chunks_.update(plan, B.shift, B.chunks.size());
  const std::vector<ParticleId>& bound = chunk_bounds();
  // The rotating particles' shares follow their list's own edits (an
  // element bound again may move a particle in it without moving the
  // plan's generation).
  Particles& P = model_.particles;
  const std::vector<ParticleId>& rotating = P.rotational.raw();
  if (!rotating_chunk_shares_.follow(0, bound) || !P.rotational_edits.clean_since(rotating_caught_up_)) {
    P.rotational_edits.restart(model_.revision);
    rotating_caught_up_ = model_.revision;
    rotating_chunk_shares_.derive(0, bound, std::uint32_t(rotating.size()), [&](std::uint32_t e, ParticleId* at) {
      at[0] = rotating[e];
      return 1;
    });
    rotating_by_chunk_.resize(rotating_chunk_shares_.items.size());
    for (std::size_t k = 0; k < rotating_by_chunk_.size(); ++k)
      rotating_by_chunk_[k] = rotating[rotating_chunk_shares_.items[k]];
  }
}

namespace {
// Each thread's torque sums of the chunk it evaluated last (as its force
// sums, ChunkSumsScratch).
thread_local std::vector<ChunkSumsScratch::Slot> chunk_turns_scratch;
}  // namespace

TENDRIL_SIMD_CLONES ForceSum* Solver::chunk_beam6_sums(std::uint32_t chunk, const Vec3* x, const Quat* q,
                                                    ForceSum* sums) const {
  const std::uint32_t shift = bar_chunks_.shift;
  const ParticleId base = ParticleId(chunk) << shift;
  if (chunk_turns_scratch.size() < (std::size_t(1) << shift)) chunk_turns_scratch.resize(std::size_t(1) << shift);
  ForceSum* turns = &chunk_turns_scratch.data()->sum;
  // The torques start at the moments, the rotational stiffnesses at 0.
  const Vec3* moment = model_.particles.moment.data();
  const ElementShares& rot = rotating_chunk_shares_;
  for (std::uint32_t k = rot.begin[chunk]; k < rot.begin[chunk + 1]; ++k) {
    const ParticleId p = rotating_by_chunk_[k];
    turns[p - base] = ForceSum{moment[p].x(), moment[p].y(), moment[p].z(), 0.0};
  }
  const Beam6Chunks& B = beam6_chunks_;
  const Owned<true> own{base, base + (ParticleId(1) << shift)};
  beam6_forces<true>(B.plan, model_.beam6s.awake_begin(), B.begin[chunk], B.end[chunk] - B.begin[chunk], own, x,
                     q, settings.geometric_factor,
                     ChunkSink{sums, base, turns});
  return turns;
}

unsigned Solver::element_threads() const {
  const std::uint32_t n = std::uint32_t(bar_chunks().chunks.size());
  return unsigned(std::clamp<std::uint32_t>(std::uint32_t(settings.threads), 1, n));
}

bool Solver::elements_on_threads() const {
  const Model& m = model_;
  const std::size_t elements = m.bars.awake + m.hinges.awake + m.beam6s.awake + m.csts.awake;
  return elements >= element_threads_from && element_threads() > 1;
}

const std::vector<ParticleId>& Solver::element_bounds() const {
  const BarChunks& B = bar_chunks();
  const unsigned threads = element_threads();
  const std::vector<std::uint32_t>& first = owner_split_.split(B, threads);  // never measured: equal shares
  element_bound_.resize(threads + 1);
  for (unsigned t = 0; t <= threads; ++t) element_bound_[t] = ParticleId(first[t]) << B.shift;
  return element_bound_;
}

void Solver::for_chunks(FunctionRef<void(std::uint32_t)> body, FunctionRef<void(std::uint32_t)> late,
                        bool threaded) const {
  const BarChunks& B = bar_chunks_;
  const std::uint32_t n = std::uint32_t(B.chunks.size());
  const unsigned threads = threaded ? unsigned(std::clamp<std::uint32_t>(std::uint32_t(settings.threads), 1, n)) : 1;
  if (threads == 1) {
    for (std::uint32_t c = 0; c < n; ++c) {
      body(c);
      late(c);
    }
    return;
  }
  const std::vector<std::uint32_t>& first = chunk_balance_.split(B, threads);
  // A chunk whose inbox draws on an earlier thread's range waits, after
  // its own thread's range, for the bodies of those chunks (each marks its
  // end with this pass's round): no second run over the threads.
  if (chunk_done_.size() < n) chunk_done_ = std::vector<std::atomic<std::uint64_t>>(n);
  thread_busy_.assign(threads, 0.0);
  const std::uint64_t round = ++chunk_round_;
  auto mark_done = [&](std::uint32_t k) {
    chunk_done_[k].store(round, std::memory_order_release);
    chunk_done_[k].notify_all();
  };
  using Clock = std::chrono::steady_clock;
  workers_->run(threads, [&](unsigned t) {
    const Clock::time_point start = Clock::now();
    bool deferred = false;
    try {
      for (std::uint32_t k = first[t]; k < first[t + 1]; ++k) {
        body(k);
        mark_done(k);
        if (!late_waits(B, first, k)) late(k);
        else deferred = true;
      }
    } catch (...) {  // no thread may wait for a body that never ends
      for (std::uint32_t k = first[t]; k < first[t + 1]; ++k) mark_done(k);
      throw;
    }
    Clock::duration waited{};
    for (std::uint32_t k = first[t]; deferred && k < first[t + 1]; ++k) {
      if (!late_waits(B, first, k)) continue;
      const Clock::time_point wait = Clock::now();
      for (std::uint32_t c = B.chunks[k].first_source; c < first[t]; ++c) wait_for(chunk_done_[c], round);
      waited += Clock::now() - wait;
      late(k);
    }
    thread_busy_[t] = std::chrono::duration<double>(Clock::now() - start - waited).count();
  });
  chunk_balance_.measured(B, thread_busy_);
}

void Solver::for_chunks(FunctionRef<void(std::uint32_t)> body) const {
  for_chunks(body, [](std::uint32_t) {});
}

void Solver::accumulate_forces(const Vec3* x, const Quat* q, Vec3* F, double* S, Vec3* T, double* K) const {
  const Particles& P = model_.particles;
  const BarChunks& B = bar_chunks();
  const std::uint64_t pass = new_chunk_pass();
  const bool threaded = elements_on_threads();
  for_chunks([&](std::uint32_t c) { chunk_bar_sums(c, x, pass, true); },
             [&](std::uint32_t c) {
               const ForceSum* sums = chunk_force_sums(c, x, pass);
               const BarChunks::Chunk& ch = B.chunks[c];
               const ParticleId base = ParticleId(c) << B.shift;
               for (std::uint32_t n = ch.particles_begin; n < ch.particles_end; ++n) {
                 const ParticleId p = B.particles[n];
                 const ForceSum& f = sums[p - base];
                 F[p] = Vec3(f[0], f[1], f[2]);
                 S[p] = f[3];
               }
             },
             threaded);
  for (ParticleId p : P.rotational.raw()) {
    T[p] = P.moment[p];
    K[p] = 0;
  }
  const double gf = settings.geometric_factor;
  // Only awake elements: those touching a passive particle (multi-
  // resolution, thesis 5.5.2.3) sit behind ElementBuffer::awake, unvisited.
  const Hinge* hinges = model_.hinges.awake_begin();
  const std::uint32_t n_hinges = std::uint32_t(model_.hinges.awake_end() - hinges);
  const Beam6* beam6s = model_.beam6s.awake_begin();
  const std::uint32_t n_beam6s = std::uint32_t(model_.beam6s.awake_end() - beam6s);
  if (n_beam6s > 0) beam6_plan_.update(model_);
  const Beam6Plan& plan = beam6_plan_;
  if (n_hinges + n_beam6s > 0 && threaded) {
    // On threads: each adds into the particles it owns (ElementShares).
    const std::vector<ParticleId>& bound = element_bounds();
    const unsigned threads = unsigned(bound.size()) - 1;
    if (n_hinges > 0 && !hinge_shares_.current(model_.revision, bound))
      hinge_shares_.derive(model_.revision, bound, n_hinges, [&](std::uint32_t e, ParticleId* at) {
        at[0] = hinges[e].i, at[1] = hinges[e].j, at[2] = hinges[e].k;
        return 3;
      });
    if (n_beam6s > 0) {
      const bool shares_current = beam6_shares_.current(plan.generation(), bound);
      if (!shares_current)
        beam6_shares_.derive(plan.generation(), bound, n_beam6s, [&](std::uint32_t e, ParticleId* at) {
          at[0] = plan.i[e], at[1] = plan.j[e];
          return 2;
        });
      if (!shares_current || !beam6_thread_plan_.follow(plan)) beam6_thread_plan_.derive(plan, beam6_shares_.items);
    }
    std::vector<std::uint32_t>& bad = thread_bad_hinge_;
    bad.assign(threads, kNone);
    workers_->run(threads, [&](unsigned t) {
      const Owned<true> own{bound[t], bound[t + 1]};
      if (n_hinges > 0) {
        const ElementShares& sh = hinge_shares_;
        bad[t] = hinge_forces<true>(hinges, sh.items.data() + sh.begin[t], sh.begin[t + 1] - sh.begin[t], own, x, F,
                                    S);
        if (bad[t] != kNone) return;
      }
      if (n_beam6s > 0) {
        const ElementShares& sh = beam6_shares_;
        beam6_forces<true>(beam6_thread_plan_, beam6s, sh.begin[t], sh.begin[t + 1] - sh.begin[t], own, x, q, gf,
                           ModelSink{F, S, T, K});
      }
    });
    const std::uint32_t first_bad = *std::min_element(bad.begin(), bad.end());
    if (first_bad != kNone) [[unlikely]]
      throw_degenerate_hinge(model_, hinges[first_bad], x);  // a zero-length link (coincident particles): stop, naming them
  } else {
    const std::uint32_t bad = hinge_forces<false>(hinges, nullptr, n_hinges, {}, x, F, S);
    if (bad != kNone) [[unlikely]]
      throw_degenerate_hinge(model_, hinges[bad], x);  // a zero-length link (coincident particles): stop, naming them
    if (n_beam6s > 0) beam6_forces<false>(plan, beam6s, 0, n_beam6s, {}, x, q, gf, ModelSink{F, S, T, K});
  }
  accumulate_couples(x, F);  // moments on 3-DOF particles (couples.cpp)
  for (Dart d : model_.clamp_darts.raw()) {  // clamped 3-DOF beam ends (Model::set_clamp)
    if (!model_.clamp_acts(d)) continue;
    const ParticleId p = model_.dart_particle[d], q = model_.dart_particle[model_.map.alpha(0, d)];
    if (!(P.active[p] & P.active[q])) continue;  // dormant, like an element touching a passive particle
    const ClampForces f = clamp_forces(model_.clamp[d], model_.blocks[model_.dart_block[d]].section.EI, x[p], x[q]);
    F[q] += f.fq;
    F[p] -= f.fq;
    S[p] += f.k;
    S[q] += f.k;
  }
  for (const RigidJoint& j : model_.rigid_joints.raw()) {  // rigid joints of 3-DOF beams (Model::set_joint)
    if (!model_.rigid_acts(j)) continue;
    const ParticleId p = model_.dart_particle[j.a];
    const ParticleId a = model_.dart_particle[model_.map.alpha(0, j.a)], b = model_.dart_particle[model_.map.alpha(0, j.b)];
    if (!(P.active[p] & P.active[a] & P.active[b])) continue;  // dormant, like an element touching a passive particle
    const RigidJointForces f = rigid_joint_forces(model_.rigid_stiffness(j), j.angle, x[p], x[a], x[b]);
    F[a] += f.fa;
    F[b] += f.fb;
    F[p] -= f.fa + f.fb;
    S[a] += f.ka;
    S[b] += f.kb;
    S[p] += f.ka + f.kb;
  }
  if (!model_.joints.items.empty()) accumulate_joint_forces(x, F, S);
  if (!model_.goals.empty()) accumulate_goal_forces(x, F, S);
  if (!model_.csts.items.empty()) accumulate_cst_forces(x, F, S);
  accumulate_pressure_forces(x, F, S);
}

}  // namespace tendril
