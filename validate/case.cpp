#include "case.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace tendril::validate {

Outcome relax_load_steps(Solver& solver, const std::vector<int>& steps, const std::function<void(int)>& set,
                         const std::function<double(int)>& error, double tolerance, std::uint64_t max_steps) {
  Outcome out;
  out.converged = true;
  for (int k : steps) {
    set(k);
    const Outcome o = relax(solver, tolerance, max_steps);
    out.steps += o.steps;
    out.force_evaluations += o.force_evaluations;
    out.wall_ms += o.wall_ms;
    out.converged = out.converged && o.converged;
    out.error = std::max(out.error, error(k));
  }
  return out;
}

Outcome relax(Solver& solver, double tolerance, std::uint64_t max_steps) {
  const std::uint64_t evaluations = solver.force_evaluations();
  const auto start = std::chrono::steady_clock::now();
  const RunResult r = solver.run(tolerance, max_steps);
  const auto stop = std::chrono::steady_clock::now();
  Outcome out;
  out.steps = r.steps;
  out.force_evaluations = solver.force_evaluations() - evaluations;
  out.wall_ms = std::chrono::duration<double, std::milli>(stop - start).count();
  out.converged = r.converged;
  return out;
}

std::vector<Integrator> all_integrators() {
  std::vector<Integrator> out(kIntegrators.begin(), kIntegrators.end());
  out.insert(out.end(), kConstraintIntegrators.begin(), kConstraintIntegrators.end());
  return out;
}

double relative_error(double measured, double exact) { return std::abs(measured / exact - 1); }

}  // namespace tendril::validate
