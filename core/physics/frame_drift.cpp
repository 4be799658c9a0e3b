// The frames' drift in vectorised blocks (frame_drift.hpp): per particle
// the rotation vector r = dt w and its squared angle; then, in loops without
// branches, the angle, the sine and cosine of half of it by polynomials
// (model/half_angle.hpp; a lane beyond their bound takes libm's, one at a
// time), the rotation's quaternion, its product with the frame and the
// normalization, written out as Eigen computes them with SSE2
// (Geometry_SIMD.h's quat_product, a 4-vector's squaredNorm as
// (x x + z z) + (y y + w w)), so the frames are those of rotation_of and
// Quaternion::normalized bit for bit (tests/physics/test_beam6_block.cpp).
// A rotation below rotation_of's small-angle bound takes its (1, r / 2) in
// the same loop: near equilibrium, or at the start of a run, that is most
// frames, and one at a time through rotation_of they cost the 100K 6-DOF grid
// a quarter of its step (docs/performance.md, stop 38).
#include "physics/frame_drift.hpp"

#include <algorithm>
#include <cmath>

#include "model/frames.hpp"
#include "model/half_angle.hpp"
#include "physics/simd_clones.hpp"

namespace tendril {

namespace {

constexpr std::uint32_t kFrameBlock = 64;

struct FrameBlock {
  alignas(64) double rx[kFrameBlock], ry[kFrameBlock], rz[kFrameBlock], theta[kFrameBlock];
  alignas(64) double small[kFrameBlock];  // 1: below rotation_of's small-angle bound (a double, to stay in vectors)
  alignas(64) double sin_half[kFrameBlock], cos_half[kFrameBlock];
  alignas(64) double qx[kFrameBlock], qy[kFrameBlock], qz[kFrameBlock], qw[kFrameBlock];
};

// theta holds the squared angles on entry, the angles on return; rotation_of's
// half_angle_sincos, the polynomial in every lane and libm's where the half
// angle is beyond the polynomials' bound (or not a number).
TENDRIL_SIMD_CLONES void half_angles(FrameBlock& f, std::uint32_t n) {
  double beyond = 0;  // how many lanes are beyond: a count of 64 at most, exact
#pragma omp simd reduction(+ : beyond)
  for (std::uint32_t m = 0; m < n; ++m) {
    f.small[m] = f.theta[m] < kSmallAngle2 ? 1.0 : 0.0;
    const double theta = std::sqrt(f.theta[m]);
    const double h = 0.5 * theta;
    double s, c;
    half_angle_poly(h, s, c);
    f.theta[m] = theta, f.sin_half[m] = s, f.cos_half[m] = c;
    beyond += h <= kHalfAngleBound ? 0.0 : 1.0;
  }
  if (beyond == 0) return;
  for (std::uint32_t m = 0; m < n; ++m) {
    const double h = 0.5 * f.theta[m];
    if (!(h <= kHalfAngleBound)) half_angle_sincos(h, f.sin_half[m], f.cos_half[m]);
  }
}

TENDRIL_SIMD_CLONES void frame_block(FrameBlock& f, std::uint32_t n) {
#pragma omp simd
  for (std::uint32_t m = 0; m < n; ++m) {
    // a = rotation_of(r): below the small-angle bound (1, r / 2), which
    // rotation_of normalizes by exactly 1; b = the frame; Eigen's
    // quat_product for doubles.
    const bool small = f.small[m] != 0;
    const double s = small ? 0.5 : f.sin_half[m] / f.theta[m];
    const double aw = small ? 1.0 : f.cos_half[m], ax = s * f.rx[m], ay = s * f.ry[m], az = s * f.rz[m];
    const double bx = f.qx[m], by = f.qy[m], bz = f.qz[m], bw = f.qw[m];
    const double x = (aw * bx + ay * bz) - (az * by - ax * bw);
    const double y = (aw * by + ay * bw) + (az * bx - ax * bz);
    const double z = (aw * bz - ay * bx) + (az * bw + ax * by);
    const double w = (aw * bw - ay * by) - (az * bz + ax * bx);
    const double nn = (x * x + z * z) + (y * y + w * w);
    const double norm = std::sqrt(nn);
    f.qx[m] = nn > 0 ? x / norm : x;
    f.qy[m] = nn > 0 ? y / norm : y;
    f.qz[m] = nn > 0 ? z / norm : z;
    f.qw[m] = nn > 0 ? w / norm : w;
  }
}

}  // namespace

TENDRIL_SIMD_CLONES void drift_frames(const ParticleId* ids, std::uint32_t n, const std::uint8_t* active, double dt,
                                      const Vec3* w, Quat* R) {
  FrameBlock f;
  ParticleId at[kFrameBlock];
  for (std::uint32_t e0 = 0; e0 < n; e0 += kFrameBlock) {
    const std::uint32_t end = std::min(n, e0 + kFrameBlock);
    std::uint32_t k = 0;
    for (std::uint32_t e = e0; e < end; ++e) {
      const ParticleId p = ids[e];
      if (!active[p]) continue;
      const Vec3 r = dt * w[p];
      f.rx[k] = r.x(), f.ry[k] = r.y(), f.rz[k] = r.z(), f.theta[k] = r.squaredNorm();
      const Quat& q = R[p];
      f.qx[k] = q.x(), f.qy[k] = q.y(), f.qz[k] = q.z(), f.qw[k] = q.w();
      at[k++] = p;
    }
    half_angles(f, k);
    frame_block(f, k);
    for (std::uint32_t m = 0; m < k; ++m) R[at[m]] = Quat(f.qw[m], f.qx[m], f.qy[m], f.qz[m]);
  }
}

}  // namespace tendril
