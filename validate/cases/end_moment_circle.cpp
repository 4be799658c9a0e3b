// A cantilever (L = 1 m, EI = 1 N m^2, EA = 10 kN, 6 or 3 DOF) under an end
// moment M = 2 pi EI / L bends to the constant curvature M / EI = 2 pi / L:
// a closed circle, the tip back on the root. The error is the tip-to-root
// gap over L.
#include <numbers>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

template <class C>
Outcome roll(C& c, const Setting& setting, double L, double EI) {
  c.m.set_moment(c.tip(), Vec3(0, 0, 2 * std::numbers::pi * EI / L));
  Solver solver(c.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-7, 2'000'000);  // 0.1 uN against EI / L^2 = 1 N
  out.error = (c.m.particles.position[c.tip()] - c.m.particles.position[c.ps.front()]).norm() / L;
  return out;
}

// 3 DOF: the moment acts as a couple across the end segment, the root is
// a clamp hinge (Cantilever3); the particles lie on the exact circle, the
// polygon's chords overshoot it by pi^2 / (6 n^2) of L.
Outcome run_circle(const Setting& setting) {
  const double L = 1, EI = 1;
  if (setting.formulation == "beam-3dof") {
    Cantilever3 c(setting.segments, L, Section{1e4, EI, 0, 0});
    return roll(c, setting, L, EI);
  }
  Cantilever c(setting.segments, L, Section{1e4, EI, 0, 0});
  return roll(c, setting, L, EI);
}

}  // namespace

Case end_moment_circle_case() {
  Case c;
  c.name = "end_moment_circle";
  c.reference = "cantilever under an end moment 2 pi EI / L (6 and 3 DOF): a closed circle; tip-to-root gap / L";
  c.resolution = "segments of the cantilever";
  c.formulations = {"beam-6dof", "beam-3dof"};
  c.segments = {10, 20, 40};  // Midpoint did not converge in 2 million steps at 80
  c.quick_segments = {10, 20};
  c.defaults.formulation = "beam-6dof";
  c.defaults.segments = 20;
  c.tolerance = 0.01;
  c.run = run_circle;
  return c;
}

}  // namespace tendril::validate
