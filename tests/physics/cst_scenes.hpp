#pragma once
// Scenes shared by the CST tests: the catenoid between two rings and the
// flat square, built on the model with their CST triangulation from the
// meshing layer (edge classification, fig. 5.30).
#include <cmath>
#include <vector>

#include "edge_classification.hpp"
#include "model/model.hpp"

namespace tendril::test {

// The CST triangulation of a patch by edge classification, warp along `warp`.
inline std::vector<Model::Triangle> triangles_of(const Model& m, BlockId patch, const Vec3& warp) {
  meshing::ClassifyOptions o;
  o.warp = warp;
  std::vector<Model::Triangle> out;
  for (const auto& t : meshing::cst_triangulation(m, patch, o).triangles) out.push_back({t[0], t[1], t[2]});
  return out;
}

// The CST triangles of an s x s grid of particles g (row by row): each
// quad (r, c) split along its diagonal from (r, c) to (r + 1, c + 1).
inline std::vector<Model::Triangle> grid_triangles(const std::vector<ParticleId>& g, int s) {
  std::vector<Model::Triangle> out;
  for (int r = 0; r + 1 < s; ++r)
    for (int c = 0; c + 1 < s; ++c) {
      const ParticleId a = g[r * s + c], b = g[r * s + c + 1], cc = g[(r + 1) * s + c + 1], d = g[(r + 1) * s + c];
      out.push_back({a, b, cc});
      out.push_back({cc, d, a});
    }
  return out;
}

// A film prestressed 300 and 200 N/m (warp, weft), in form-finding or, with
// an orthotropic elastic law, in analysis.
inline Membrane test_film(bool analysis) {
  Membrane film;
  film.mode = analysis ? Membrane::Analysis : Membrane::FormFinding;
  film.sigma_warp = 300, film.sigma_weft = 200;
  if (analysis) film.dxx = 800, film.dyy = 500, film.dxy = 100, film.dyx = 100, film.G = 30;
  return film;
}

// A tube of `around` x `rows` quads between two fixed coaxial rings of
// radius 1 at z = -0.5 and z = 0.5, interior particles on the cylinder.
struct Tube {
  Model m;
  BlockId patch = kNone;
  int around, rows;
  std::vector<ParticleId> ps;  // ring r, particle c at r * around + c
  Tube(int around_, int rows_, double start_radius = 1.0) : around(around_), rows(rows_) {
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= rows; ++r)
      for (int c = 0; c < around; ++c) {
        const double t = 2 * pi * c / around, z = -0.5 + double(r) / rows;
        const double radius = (r == 0 || r == rows) ? 1.0 : start_radius;
        ps.push_back(m.add_particle(Vec3(radius * std::cos(t), radius * std::sin(t), z)));
      }
    std::vector<Model::Quad> quads;
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < around; ++c) {
        const int c1 = (c + 1) % around;
        quads.push_back({at(r, c), at(r, c1), at(r + 1, c1), at(r + 1, c)});
      }
    patch = m.add_patch(quads, Section{1e3, 0, 0, 0});
    for (int c = 0; c < around; ++c) {
      m.set_lock(at(0, c), kLockTranslation);
      m.set_lock(at(rows, c), kLockTranslation);
    }
  }
  ParticleId at(int r, int c) const { return ps[std::size_t(r) * around + c]; }
  // Mean distance from the axis of the particles of ring r.
  double radius(int r) const {
    double sum = 0;
    for (int c = 0; c < around; ++c) sum += m.particles.position[at(r, c)].head<2>().norm();
    return sum / around;
  }
};

// The exact catenoid r = a cosh(z / a) through rings of radius 1 at z = +-0.5:
// the larger (stable) root of a cosh(0.5 / a) = 1.
inline double catenoid_waist() {
  double lo = 0.6, hi = 1.0;  // f(a) = a cosh(0.5/a) - 1 grows on [0.6, 1]
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (a * std::cosh(0.5 / a) - 1 < 0 ? lo : hi) = a;
  }
  return 0.5 * (lo + hi);
}

// An n x n grid of quads over a side x side square in the plane z = 0,
// boundary particles locked.
struct FlatSquare {
  Model m;
  BlockId patch = kNone;
  int n;
  std::vector<ParticleId> ps;  // row-major, (n+1)^2
  FlatSquare(int n_, double side) : n(n_) {
    for (int r = 0; r <= n; ++r)
      for (int c = 0; c <= n; ++c) ps.push_back(m.add_particle(Vec3(side * c / n, side * r / n, 0)));
    patch = m.add_quad_grid(ps, n + 1, n + 1, Section{1e3, 0, 0, 0});
    for (int r = 0; r <= n; ++r)
      for (int c = 0; c <= n; ++c)
        if (r == 0 || c == 0 || r == n || c == n) m.set_lock(at(r, c), kLockTranslation);
  }
  ParticleId at(int r, int c) const { return ps[std::size_t(r) * (n + 1) + c]; }
};

}  // namespace tendril::test
