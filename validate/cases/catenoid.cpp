// An equal-stress CST membrane (thesis 3.2.8.2, eq. 3.36 with sigma_warp =
// sigma_weft: a soap film) between two coaxial rings of radius 1 at a
// distance of 1, against the catenoid r = a cosh(z / a) through the rings:
// a cosh(0.5 / a) = 1, its larger root a = 0.84834 the waist radius.
// Resolution: n particles round each ring and n / 3 rows of quads along the
// axis, each quad cut into two triangles with the first side round the
// tube (warp); the particles start on the cylinder of radius 1.
#include <cmath>
#include <numbers>

#include "case.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

double exact_waist() {
  double lo = 0.6, hi = 1.0;  // a cosh(0.5 / a) - 1 grows on [0.6, 1]
  for (int i = 0; i < 200; ++i) {
    const double a = 0.5 * (lo + hi);
    (a * std::cosh(0.5 / a) - 1 < 0 ? lo : hi) = a;
  }
  return 0.5 * (lo + hi);
}

Outcome run_catenoid(const Setting& setting) {
  const int n = setting.segments, rows = n / 3;  // rows even: a ring at the waist
  Model m;
  std::vector<ParticleId> ps;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c < n; ++c) {
      const double t = 2 * std::numbers::pi * c / n;
      ps.push_back(m.add_particle(Vec3(std::cos(t), std::sin(t), -0.5 + double(r) / rows)));
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
  Membrane film;
  film.mode = Membrane::FormFinding;
  film.sigma_warp = film.sigma_weft = 1;  // N/m
  m.set_patch_formulation(tube, film, triangles);

  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-8, 2'000'000);  // 10 nN against pulls of ~0.1 N
  double waist = 0;
  for (int c = 0; c < n; ++c) waist += m.particles.position[at(rows / 2, c)].head<2>().norm() / n;
  out.error = relative_error(waist, exact_waist());
  return out;
}

}  // namespace

Case catenoid_case() {
  Case c;
  c.name = "catenoid";
  c.reference = "equal-stress CST membrane between rings of radius 1 at distance 1: catenoid waist 0.84834";
  c.resolution = "particles round a ring (rows: a third)";
  c.formulations = {"cst"};
  c.segments = {12, 24, 48, 96};
  c.quick_segments = {12, 24};
  c.defaults.formulation = "cst";
  c.defaults.segments = 24;
  c.tolerance = 0.005;
  c.run = run_catenoid;
  return c;
}

}  // namespace tendril::validate
