#pragma once
// A limit-load case (Lee's frame, Williams' toggle): builds the benchmark
// model at the setting's resolution and formulation, finds its limit under
// displacement control and reports the error against the model's reference.
#include "benchmark_models.hpp"
#include "case.hpp"

namespace tendril::validate {

template <class Benchmark>
Outcome run_limit_case(const Setting& setting) {
  Benchmark b(setting.segments, setting.formulation == "beam-6dof" ? 6 : 3);
  Solver solver(b.m);
  solver.settings = setting.solver;
  const LimitPoint p = b.limit(solver);
  Outcome out;
  out.steps = p.steps;
  out.force_evaluations = p.force_evaluations;
  out.wall_ms = p.wall_ms;
  out.converged = p.converged;
  out.error = Benchmark::error(p);
  return out;
}

}  // namespace tendril::validate
