// Projective dynamics (projective.hpp): the prefactored global step reaches
// the explicit solvers' equilibria (elastica 3 and 6 DOF, catenary), factors
// once and again only when the topology, the locks or the weights change,
// and needs far fewer iterations than the per-particle average of VIE.
#include <doctest/doctest.h>

#include <string>

#include "benchmark_models.hpp"

using namespace tendril;
using Chain = validate::HangingChain;
using Strut = validate::Elastica;

namespace {
RunResult relax(Model& m, Solver& s, Integrator integrator, double tolerance) {
  s.settings.integrator = integrator;
  const RunResult r = s.run(tolerance, 1'000'000);
  REQUIRE(r.converged);
  CHECK(m.check() == "");
  return r;
}
}  // namespace

TEST_CASE("projective: the elastica (3 and 6 DOF) and the catenary within tolerance, in fewer steps than VIE") {
  for (int dofs : {3, 6}) {
    CAPTURE(dofs);
    Strut pd(80, 32, dofs), vie(80, 32, dofs);
    Solver sp(pd.m), sv(vie.m);
    const RunResult rp = relax(pd.m, sp, Integrator::ProjectiveDynamics, 1e-3);
    const RunResult rv = relax(vie.m, sv, Integrator::VariationalImplicitEuler, 1e-3);
    MESSAGE("elastica " << dofs << " DOF: projective " << rp.steps << " steps, " << sp.factorizations()
                        << " factorisation(s); vie " << rv.steps << " steps; errors " << pd.deflection_error() << ", "
                        << pd.load_error(sp));
    CHECK(pd.deflection_error() < 0.01);
    CHECK(pd.load_error(sp) < 0.01);
    CHECK(std::abs(pd.deflection_error() - vie.deflection_error()) < 1e-5);  // one discrete equilibrium
    CHECK(sp.factorizations() == 1);
    CHECK(rp.steps * 2 < rv.steps);
  }
  Chain c;
  Solver s(c.m);
  const RunResult r = relax(c.m, s, Integrator::ProjectiveDynamics, 1e-6);
  MESSAGE("catenary, projective: " << r.steps << " steps, sag error " << c.sag_error());
  CHECK(c.sag_error() < 0.005);
  CHECK(s.factorizations() == 1);
}

TEST_CASE("projective: refactors only when locks or dt change, follows a new cable, never for loads") {
  Chain c(20);
  Solver s(c.m);
  s.settings.integrator = Integrator::ProjectiveDynamics;
  for (int k = 0; k < 50; ++k) s.step();
  CHECK(s.factorizations() == 1);
  c.m.set_load(c.ps[10], Vec3(0, 0, -100));  // the right-hand side only
  for (int k = 0; k < 50; ++k) s.step();
  CHECK(s.factorizations() == 1);
  c.m.set_lock(c.ps[5], kLockZ);  // a row leaves the z system
  const double locked_z = c.m.particles.position[c.ps[5]].z();
  s.step();
  CHECK(s.factorizations() == 2);
  c.m.add_cable(c.ps[4], c.ps[16], Section{1e5, 0, 0, 0});  // rule 6: a new bar across the chain
  s.step();
  CHECK(s.factorizations() == 2);  // followed by a low-rank correction (test_projective_update.cpp)
  CHECK(s.projective_updates() == 1);
  for (int k = 0; k < 50; ++k) s.step();
  CHECK(s.factorizations() == 2);
  s.settings.vie_dt = 7;  // the momentum weight is on the diagonal
  s.step();
  CHECK(s.factorizations() == 3);
  // The refactored system still solves the loaded, locked, refined chain.
  REQUIRE(s.run(1e-6, 1'000'000).converged);
  CHECK(c.m.particles.position[c.ps[5]].z() == locked_z);
  Solver check(c.m);
  check.compute_forces();
  for (ParticleId p : {c.ps[3], c.ps[4], c.ps[10], c.ps[16]}) CHECK(c.m.particles.force[p].norm() < 1e-6);
}

TEST_CASE("projective: switching leapfrog -> projective -> leapfrog mid-run reaches the same elastica") {
  Strut strut;
  Solver solver(strut.m);
  solver.run(1e-3, 300);
  solver.settings.integrator = Integrator::ProjectiveDynamics;
  solver.run(1e-3, 20);
  CHECK(std::string(solver.phase()) == "projective");
  solver.settings.integrator = Integrator::Leapfrog;
  REQUIRE(solver.run(1e-3, 1'000'000).converged);
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}
