// The mixed solver (thesis 5.4.2.2, fig. 5.17): Leapfrog far from
// equilibrium, the Variational Implicit Euler with its own time step near
// it, and Leapfrog again when the model is disturbed.
#include <doctest/doctest.h>

#include <string>

#include "benchmark_models.hpp"

using namespace tendril;
using Chain = validate::HangingChain;
using Strut = validate::Elastica;

TEST_CASE("mixed: the elastica and the catenary within their tolerances, finishing in the VIE phase") {
  for (double vie_dt : {0.0, 4.0}) {
    CAPTURE(vie_dt);
    Strut strut;
    Solver s1(strut.m);
    s1.settings.integrator = Integrator::Mixed;
    s1.settings.vie_dt = vie_dt;
    CHECK(std::string(s1.phase()) == "leapfrog");
    const RunResult r1 = s1.run(1e-3, 1'000'000);
    REQUIRE(r1.converged);
    CHECK(std::string(s1.phase()) == "vie");
    CHECK(strut.deflection_error() < 0.01);
    CHECK(strut.load_error(s1) < 0.01);

    Chain c;
    Solver s2(c.m);
    s2.settings.integrator = Integrator::Mixed;
    s2.settings.vie_dt = vie_dt;
    const RunResult r2 = s2.run(1e-6, 1'000'000);
    REQUIRE(r2.converged);
    CHECK(std::string(s2.phase()) == "vie");
    CHECK(c.sag_error() < 0.005);
    MESSAGE("mixed, vie_dt " << vie_dt << ": elastica " << r1.steps << " steps (" << s1.force_evaluations()
                             << " evaluations), errors " << strut.deflection_error() << ", " << strut.load_error(s1)
                             << "; catenary " << r2.steps << " steps (" << s2.force_evaluations()
                             << " evaluations), error " << c.sag_error());
  }
}

TEST_CASE("mixed: leaves Leapfrog at mixed_switch of the peak residual, returns to it when disturbed") {
  Chain c(20);
  Solver solver(c.m);
  solver.settings.integrator = Integrator::Mixed;
  solver.settings.mixed_switch = 0.01;
  double peak = 0;
  std::uint64_t switched = 0;
  for (std::uint64_t k = 0; k < 100'000 && !switched; ++k) {
    solver.step();
    if (std::string(solver.phase()) == "vie") switched = solver.steps();
    else peak = std::max(peak, solver.residual());
  }
  REQUIRE(switched > 0);
  // The step that switched started from a residual within 1 % of the peak.
  CHECK(solver.residual() <= 0.01 * peak);
  REQUIRE(solver.run(1e-6, 1'000'000).converged);
  // A load on mid-span: the residual jumps far above the one VIE started from.
  c.m.set_load(c.ps[10], Vec3(0, 0, -500));
  solver.step();
  CHECK(std::string(solver.phase()) == "leapfrog");
  REQUIRE(solver.run(1e-6, 1'000'000).converged);
  CHECK(std::string(solver.phase()) == "vie");
  // Equilibrium of the loaded chain: the supports carry weight and load.
  const double weight = Chain::rho * Chain::length * 9.81;
  CHECK((solver.reaction(c.ps.front()) + solver.reaction(c.ps.back())).z() ==
        doctest::Approx(weight + 500).epsilon(1e-6));
}
