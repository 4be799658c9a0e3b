// Solver behaviour beyond the validation cases: exact small problems,
// locks and reactions, and a non-finite state stopped before it spreads.
#include <doctest/doctest.h>

#include <cmath>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

TEST_CASE("a loaded bar stretches by F L / EA and the support reacts with -F") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(2, 0, 0));
  m.add_cable(a, b, Section{1e6, 0, 0, 0});
  m.set_lock(a, kLockTranslation);
  m.set_lock(b, kLockY | kLockZ);
  m.set_load(b, Vec3(500, 0, 0));
  Solver s(m);
  RunResult r = s.run(1e-8, 100000);
  REQUIRE(r.converged);
  CHECK(m.particles.position[b].x() == doctest::Approx(2 + 500 * 2 / 1e6).epsilon(1e-12));
  CHECK(s.reaction(a).x() == doctest::Approx(-500).epsilon(1e-9));
  CHECK(s.reaction(b).norm() < 1e-12);  // nothing is locked along the load
}

TEST_CASE("a prestressed bar carries its geometric tension at its rest length") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1e4, 0, 250, 0});  // T = 250 + EA/L (L - L0), eq. 3.32
  m.set_lock(a, kLockTranslation);
  m.set_lock(b, kLockTranslation);
  Solver s(m);
  s.compute_forces();
  CHECK(s.reaction(a).x() == doctest::Approx(-250));
  CHECK(s.reaction(b).x() == doctest::Approx(250));
}

TEST_CASE("locked axes do not move and are reported as reactions") {
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= 4; ++i) ps.push_back(m.add_particle(Vec3(i, 0, 0)));
  m.add_beam(ps, Section{1e7, 1e3, 0, 0});
  m.set_lock(ps[0], kLockTranslation);
  m.set_lock(ps[4], kLockTranslation);
  m.set_load(ps[2], Vec3(0, 0, -100));
  Solver s(m);
  REQUIRE(s.run(1e-7, 200000).converged);
  CHECK(m.particles.position[ps[0]] == Vec3(0, 0, 0));
  CHECK(m.particles.position[ps[4]] == Vec3(4, 0, 0));
  // Symmetric: each support takes half the load.
  CHECK(s.reaction(ps[0]).z() == doctest::Approx(50).epsilon(1e-6));
  CHECK(s.reaction(ps[4]).z() == doctest::Approx(50).epsilon(1e-6));
  CHECK(m.particles.position[ps[2]].z() < 0);
}

TEST_CASE("a non-finite force stops the step before any particle moves") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
  m.add_beam({a, b, c}, Section{1e6, 10, 0, 0});
  m.set_lock(a, kLockTranslation);
  m.set_load(c, Vec3(0, std::nan(""), 0));
  Solver s(m);
  const Vec3 before = m.particles.position[b];
  try {
    s.step();
    FAIL("expected a NumericalError");
  } catch (const NumericalError& e) {
    CHECK(std::string(e.what()).find("particle " + std::to_string(c)) != std::string::npos);
  }
  CHECK(m.particles.position[b] == before);
  CHECK(m.particles.position[c] == Vec3(2, 0, 0));
  CHECK(m.check() == "");
}

// Leapfrog finds the masses in its kick's pass: a torque it cannot use is
// found after some velocities were kicked, so they are reset, and neither a
// position nor a frame moved.
TEST_CASE("a non-finite torque on a 6-DOF beam stops the step: velocities reset, nothing moved") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
  const BlockId beam = m.add_beam({a, b, c}, Section{1e6, 10, 0, 0});
  m.set_beam_formulation(beam, 6);
  m.set_lock(a, kLockTranslation | kLockRotation);
  m.set_load(c, Vec3(0, 0, -1));
  Solver s(m);
  s.settings.integrator = Integrator::Leapfrog;
  for (int i = 0; i < 3; ++i) s.step();
  REQUIRE(m.particles.velocity[c].norm() > 0);
  m.particles.moment[b] = Vec3(0, std::nan(""), 0);  // set_moment refuses it: as a corrupted state
  const auto positions = m.particles.position.raw();
  const auto frames = m.particles.orientation.raw();
  const std::uint64_t steps = s.steps();
  try {
    s.step();
    FAIL("expected a NumericalError");
  } catch (const NumericalError& e) {
    CHECK(std::string(e.what()).find("torque on particle " + std::to_string(b)) != std::string::npos);
  }
  CHECK(m.particles.position.raw() == positions);
  CHECK(m.particles.orientation.raw() == frames);
  for (ParticleId p : {a, b, c}) {
    CHECK(m.particles.velocity[p] == Vec3::Zero());
    CHECK(m.particles.angular_velocity[p] == Vec3::Zero());
  }
  CHECK(s.steps() == steps);
  m.particles.moment[b] = Vec3::Zero();  // usable again: the step goes on
  s.step();
  CHECK(s.steps() == steps + 1);
  CHECK(m.particles.position[c].z() < 0);
  CHECK(m.check() == "");
}

TEST_CASE("the same model gives the same numbers, bit for bit") {
  auto run = [] {
    Model m;
    std::vector<ParticleId> ps;
    for (int i = 0; i <= 20; ++i) ps.push_back(m.add_particle(Vec3(0.5 * i, 0.01 * std::sin(i), 0)));
    m.add_beam(ps, Section{1e7, 1e3, 0, 1});
    m.gravity = Vec3(0, 0, -9.81);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
    Solver s(m);
    s.run(1e-9, 3000);
    return m.particles.position;
  };
  CHECK(run() == run());
}
