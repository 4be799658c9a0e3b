#pragma once
// Boundary loops for the paving tests and measurements.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "model/types.hpp"

namespace tendril::meshing::test {

// A closed polygon through `corners`, each side cut into `per_unit` * length
// equal pieces (sides of integer length).
inline std::vector<Vec3> polygon_loop(const std::vector<Vec3>& corners, int per_unit = 1) {
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int pieces = int(std::lround((b - a).norm() * per_unit));
    for (int k = 0; k < pieces; ++k) out.push_back(a + (b - a) * (double(k) / pieces));
  }
  return out;
}

inline std::vector<Vec3> square_loop(double side, int per_unit = 1) {
  return polygon_loop({Vec3(0, 0, 0), Vec3(side, 0, 0), Vec3(side, side, 0), Vec3(0, side, 0)}, per_unit);
}

inline std::vector<Vec3> l_loop(double arm, double width, int per_unit = 1) {
  return polygon_loop({Vec3(0, 0, 0), Vec3(arm, 0, 0), Vec3(arm, width, 0), Vec3(width, width, 0), Vec3(width, arm, 0),
                       Vec3(0, arm, 0)},
                      per_unit);
}

// n points on a circle of radius r; wave lifts them to a saddle z = wave cos 2t.
inline std::vector<Vec3> circle_loop(int n, double r, double wave = 0) {
  std::vector<Vec3> out;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * i / n;
    out.push_back(Vec3(r * std::cos(t), r * std::sin(t), wave * std::cos(2 * t)));
  }
  return out;
}

// A star of `points` tips on radius r_out and notches on r_in, every side
// cut into pieces of about `spacing`.
inline std::vector<Vec3> star_loop(int points, double r_out, double r_in, double spacing = 1) {
  std::vector<Vec3> corners, out;
  for (int k = 0; k < 2 * points; ++k) {
    const double t = std::numbers::pi * k / points, r = k % 2 ? r_in : r_out;
    corners.push_back(Vec3(r * std::cos(t), r * std::sin(t), 0));
  }
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int pieces = std::max(1, int(std::lround((b - a).norm() / spacing)));
    for (int k = 0; k < pieces; ++k) out.push_back(a + (b - a) * (double(k) / pieces));
  }
  return out;
}

}  // namespace tendril::meshing::test
