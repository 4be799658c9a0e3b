#pragma once
// The sine and cosine of half a frame's turn (rotation_of, eq. 3.16), by
// polynomials: the frames' drift (physics/frame_drift.cpp) computes them in
// its vectorised block loop, where libm's sin and cos, one particle at a
// time, cost about an eighth of a 6-DOF step. Both rotation_of and the block
// use these, so every integrator turns frames alike bit for bit.
//
// For |h| <= kHalfAngleBound: Taylor series, sine to h^15, cosine to h^14,
// coefficients (-1)^k / n! rounded to double. Truncation is below 2^-60
// relative at the bound; measured against long double over 10^7 points of
// [0, 0.5], the error is at most 0.61 ulp (sine) and 0.69 ulp (cosine),
// never more than one double away from glibc's sin and cos
// (tests/physics/test_half_angle.cpp). Beyond the bound: std::sin, std::cos.
// Without fused multiply-adds (-ffp-contract=off or a target without FMA),
// a vector lane rounds as scalar code does.
#include <cmath>

namespace tendril {

// A frame turning by more than 2 * 0.5 rad in one step is rare.
constexpr double kHalfAngleBound = 0.5;

// sin(h) and cos(h) for |h| <= kHalfAngleBound; no branch, so it vectorises.
inline void half_angle_poly(double h, double& s, double& c) {
  const double z = h * h;
  const double ps = -1.0 / 6 + z * (1.0 / 120 + z * (-1.0 / 5040 + z * (1.0 / 362880 + z * (-1.0 / 39916800 +
                    z * (1.0 / 6227020800 + z * (-1.0 / 1307674368000))))));
  const double pc = 1.0 / 24 + z * (-1.0 / 720 + z * (1.0 / 40320 + z * (-1.0 / 3628800 +
                    z * (1.0 / 479001600 + z * (-1.0 / 87178291200)))));
  s = h + (h * z) * ps;
  c = 1.0 + z * (-0.5 + z * pc);
}

// sin(h) and cos(h) for every h: the polynomials within the bound, libm's
// beyond it.
inline void half_angle_sincos(double h, double& s, double& c) {
  if (std::abs(h) <= kHalfAngleBound) {
    half_angle_poly(h, s, c);
  } else {
    s = std::sin(h);
    c = std::cos(h);
  }
}

}  // namespace tendril
