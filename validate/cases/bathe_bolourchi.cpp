// Bathe & Bolourchi's 45-degree bend (6-DOF beams; the model and its
// reference are in benchmark_models.hpp): the tip displacement under a
// 600 lb load normal to the bend's plane against Simo & Vu-Quoc's
// (-23.48, -13.50, 53.37) in, the largest of the three components' errors.
// Their 8 elements are the default; the reference is itself a converged
// finite-element result, so finer meshes show how far 8 elements are from
// it (32 elements: 0.79 %, measured; Midpoint needed 955 000 steps there).
#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_bend(const Setting& setting) {
  BentCantilever bend(setting.segments);
  Solver solver(bend.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-6, 2'000'000);  // 1 ulb against 600 lb
  out.error = bend.error();
  return out;
}

}  // namespace

Case bathe_bolourchi_case() {
  Case c;
  c.name = "bathe_bolourchi";
  c.reference =
      "45-degree bend, R = 100 in, 600 lb tip load out of plane (6 DOF): Simo & Vu-Quoc's tip displacement "
      "(-23.48, -13.50, 53.37) in; the largest component error";
  c.resolution = "elements of the bend";
  c.formulations = {"beam-6dof"};
  c.segments = {4, 8, 16};
  c.quick_segments = {8, 16};
  c.defaults.formulation = "beam-6dof";
  c.defaults.segments = 8;
  c.tolerance = 0.02;
  c.run = run_bend;
  return c;
}

}  // namespace tendril::validate
