// Pin-ended strut of thesis 5.4.1.2 (Adriaenssens & Barnes 2001): L = 10 m,
// 64 segments, EI = 100 kNm^2, EA = 100 MN, buckled into an elastica by
// moving one roller towards the other. Mid-span deflection and axial load are
// compared with the exact inextensible elastica:
//   k = sin(theta0/2),  P = EI (2K(k)/L)^2,  chord = L (2E(k)/K(k) - 1),
//   delta = k L / K(k).
#include <doctest/doctest.h>

#include <cmath>

#include "benchmark_models.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

struct ElasticaResult {
  double deflection, load, exact_deflection, exact_load;
};

// The strut of validate/benchmark_models.hpp at 64 segments, started from a
// half sine wave with the right chord and roughly the right arc length; the
// rest lengths stay those of the straight strut.
struct Strut : validate::Elastica {
  explicit Strut(double theta0_deg) : Elastica(theta0_deg, 64) {}

  ElasticaResult measure(const Solver& solver) const {
    return {m.particles.position[ps[ps.size() / 2]].y(), -solver.reaction(ps.back()).x(), exact_deflection,
            exact_load};
  }
};

bool within(const ElasticaResult& r, double tolerance) {
  return std::abs(r.deflection / r.exact_deflection - 1) < tolerance &&
         std::abs(r.load / r.exact_load - 1) < tolerance;
}

ElasticaResult buckle(double theta0_deg, Damping damping = Damping::Kinetic, double viscous = 0) {
  Strut strut(theta0_deg);
  Solver solver(strut.m);
  solver.settings.damping = damping;
  solver.settings.viscous = viscous;
  RunResult r = solver.run(1e-3, 2'000'000);
  REQUIRE(r.converged);
  REQUIRE(strut.m.check() == "");
  ElasticaResult out = strut.measure(solver);
  MESSAGE("theta0=" << theta0_deg << " steps=" << r.steps << " delta=" << out.deflection << " exact="
                    << out.exact_deflection << " P=" << out.load << " exact=" << out.exact_load);
  return out;
}

}  // namespace

TEST_CASE("elastica: mid-span deflection and axial load within 1% of the exact elastica") {
  for (double theta0 : {40.0, 80.0, 120.0}) {
    CAPTURE(theta0);
    ElasticaResult r = buckle(theta0);
    CHECK(std::abs(r.deflection / r.exact_deflection - 1) < 0.01);
    CHECK(std::abs(r.load / r.exact_load - 1) < 0.01);
  }
}

TEST_CASE("elastica with viscous damping reaches the same equilibrium") {
  ElasticaResult r = buckle(80.0, Damping::Viscous, 0.02);
  CHECK(std::abs(r.deflection / r.exact_deflection - 1) < 0.01);
  CHECK(std::abs(r.load / r.exact_load - 1) < 0.01);
}

TEST_CASE("elastica: every integrator with kinetic damping within 1% of the exact elastica") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Strut strut(80.0);
    Solver solver(strut.m);
    solver.settings.integrator = integrator;
    RunResult r = solver.run(1e-3, 200'000);
    REQUIRE(r.converged);
    CHECK(strut.m.check() == "");
    ElasticaResult out = strut.measure(solver);
    MESSAGE(name << ": steps=" << r.steps << " force evaluations=" << solver.force_evaluations()
                 << " kinetic resets=" << solver.kinetic_resets() << " delta=" << out.deflection
                 << " P=" << out.load);
    CHECK(within(out, 0.01));
  }
}

TEST_CASE("elastica: switching from Leapfrog to RK4 mid-run reaches the same elastica") {
  Strut strut(80.0);
  Solver solver(strut.m);
  for (int i = 0; i < 500; ++i) solver.step();
  REQUIRE(solver.residual() > 1);  // still far from equilibrium
  solver.settings.integrator = Integrator::RK4;
  RunResult r = solver.run(1e-3, 200'000);
  REQUIRE(r.converged);
  CHECK(strut.m.check() == "");
  ElasticaResult out = strut.measure(solver);
  MESSAGE("leapfrog x500, then rk4: steps=" << 500 + r.steps << " delta=" << out.deflection << " P=" << out.load);
  CHECK(within(out, 0.01));
}

TEST_CASE("elastica: cycling through every integrator every 300 steps still converges") {
  Strut strut(80.0);
  Solver solver(strut.m);
  RunResult r;
  std::uint64_t steps = 0;
  for (int round = 0; round < 100 && !r.converged; ++round) {
    solver.settings.integrator = kIntegrators[round % kIntegrators.size()];
    r = solver.run(1e-3, 300);
    steps += r.steps;
  }
  REQUIRE(r.converged);
  ElasticaResult out = strut.measure(solver);
  MESSAGE("cycling: steps=" << steps << " last=" << std::string(integrator_name(solver.settings.integrator))
                            << " delta=" << out.deflection << " P=" << out.load);
  CHECK(within(out, 0.01));
}
