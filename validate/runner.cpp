#include "runner.hpp"

#include <algorithm>
#include <exception>

#include "report.hpp"

namespace tendril::validate {

bool Row::passes() const { return failure.empty() && outcome.converged && outcome.error <= tolerance; }

std::string Row::why_not() const {
  if (!failure.empty()) return "failed: " + failure;
  if (!outcome.converged) return "did not converge";
  if (!(outcome.error <= tolerance)) return "error " + percent(outcome.error) + " % > tolerance " + percent(tolerance) + " %";
  return "";
}

std::string default_failure(const Row& r) {
  return r.case_name + " under its default settings (" + r.integrator + ", " + r.formulation + ", " +
         std::to_string(r.segments) + " segments): " + r.why_not();
}

std::vector<Setting> matrix(const Case& c, bool quick) {
  std::vector<Setting> out;
  const int coarsest = *std::min_element(c.quick_segments.begin(), c.quick_segments.end());
  for (const std::string& formulation : c.formulations)
    for (Integrator integrator : c.integrators)
      for (int segments : quick ? c.quick_segments : c.segments) {
        const bool default_column = formulation == c.defaults.formulation && integrator == c.defaults.solver.integrator;
        if (quick && segments != coarsest && !default_column) continue;
        Setting s = c.defaults;
        s.formulation = formulation;
        s.segments = segments;
        s.solver.integrator = integrator;
        out.push_back(s);
      }
  return out;
}

bool is_default(const Case& c, const Setting& s) {
  return s.formulation == c.defaults.formulation && s.segments == c.defaults.segments &&
         s.solver.integrator == c.defaults.solver.integrator;
}

Row run_setting(const Case& c, const Setting& s, const RunOptions& options) {
  Row row;
  row.case_name = c.name;
  row.integrator = integrator_name(s.solver.integrator);
  row.formulation = s.formulation;
  row.segments = s.segments;
  row.is_default = is_default(c, s);
  row.tolerance = c.tolerance;
  try {
    row.outcome = c.run(s);
    double timed = row.outcome.wall_ms;
    for (int run = 1; run < options.max_runs && timed < options.min_timed_ms; ++run) {
      const Outcome again = c.run(s);
      timed += again.wall_ms;
      if (again.error != row.outcome.error || again.steps != row.outcome.steps) {
        row.failure = "not deterministic: a repeat gave another error or step count";
        break;
      }
      row.outcome.wall_ms = std::min(row.outcome.wall_ms, again.wall_ms);
    }
  } catch (const std::exception& e) {
    row.failure = e.what();
  }
  return row;
}

}  // namespace tendril::validate
