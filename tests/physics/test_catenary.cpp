// The hanging chain of validate/benchmark_models.hpp (80 cables) against the
// elastic catenary (Irvine 1981), with Leapfrog and RK4.
#include <doctest/doctest.h>

#include <cmath>

#include "benchmark_models.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {
using Chain = validate::HangingChain;

void check_catenary(Integrator integrator) {
  Chain c;
  CHECK(c.m.state(c.ps[1]) == State::Shared);
  Solver solver(c.m);
  solver.settings.integrator = integrator;
  RunResult r = solver.run(1e-6, 1'000'000);
  REQUIRE(r.converged);
  REQUIRE(c.m.check() == "");
  MESSAGE(std::string(integrator_name(integrator)) << ": steps=" << r.steps << " force evaluations=" << solver.force_evaluations()
                                      << " sag=" << c.sag() << " exact=" << Chain::exact_sag());
  CHECK(std::abs(c.sag() / Chain::exact_sag() - 1) < 0.005);
  // The supports carry the whole weight.
  CHECK((solver.reaction(c.ps.front()) + solver.reaction(c.ps.back())).z() ==
        doctest::Approx((Chain::rho * Chain::length * Chain::g)).epsilon(1e-6));
}

}  // namespace

TEST_CASE("catenary: sag of a hanging cable chain within 0.5%") { check_catenary(Integrator::Leapfrog); }

TEST_CASE("catenary with RK4: sag within 0.5%") { check_catenary(Integrator::RK4); }
