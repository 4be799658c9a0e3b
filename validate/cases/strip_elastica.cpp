// Mattiasson's cantilever as a wide bending strip (StripCantilever: D W =
// 1 N m^2, 2 quads across), tip loads PL^2/EI = 2, 5 and 10 applied in
// turn, against his table of the elastica with EI = D W: the largest
// relative error of u/L and w/L over the rows (thesis 6.1's strips, the
// beams issue's "strip as a wide beam").
#include <algorithm>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_strip_elastica(const Setting& setting) {
  StripCantilever c(setting.segments, 2);
  Solver solver(c.m);
  solver.settings = setting.solver;
  // PL^2/EI = k + 1
  return relax_load_steps(
      solver, {1, 4, 9}, [&](int k) { c.set_tip_load(Vec3(0, 0, -(k + 1))); }, [&](int k) { return c.error(k); }, 1e-8, 2'000'000);
}

}  // namespace

Case strip_elastica_case() {
  Case c;
  c.name = "strip_elastica";
  c.reference = "strip (D W = EI) under a tip load PL^2/EI = 2, 5, 10 (Mattiasson 1981): tip u/L and w/L of every row";
  c.resolution = "quads along the strip (2 across)";
  c.formulations = {"strip"};
  std::erase(c.integrators, Integrator::Midpoint);  // 10-20x the steps of the others, 2 million not enough at 40
  c.segments = {10, 20, 40};
  c.quick_segments = {10, 20};
  c.defaults.formulation = "strip";
  c.defaults.segments = 20;
  c.tolerance = 0.005;
  c.run = run_strip_elastica;
  return c;
}

}  // namespace tendril::validate
