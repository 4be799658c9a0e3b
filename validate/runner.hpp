#pragma once
// Runs a case's matrix: every formulation x integrator x resolution.
#include <string>
#include <vector>

#include "case.hpp"

namespace tendril::validate {

struct Row {
  std::string case_name, integrator, formulation;
  int segments = 0;
  Outcome outcome;
  bool is_default = false;
  double tolerance = 0;  // the case's (it binds the default row only)
  std::string failure;   // what the run threw, or why it cannot be trusted
  // A default row passes when it ran, converged and is within tolerance.
  bool passes() const;
  // Why it does not pass: "failed: ...", "did not converge" or
  // "error 2.1 % > tolerance 2 %"; "" when it passes.
  std::string why_not() const;
};

struct RunOptions {
  bool quick = false;  // the smaller matrix of matrix(c, true)
  // A relaxation shorter than min_timed_ms is run again, up to max_runs in
  // all, and the fastest run is reported: one run of a small model is too
  // short to time. The repeats must agree bit for bit (DESIGN: deterministic).
  double min_timed_ms = 200;
  int max_runs = 10;
};

// In table order: formulation, then integrator, then segments. Every setting
// starts from the case's default solver settings. Quick (CI): every
// formulation and integrator at the coarsest of Case::quick_segments (does
// it run?), and the default formulation and integrator at all of them (does
// the default pass?).
std::vector<Setting> matrix(const Case& c, bool quick);
bool is_default(const Case& c, const Setting& s);
Row run_setting(const Case& c, const Setting& s, const RunOptions& options);
// What `tendril validate` prints on stderr for a default row that does not
// pass (and then exits with 1): the case, its default settings and why.
std::string default_failure(const Row& r);

}  // namespace tendril::validate
