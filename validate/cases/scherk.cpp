// Scherk's first surface z = ln(cos y / cos x), a minimal surface, over the
// square |x|, |y| <= 1.2 from a *flat* start: the boundary particles sit on
// the surface (z from -ln cos 1.2 = 1.0 to +1.0 round the square), the
// interior ones start at z = 0 and an equal-stress CST membrane (a soap
// film) finds the surface. The interior particles slide in the surface as
// it forms (the G-strings of cst_forces.cpp); the error is the largest
// |z - z(x, y)| over them, at their own x and y, over the boundary's height
// range (2.0).
// Resolution: quads along a side.
#include <cmath>

#include "case.hpp"
#include "cases/soap_film.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

constexpr double kHalf = 1.2;

double scherk(double x, double y) { return std::log(std::cos(y) / std::cos(x)); }

Outcome run_scherk(const Setting& setting) {
  const int n = setting.segments;
  Model m;
  std::vector<ParticleId> ps;
  for (int r = 0; r <= n; ++r)
    for (int c = 0; c <= n; ++c) {
      const double x = -kHalf + 2 * kHalf * c / n, y = -kHalf + 2 * kHalf * r / n;
      const bool boundary = r == 0 || c == 0 || r == n || c == n;
      ps.push_back(m.add_particle(Vec3(x, y, boundary ? scherk(x, y) : 0)));
      if (boundary) m.set_lock(ps.back(), kLockTranslation);
    }
  auto at = [&](int r, int c) { return ps[std::size_t(r) * (n + 1) + c]; };
  const BlockId patch = m.add_quad_grid(ps, n + 1, n + 1, Section{1, 0, 0, 0});
  std::vector<Model::Triangle> triangles;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      triangles.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1)});
      triangles.push_back({at(r + 1, c + 1), at(r + 1, c), at(r, c)});
    }
  make_soap_film(m, patch, 1, triangles);  // N/m
  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-8, 2'000'000);
  const double range = 2 * -std::log(std::cos(kHalf));
  double worst = 0;
  for (int r = 1; r < n; ++r)
    for (int c = 1; c < n; ++c) {
      const Vec3& x = m.particles.position[at(r, c)];
      worst = std::max(worst, std::abs(x.z() - scherk(x.x(), x.y())) / range);
    }
  out.error = worst;
  return out;
}

}  // namespace

Case scherk_case() {
  Case c;
  c.name = "scherk";
  c.reference = "Scherk's minimal surface z = ln(cos y / cos x), |x|, |y| <= 1.2, from flat: largest height error / range";
  c.resolution = "quads along a side";
  c.formulations = {"cst"};
  c.segments = {8, 16, 32};
  c.quick_segments = {8, 16};
  c.defaults.formulation = "cst";
  c.defaults.segments = 16;
  c.tolerance = 0.005;
  c.run = run_scherk;
  return c;
}

}  // namespace tendril::validate
