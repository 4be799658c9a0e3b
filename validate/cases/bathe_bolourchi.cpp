// Bathe & Bolourchi's 45-degree bend (6-DOF beams; the model and its
// reference are in benchmark_models.hpp), built as one beam whose curved
// shape is its rest shape (rest = "current"): the tip under 300 lb, then
// under 600 lb from there (load steps, as Simo & Vu-Quoc ran it), against
// Simo & Vu-Quoc's tip positions; the error is the larger of the two tips'
// distances from theirs over their displacements. Their 8 elements are 0.6 %
// off; 16 elements (the default) are within 0.5 %.
#include <algorithm>

#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

namespace {

Outcome run_bend(const Setting& setting) {
  BentCantilever bend(setting.segments, 300);
  Solver solver(bend.m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-6, 2'000'000);  // 1 ulb against 300 lb
  const double at300 = bend.tip_error(300);
  bend.m.set_load(bend.tip(), Vec3(0, 0, 600));
  const Outcome second = relax(solver, 1e-6, 2'000'000);
  out.steps += second.steps;
  out.force_evaluations += second.force_evaluations;
  out.wall_ms += second.wall_ms;
  out.converged = out.converged && second.converged;
  out.error = std::max(at300, bend.tip_error(600));
  return out;
}

}  // namespace

Case bathe_bolourchi_case() {
  Case c;
  c.name = "bathe_bolourchi";
  c.reference =
      "45-degree bend, R = 100 in, one curved beam at rest (6 DOF), 300 then 600 lb out of plane: Simo & Vu-Quoc's "
      "tips (58.84, 22.33, 40.08) and (47.23, 15.79, 53.37) in; |tip - reference| / |reference displacement|";
  c.resolution = "elements of the bend";
  c.formulations = {"beam-6dof"};
  c.segments = {8, 16, 32};
  c.quick_segments = {8, 16};
  c.defaults.formulation = "beam-6dof";
  c.defaults.segments = 16;
  c.tolerance = 0.005;
  c.run = run_bend;
  return c;
}

}  // namespace tendril::validate
