#pragma once
// A quad mesh of the disc of radius R about the origin in the xy plane: the
// n x n grid of the square [-1, 1]^2 mapped by the elliptical grid mapping
// x = u sqrt(1 - v^2 / 2), y = v sqrt(1 - u^2 / 2), which takes the
// square's sides onto the circle; its 4n boundary particles lie on it. The
// CST triangles cut each quad along the diagonal through the disc's centre
// quadrant-wise, so the four quads at the square's corners (an angle of
// 180 degrees there) are cut through that corner and no triangle is flat.
// Used by the pressure_cap and membrane_ring cases.
#include <cmath>
#include <vector>

#include "model/model.hpp"

namespace tendril::validate {

struct DiscMesh {
  int n = 0;
  std::vector<ParticleId> grid;      // row-major, (n + 1)^2
  std::vector<ParticleId> boundary;  // round the circle, counter-clockwise
  std::vector<Model::Triangle> triangles;
  ParticleId at(int r, int c) const { return grid[std::size_t(r) * (n + 1) + c]; }
  ParticleId centre() const { return at(n / 2, n / 2); }
};

inline DiscMesh disc_mesh(Model& m, int n, double R) {
  DiscMesh d;
  d.n = n;
  for (int r = 0; r <= n; ++r)
    for (int c = 0; c <= n; ++c) {
      const double u = -1 + 2.0 * c / n, v = -1 + 2.0 * r / n;
      d.grid.push_back(m.add_particle(R * Vec3(u * std::sqrt(1 - v * v / 2), v * std::sqrt(1 - u * u / 2), 0)));
    }
  for (int c = 0; c < n; ++c) d.boundary.push_back(d.at(0, c));
  for (int r = 0; r < n; ++r) d.boundary.push_back(d.at(r, n));
  for (int c = n; c > 0; --c) d.boundary.push_back(d.at(n, c));
  for (int r = n; r > 0; --r) d.boundary.push_back(d.at(r, 0));
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const ParticleId a = d.at(r, c), b = d.at(r, c + 1), cc = d.at(r + 1, c + 1), dd = d.at(r + 1, c);
      if ((r < n / 2) == (c < n / 2)) {  // diagonal a - cc
        d.triangles.push_back({a, b, cc});
        d.triangles.push_back({cc, dd, a});
      } else {  // diagonal b - dd
        d.triangles.push_back({b, cc, dd});
        d.triangles.push_back({dd, a, b});
      }
    }
  return d;
}

}  // namespace tendril::validate
