// Variational Implicit Euler (thesis 3.3.5, eq. 3.53-3.64): it reaches the
// explicit solvers' discrete equilibria (the elastica and the catenary
// against their exact solutions), with 3- and 6-DOF beams; it stays stable
// far beyond Leapfrog's largest stable step with physical masses; it can be
// switched to and from at run time.
#include <doctest/doctest.h>

#include "physics/projections.hpp"
#include "benchmark_models.hpp"

using namespace tendril;
using Chain = validate::HangingChain;
using Strut = validate::Elastica;

TEST_CASE("vie: the elastica within 1% of the exact solution, the same discrete answer as Leapfrog") {
  Strut leap;
  Solver ls(leap.m);
  REQUIRE(ls.run(1e-3, 1'000'000).converged);
  for (int iterations : {1, 4, 16}) {
    CAPTURE(iterations);
    Strut strut;
    Solver solver(strut.m);
    solver.settings.integrator = Integrator::VariationalImplicitEuler;
    solver.settings.vie_iterations = iterations;
    const RunResult r = solver.run(1e-3, 1'000'000);
    REQUIRE(r.converged);
    CHECK(strut.m.check() == "");
    MESSAGE("elastica, vie x" << iterations << ": steps " << r.steps << ", evaluations " << solver.force_evaluations()
                              << ", deflection error " << strut.deflection_error() << ", load error "
                              << strut.load_error(solver));
    CHECK(strut.deflection_error() < 0.01);
    CHECK(strut.load_error(solver) < 0.01);
    // Force-consistent projections: the fixed point is Leapfrog's.
    CHECK(std::abs(strut.deflection_error() - leap.deflection_error()) < 1e-6);
  }
}

TEST_CASE("vie: the hanging chain within 0.5% of the elastic catenary; supports carry the weight") {
  Chain c;
  Solver solver(c.m);
  solver.settings.integrator = Integrator::VariationalImplicitEuler;
  const RunResult r = solver.run(1e-6, 1'000'000);
  REQUIRE(r.converged);
  MESSAGE("catenary, vie: steps " << r.steps << ", sag " << c.sag() << " vs " << Chain::exact_sag());
  CHECK(c.sag_error() < 0.005);
  const double weight = Chain::rho * Chain::length * 9.81;
  CHECK((solver.reaction(c.ps.front()) + solver.reaction(c.ps.back())).z() == doctest::Approx(weight).epsilon(1e-6));
}

TEST_CASE("vie: 6-DOF beams, translation and rotation, reach the elastica") {
  Strut strut(80, 32, 6);
  Solver solver(strut.m);
  solver.settings.integrator = Integrator::VariationalImplicitEuler;
  const RunResult r = solver.run(1e-3, 1'000'000);
  REQUIRE(r.converged);
  CHECK(strut.m.check() == "");
  MESSAGE("elastica 6 DOF, vie: steps " << r.steps << ", deflection error " << strut.deflection_error()
                                        << ", load error " << strut.load_error(solver));
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}

TEST_CASE("vie: projections balance to the element forces (K (p - x) = f, eq. 3.55 and 3.59)") {
  Strut strut(80, 16, 6);
  Strut strut3(80, 16, 3);
  for (Model* m : {&strut.m, &strut3.m}) {
    Solver solver(*m);
    solver.compute_forces();
    const std::size_t n = m->particles.capacity();
    std::vector<Vec3> pull(n), turn(n);
    std::vector<double> w(n), wr(n);
    accumulate_projections(*m, m->particles.position.data(), m->particles.orientation.data(), 1.0,
                           {pull.data(), w.data(), turn.data(), wr.data()});
    for (std::size_t p = 0; p < n; ++p) {
      CHECK((pull[p] - m->particles.force[p]).norm() <= 1e-9 * (1 + m->particles.force[p].norm()));
      CHECK(w[p] >= m->particles.stiffness[p]);  // never a larger move than the explicit bound
    }
    for (ParticleId p : m->particles.rotational.raw())
      CHECK((turn[p] - m->particles.torque[p]).norm() <= 1e-9 * (1 + m->particles.torque[p].norm()));
  }
}

TEST_CASE("vie: stable with physical masses at 150x the time step where Leapfrog diverges") {
  // The chain's stiffest mode with physical masses (0.3 kg per particle,
  // EA/L = 667 kN/m) bounds Leapfrog at dt = 2 / sqrt(4 k / m) = 0.67 ms.
  auto run = [](Integrator integrator, double dt) {
    Chain c;
    Solver solver(c.m);
    solver.settings.integrator = integrator;
    solver.settings.mass_mode = MassMode::Physical;
    solver.settings.dt = dt;
    const RunResult r = solver.run(1e-6, 100'000);
    return std::pair{r, c.sag_error()};
  };
  CHECK(run(Integrator::Leapfrog, 6.5e-4).first.converged);
  // Beyond it the run stops itself, diverged, before anything overflows.
  const RunResult beyond = run(Integrator::Leapfrog, 1e-3).first;
  CHECK(beyond.verdict == Verdict::Diverged);
  CHECK_FALSE(beyond.converged);
  for (double dt : {1e-3, 1e-2, 0.1}) {
    CAPTURE(dt);
    const auto [r, error] = run(Integrator::VariationalImplicitEuler, dt);
    MESSAGE("vie, physical masses, dt " << dt << ": steps " << r.steps << ", sag error " << error);
    REQUIRE(r.converged);
    CHECK(error < 0.005);
  }
}

TEST_CASE("vie: switching leapfrog -> vie -> leapfrog mid-run reaches the same elastica") {
  Strut strut;
  Solver solver(strut.m);
  solver.run(1e-3, 500);
  solver.settings.integrator = Integrator::VariationalImplicitEuler;
  solver.run(1e-3, 500);
  CHECK(std::string(solver.phase()) == "vie");
  solver.settings.integrator = Integrator::Leapfrog;
  const RunResult r = solver.run(1e-3, 1'000'000);
  REQUIRE(r.converged);
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}

TEST_CASE("vie: locked axes stay, loads enter through x0, a non-finite result moves nothing") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1000, 0, 0, 0}, 1.0);
  m.set_lock(a, kLockTranslation);
  m.set_lock(b, kLockY | kLockZ);
  m.set_load(b, Vec3(10, 5, 5));
  Solver solver(m);
  solver.settings.integrator = Integrator::VariationalImplicitEuler;
  REQUIRE(solver.run(1e-9, 100'000).converged);
  CHECK(m.particles.position[b].x() == doctest::Approx(1.01).epsilon(1e-9));  // F L / EA
  CHECK(m.particles.position[b].y() == 0);
  CHECK(m.particles.position[b].z() == 0);
  CHECK(solver.reaction(a).x() == doctest::Approx(-10).epsilon(1e-6));
  m.set_load(b, Vec3(std::numeric_limits<double>::infinity(), 0, 0));
  const Vec3 before = m.particles.position[b];
  CHECK_THROWS_AS(solver.step(), NumericalError);
  CHECK(m.particles.position[b] == before);
}
