// Mattiasson's cantilever (benchmark_models.hpp): L = 1 m, EI = 1 N m^2,
// tip loads PL^2/EI = 2, 5 and 10 normal to the axis, applied in turn (each
// from the last equilibrium), against his table of the elastica's tip
// displacements u/L and w/L; the error is the largest of the six relative
// errors. 3 DOF: the root clamped by a clamp hinge (Model::set_clamp); 6
// DOF: the root's rotations locked.
#include <algorithm>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_mattiasson(const Setting& setting) {
  Mattiasson c(setting.segments, setting.formulation == "beam-6dof" ? 6 : 3);
  Solver solver(c.m);
  solver.settings = setting.solver;
  // PL^2/EI = k + 1
  return relax_load_steps(
      solver, {1, 4, 9}, [&](int k) { c.set_load(k + 1); }, [&](int k) { return c.error(k); }, 1e-8, 2'000'000);
}

}  // namespace

Case mattiasson_case() {
  Case c;
  c.name = "mattiasson";
  c.reference = "cantilever under a tip load PL^2/EI = 2, 5, 10 (Mattiasson 1981): tip u/L and w/L; the largest error";
  c.resolution = "segments of the cantilever";
  c.formulations = {"beam-3dof", "beam-6dof"};
  c.segments = {10, 20, 40};
  c.quick_segments = {10, 20};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 20;
  c.tolerance = 0.005;
  c.run = run_mattiasson;
  return c;
}

}  // namespace tendril::validate
