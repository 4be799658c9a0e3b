// `tendril validate` fails (exit 1, a line on stderr) exactly when a case's
// default row did not run, did not converge or missed its tolerance; the
// other rows only inform. Checked on synthetic cases whose outcome is set.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "registry.hpp"
#include "runner.hpp"

using namespace tendril;
using namespace tendril::validate;

namespace {

Case synthetic(std::function<Outcome(const Setting&)> run) {
  Case c;
  c.name = "synthetic";
  c.formulations = {"bar"};
  c.integrators = {Integrator::Leapfrog, Integrator::RK4};
  c.segments = {4, 8};
  c.quick_segments = {4};
  c.defaults.formulation = "bar";
  c.defaults.segments = 4;
  c.tolerance = 0.01;
  c.run = std::move(run);
  return c;
}

Outcome outcome(double error, bool converged) {
  Outcome o;
  o.error = error;
  o.converged = converged;
  o.steps = 10;
  return o;
}

Row default_row(const Case& c) {
  RunOptions options;
  options.max_runs = 1;
  const Row r = run_setting(c, c.defaults, options);
  REQUIRE(r.is_default);
  return r;
}

}  // namespace

TEST_CASE("validate: a default row passes within tolerance and fails outside it, naming why") {
  CHECK(default_row(synthetic([](const Setting&) { return outcome(0.009, true); })).passes());
  const Row over = default_row(synthetic([](const Setting&) { return outcome(0.02, true); }));
  CHECK(!over.passes());
  CHECK(over.why_not() == "error 2 % > tolerance 1 %");
  CHECK(default_failure(over) == "synthetic under its default settings (leapfrog, bar, 4 segments): error 2 % > tolerance 1 %");
  const Row stalled = default_row(synthetic([](const Setting&) { return outcome(0.001, false); }));
  CHECK(!stalled.passes());
  CHECK(stalled.why_not() == "did not converge");
  const Row thrown = default_row(synthetic([](const Setting&) -> Outcome { throw std::runtime_error("boom"); }));
  CHECK(!thrown.passes());
  CHECK(thrown.why_not() == "failed: boom");
  const Row nan = default_row(synthetic([](const Setting&) { return outcome(std::nan(""), true); }));
  CHECK(!nan.passes());
}

TEST_CASE("validate: the matrix and --quick's smaller one") {
  Case c = synthetic([](const Setting&) { return outcome(0, true); });
  c.formulations = {"bar", "beam"};
  c.segments = {4, 8, 16};
  c.quick_segments = {8, 4};
  CHECK(matrix(c, false).size() == 12);  // 2 formulations x 2 integrators x 3 resolutions
  // Quick: all four at the coarsest (4), and the default (bar, leapfrog) at 8 too.
  const std::vector<Setting> quick = matrix(c, true);
  REQUIRE(quick.size() == 5);
  int at_coarsest = 0;
  for (const Setting& s : quick) {
    if (s.segments == 4) ++at_coarsest;
    else CHECK((s.formulation == "bar" && s.solver.integrator == Integrator::Leapfrog));
  }
  CHECK(at_coarsest == 4);
}

TEST_CASE("validate: every registered case names a reference and runs its default in its quick list") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    CHECK(!c.reference.empty());
    bool found = false;
    for (const Setting& s : matrix(c, true)) found = found || is_default(c, s);
    CHECK(found);
  }
  CHECK(find_case("prestressed_ring") != nullptr);
  CHECK(find_case("bathe_bolourchi") != nullptr);
  CHECK(find_case("end_moment_circle") != nullptr);
}
