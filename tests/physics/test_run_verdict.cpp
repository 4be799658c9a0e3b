// Issue 11, "convergence that tells the truth": every verdict of a run
// (physics/run_verdict.hpp) from a small scene built to produce it, the
// relative tolerance on a beam loaded with 1e8 N, and the absolute rule of
// the existing scenes unchanged.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// A simply supported 3-DOF beam of 10 segments over `span` from x = x0,
// loaded at mid-span by `load` [N] downwards.
struct LoadedBeam {
  Model m;
  Solver solver{m};
  std::vector<ParticleId> ps;
  LoadedBeam(double span, double load, Section section, double x0 = 0) {
    for (int i = 0; i <= 10; ++i) ps.push_back(m.add_particle(Vec3(x0 + span * i / 10, 0, 0)));
    m.add_beam(ps, section);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockY | kLockZ);
    m.set_load(ps[5], Vec3(0, 0, -load));
  }
};

// A steel box girder of 20 m (EA = 2.1e11 * 0.2, EI = 2.1e11 * 0.05)
// carrying 1e8 N at mid-span, at site coordinates 1 km from the origin:
// rounding a coordinate of 1000 m (1.1e-13 m) in a segment of EA / L =
// 2.1e10 N/m leaves a residual of a few 1e-3 N, which no step removes.
LoadedBeam heavy_beam() { return LoadedBeam(20, 1e8, Section{4.2e10, 1.05e10, 0, 0}, 1000); }

}  // namespace

TEST_CASE("verdict: the converged loaded bar reads its residual against its load") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(2, 0, 0));
  m.add_cable(a, b, Section{1e6, 0, 0, 0});
  m.set_lock(a, kLockTranslation);
  m.set_lock(b, kLockY | kLockZ);
  m.set_load(b, Vec3(500, 0, 0));
  Solver s(m);
  const RunResult r = s.run(1e-8, 100000);
  REQUIRE(r.converged);
  CHECK(r.verdict == Verdict::Converged);
  CHECK(std::string(verdict_name(r.verdict)) == "converged");
  CHECK(r.force_scale == doctest::Approx(500).epsilon(1e-9));  // the load, and the support's reaction
  CHECK(r.relative_residual == doctest::Approx(r.residual / 500));
  CHECK(r.residual < 1e-8);
  CHECK(r.motion < 1e-8);
  CHECK(r.threshold == 1e-8);
}

TEST_CASE("verdict: the absolute tolerance alone converges exactly as before") {
  // The same run, step for step, with the old call and with RunLimits: the
  // relative rule is off unless asked for.
  LoadedBeam a(4, 100, Section{1e7, 1e3, 0, 0}), b(4, 100, Section{1e7, 1e3, 0, 0});
  const RunResult ra = a.solver.run(1e-7, 200000);
  const RunResult rb = b.solver.run(RunLimits{1e-7, 0, 200000});
  REQUIRE(ra.converged);
  CHECK(ra.steps == rb.steps);
  CHECK(ra.residual == rb.residual);
  CHECK(a.m.particles.position[a.ps[5]] == b.m.particles.position[b.ps[5]]);
  MESSAGE("beam 4 m, 100 N, tolerance 1e-7: ", ra.steps, " steps");
}

TEST_CASE("verdict: a beam loaded with 1e8 N converges with a relative tolerance, not with 1e-3 N") {
  LoadedBeam absolute = heavy_beam();
  const RunResult ra = absolute.solver.run(RunLimits{1e-3, 0, 100000});
  LoadedBeam relative = heavy_beam();
  const RunResult rr = relative.solver.run(RunLimits{0, 1e-9, 100000});
  MESSAGE("1e8 N beam: absolute 1e-3 N: ", std::string(verdict_name(ra.verdict)), " after ", ra.steps,
          " steps, residual ", ra.residual, " N (", ra.relative_residual, " of ", ra.force_scale, " N); relative 1e-9: ",
          std::string(verdict_name(rr.verdict)), " after ", rr.steps, " steps, residual ", rr.residual, " N");
  CHECK_FALSE(ra.converged);
  CHECK(ra.verdict == Verdict::Stalled);
  CHECK(ra.steps == 100000);
  CHECK(ra.residual > 1e-3);
  CHECK(ra.relative_residual < 1e-9);  // yet the shape is there
  REQUIRE(rr.converged);
  CHECK(rr.verdict == Verdict::Converged);
  CHECK(rr.force_scale == doctest::Approx(1e8).epsilon(1e-6));  // the load (each support takes half)
  CHECK(rr.relative_residual <= 1e-9);
  CHECK(rr.residual <= 1e-9 * rr.force_scale);
  // Converged means the shape: the mid-span deflection agrees with the
  // 100000-step run to 1e-9 of itself.
  const double z_abs = absolute.m.particles.position[absolute.ps[5]].z();
  const double z_rel = relative.m.particles.position[relative.ps[5]].z();
  CHECK(z_rel == doctest::Approx(z_abs).epsilon(1e-8));
  // Both rules: either suffices, the threshold is the larger.
  LoadedBeam both = heavy_beam();
  const RunResult rb = both.solver.run(RunLimits{1e-3, 1e-9, 100000});
  CHECK(rb.converged);
  CHECK(rb.steps == rr.steps);
}

TEST_CASE("verdict: a slow run stopped by a small max_steps says max_steps, its residual still falling") {
  LoadedBeam beam(4, 100, Section{1e7, 1e3, 0, 0});
  const RunResult tiny = beam.solver.run(1e-7, 20);
  CHECK_FALSE(tiny.converged);
  CHECK(tiny.verdict == Verdict::MaxSteps);
  CHECK(tiny.steps == 20);
  LoadedBeam again(4, 100, Section{1e7, 1e3, 0, 0});
  const RunResult r = again.solver.run(1e-7, 400);
  CHECK(r.verdict == Verdict::MaxSteps);
  CHECK(r.best_after < kStallProgress * r.best_before);  // still falling
  MESSAGE("max_steps 400: residual ", r.residual, ", best of the first half ", r.best_before, ", of the second ",
          r.best_after);
}

TEST_CASE("verdict: a run whose residual stopped falling is stalled") {
  // The 1e8 N beam held to 1e-3 N: rounding keeps its residual far above,
  // while kinetic damping resets every few steps.
  LoadedBeam beam = heavy_beam();
  const RunResult r = beam.solver.run(RunLimits{1e-3, 0, 20000});
  MESSAGE("stalled: residual ", r.residual, " N, best ", r.best_before, " then ", r.best_after, ", ", r.kinetic_resets,
          " resets in ", r.steps, " steps");
  CHECK(r.verdict == Verdict::Stalled);
  CHECK_FALSE(r.converged);
  CHECK(r.best_after >= kStallProgress * r.best_before);
  CHECK(r.kinetic_resets > r.steps / 100);
}

TEST_CASE("verdict: a time step far beyond the stability limit diverges and stops with finite positions") {
  // Physical masses (dt matters), a 1 kg mass on a cable of EA = 1e6 N:
  // omega = 1000 rad/s, so dt = 0.1 s is 50 times Leapfrog's limit 2 / omega.
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1e6, 0, 0, 0});
  m.set_point_mass(b, 1);
  m.set_lock(a, kLockTranslation);
  m.set_load(b, Vec3(1, 0, 0));
  Solver s(m);
  s.settings.mass_mode = MassMode::Physical;
  s.settings.damping = Damping::None;
  s.settings.dt = 0.1;
  const RunResult r = s.run(1e-6, 100000);
  MESSAGE("diverged at step ", r.steps, ": ", r.detail);
  CHECK(r.verdict == Verdict::Diverged);
  CHECK_FALSE(r.converged);
  CHECK(r.steps < 10);
  CHECK(r.residual > kDivergence * r.reference);
  CHECK(r.reference == doctest::Approx(1));  // the load
  CHECK(contains(r.detail, "the residual grew to"));
  CHECK(m.particles.position[b].allFinite());
}

TEST_CASE("verdict: a loaded body that nothing holds is a mechanism") {
  // Two particles on a cable, no support, 1 N on each along the cable: it
  // translates as a rigid body, x = n^2 F / S after n steps (eq. 3.4 masses),
  // 10 m (ten times its length) after about 100 steps.
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1e3, 0, 0, 0});
  m.set_load(a, Vec3(1, 0, 0));
  m.set_load(b, Vec3(1, 0, 0));
  Solver s(m);
  const RunResult r = s.run(1e-6, 100000);
  MESSAGE("mechanism at step ", r.steps, ": ", r.detail);
  CHECK(r.verdict == Verdict::Mechanism);
  CHECK_FALSE(r.converged);
  CHECK(r.steps % kMechanismCheckEvery == 0);
  CHECK(r.steps <= 4 * kMechanismCheckEvery);
  CHECK(r.residual == doctest::Approx(1).epsilon(1e-6));  // the load, unresisted
  CHECK(r.force_scale == doctest::Approx(1));
  CHECK(contains(r.detail, "travelled"));
  CHECK(contains(r.detail, "times the model's extent of 1 m"));
}

TEST_CASE("verdict: a hanging cable that falls a long way from straight is not a mechanism") {
  // A straight cable between two pins under its weight has no transverse
  // stiffness at first: it moves with an undiminished residual until its
  // sag builds the tension, and then converges.
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= 10; ++i) ps.push_back(m.add_particle(Vec3(i * 0.1, 0, 0)));
  for (int i = 0; i < 10; ++i) m.add_cable(ps[i], ps[i + 1], Section{1e4, 0, 0, 1});
  m.gravity = Vec3(0, 0, -9.81);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  Solver s(m);
  const RunResult r = s.run(1e-6, 200000);
  CHECK(r.verdict == Verdict::Converged);
  MESSAGE("hanging cable: ", r.steps, " steps");
}
