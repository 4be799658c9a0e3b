// A bending strip (StripCantilever: D W = 1 N m^2, 2 quads across) rolled
// by an end moment M = 1.5 pi D W / L into three quarters of a cylinder of
// radius D W / M; the error is the largest relative distance of a particle
// of any row from that circle (the rows bend as one).
#include <algorithm>
#include <cmath>
#include <numbers>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_strip_roll(const Setting& setting) {
  StripCantilever c(setting.segments, 2);
  const double M = 1.5 * std::numbers::pi, R = 1 / M;
  c.set_tip_moment(Vec3(0, -M, 0));
  Solver solver(c.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-8, 2'000'000);
  for (const auto& row : c.ps)
    for (ParticleId p : row) {
      const Vec3& x = c.m.particles.position[p];
      out.error = std::max(out.error, std::abs(std::hypot(x.x(), x.z() - R) / R - 1));
    }
  return out;
}

}  // namespace

Case strip_roll_case() {
  Case c;
  c.name = "strip_roll";
  c.reference = "strip (D W = EI) rolled by an end moment 1.5 pi D W / L: every particle's distance from the cylinder";
  c.resolution = "quads along the strip (2 across)";
  c.formulations = {"strip"};
  std::erase(c.integrators, Integrator::Midpoint);  // 10-20x the steps of the others, 2 million not enough at 40
  c.segments = {10, 20, 40};
  c.quick_segments = {10, 20};
  c.defaults.formulation = "strip";
  c.defaults.segments = 20;
  c.tolerance = 0.005;
  c.run = run_strip_roll;
  return c;
}

}  // namespace tendril::validate
