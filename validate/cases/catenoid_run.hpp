#pragma once
// An equal-stress CST membrane (thesis 3.2.8.2, eq. 3.36 with sigma_warp =
// sigma_weft: a soap film) between two coaxial rings of radius 1 at a
// distance h, against the catenoid r = a cosh(z / a) through the rings:
// a cosh(h / 2a) = 1, its larger root a the waist radius (the stable
// catenoid; both roots meet at h = 1.3255, beyond which there is none).
// Resolution: n particles round each ring and an even number of rows of
// quads along the axis, about n h / 3 (square quads), each quad cut into
// two triangles with the first side round the tube (warp); the particles
// start on the cylinder of radius 1. The catenoid, catenoid_tall and
// catenoid_limit cases.
#include <cmath>
#include <numbers>

#include "case.hpp"
#include "cases/soap_film.hpp"
#include "model/model.hpp"

namespace tendril::validate {

inline double catenoid_waist(double h) {
  // a cosh(h / 2a) has its minimum where (h / 2a) tanh(h / 2a) = 1 and
  // grows from there to 1: bisect above it.
  double lo = 0.01, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi), t = h / (2 * a);
    (t * std::tanh(t) > 1 ? lo : hi) = a;
  }
  hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (a * std::cosh(h / (2 * a)) - 1 < 0 ? lo : hi) = a;
  }
  return 0.5 * (lo + hi);
}

inline Outcome run_catenoid(const Setting& setting, double h) {
  const int n = setting.segments;
  const int rows = std::max(2, 2 * int(std::lround(n * h / 6)));  // even: a ring at the waist
  Model m;
  std::vector<ParticleId> ps;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c < n; ++c) {
      const double t = 2 * std::numbers::pi * c / n;
      ps.push_back(m.add_particle(Vec3(std::cos(t), std::sin(t), h * (-0.5 + double(r) / rows))));
      if (r == 0 || r == rows) m.set_lock(ps.back(), kLockTranslation);
    }
  auto at = [&](int r, int c) { return ps[std::size_t(r) * n + (c % n)]; };
  std::vector<Model::Quad> quads;
  std::vector<Model::Triangle> triangles;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < n; ++c) {
      const ParticleId a = at(r, c), b = at(r, c + 1), cc = at(r + 1, c + 1), d = at(r + 1, c);
      quads.push_back({a, b, cc, d});
      triangles.push_back({a, b, cc});
      triangles.push_back({cc, d, a});
    }
  const BlockId tube = m.add_patch(quads, Section{1, 0, 0, 0});
  make_soap_film(m, tube, 1, triangles);  // N/m

  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-8, 2'000'000);  // 10 nN against pulls of ~0.1 N
  double waist = 0;
  for (int c = 0; c < n; ++c) waist += m.particles.position[at(rows / 2, c)].head<2>().norm() / n;
  out.error = relative_error(waist, catenoid_waist(h));
  return out;
}

}  // namespace tendril::validate
