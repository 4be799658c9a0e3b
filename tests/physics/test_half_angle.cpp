// The half angle's sine and cosine (model/half_angle.hpp), the polynomials
// rotation_of and the frames' drift turn frames with: over a dense sweep of
// [-0.5, 0.5] (kHalfAngleBound) never more than one double away from glibc's
// sin and cos, within 0.62 ulp (sine) and 0.70 ulp (cosine) of the true value
// (a long double reference; measured 0.61 and 0.69), sin^2 + cos^2 within
// 2^-52 of 1 (measured 2^-52); sin h = h and cos h = 1 at 0 and at tiny h
// (1e-154 down to the smallest subnormal);
// beyond the bound libm's own values. Dropping the last term of either
// polynomial, or changing 1/7! by 1e-10 of itself, fails the checks.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

#include "model/frames.hpp"
#include "model/half_angle.hpp"

using namespace tendril;

namespace {

// How many doubles lie between a and b (one sign).
std::int64_t doubles_apart(double a, double b) {
  std::int64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x > y ? x - y : y - x;
}

// |a - exact| in units of the last place of the exact value.
double ulps(double a, long double exact) {
  int e;
  std::frexp(double(exact), &e);
  return double(std::fabs((long double)a - exact) / std::ldexp(1.0L, e - 53));
}

}  // namespace

TEST_CASE("half angle: polynomial sine and cosine against libm and a long double reference") {
  constexpr double B = kHalfAngleBound;
  constexpr bool wide = std::numeric_limits<long double>::digits >= 64;
  const long n = 1000000;
  std::int64_t apart = 0;
  long differ = 0;
  double sin_ulps = 0, cos_ulps = 0, unit = 0;
  for (long i = -n; i <= n; ++i) {
    for (int side = -1; side <= 1; ++side) {
      double h = B * double(i) / double(n);
      if (side != 0) h = std::nextafter(h, side * 1.0);
      if (std::abs(h) > B) continue;
      double s, c;
      half_angle_poly(h, s, c);
      apart = std::max({apart, doubles_apart(s, std::sin(h)), doubles_apart(c, std::cos(h))});
      differ += (s != std::sin(h)) + (c != std::cos(h));
      if (wide && h != 0) {
        sin_ulps = std::max(sin_ulps, ulps(s, sinl((long double)h)));
        cos_ulps = std::max(cos_ulps, ulps(c, cosl((long double)h)));
      }
      unit = std::max(unit, std::abs(s * s + c * c - 1));
    }
  }
  MESSAGE("max doubles apart from libm ", apart, ", ", differ, " of ", 2 * 3 * (2 * n + 1), " values differ; error ",
          sin_ulps, " ulp (sine), ", cos_ulps, " ulp (cosine); |sin^2 + cos^2 - 1| <= ", unit);
  CHECK(apart <= 1);
  CHECK(differ < 3 * 2 * (2 * n + 1) / 20);  // measured about 2 %
  if (wide) {
    CHECK(sin_ulps <= 0.62);
    CHECK(cos_ulps <= 0.70);
  }
  CHECK(unit <= std::ldexp(1.0, -52));
}

TEST_CASE("half angle: edge values and libm beyond the bound") {
  constexpr double B = kHalfAngleBound;
  for (double h : {0.0, 5e-324, 1e-300, 1e-160, 1e-154}) {
    double s, c;
    half_angle_sincos(h, s, c);
    CHECK(s == h);
    CHECK(c == 1.0);
  }
  for (double h : {1e-12, 1e-8, 1e-4, 0.1, std::nextafter(B, 0.0), B, -B}) {
    double s, c;
    half_angle_sincos(h, s, c);
    CHECK(doubles_apart(s, std::sin(h)) <= 1);
    CHECK(doubles_apart(c, std::cos(h)) <= 1);
  }
  for (double h : {std::nextafter(B, 1.0), -std::nextafter(B, 1.0), 0.7, 1.0, 3.0, -3.0, 100.0, 1e10}) {
    double s, c;
    half_angle_sincos(h, s, c);
    CHECK(s == std::sin(h));
    CHECK(c == std::cos(h));
  }
  double s, c;
  half_angle_sincos(std::numeric_limits<double>::quiet_NaN(), s, c);
  CHECK(std::isnan(s));
  CHECK(std::isnan(c));
  // rotation_of turns by these: its w is cos(|r| / 2), its vector part
  // sin(|r| / 2) / |r| r, on both sides of the bound.
  for (double t : {0.3, 0.999, 1.0, std::nextafter(1.0, 2.0), 2.5}) {
    const Vec3 r = t * Vec3(2, -1, 2) / 3;
    const double theta = std::sqrt(r.squaredNorm());
    half_angle_sincos(0.5 * theta, s, c);
    const Quat q = rotation_of(r);
    CHECK(q.w() == c);
    CHECK(q.x() == (s / theta) * r.x());
    CHECK(q.z() == (s / theta) * r.z());
  }
}
