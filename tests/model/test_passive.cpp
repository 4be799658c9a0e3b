// Multi-resolution bookkeeping (thesis 5.5.2.3): passive particles leave
// Particles::integrated, every element touching one goes behind its buffer's
// awake border and lumps no mass, a rollback restores all of it, and a
// solver step neither moves a passive particle nor feels its elements.
#include <doctest/doctest.h>

#include <algorithm>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

bool integrated(const Model& m, ParticleId p) {
  const auto& list = m.particles.integrated.raw();
  return std::find(list.begin(), list.end(), p) != list.end();
}

// A 3 x 3 quad-grid patch (bars with line mass) plus a 3-DOF beam and a
// 6-DOF beam through its middle row, so every element type is touched.
struct Net {
  Model m;
  std::vector<ParticleId> g;
  Net() {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) g.push_back(m.add_particle(Vec3(c, r, 0)));
    m.add_quad_grid(g, 3, 3, Section{1e4, 0, 10, 0.5});
    m.add_beam({g[3], g[4], g[5]}, Section{1e5, 10, 0, 1.0});
    const BlockId b6 = m.add_beam({g[1], g[4], g[7]}, Section{1e5, 10, 0, 1.0});
    m.set_beam_formulation(b6, 6);
  }
};

}  // namespace

TEST_CASE("set_passive moves a particle's elements behind the awake border and back, O(degree)") {
  Net n;
  Model& m = n.m;
  REQUIRE(m.check() == "");
  const std::size_t bars = m.bars.size(), hinges = m.hinges.size(), beams = m.beam6s.size();
  CHECK(m.bars.awake == bars);
  CHECK(m.hinges.awake == hinges);
  CHECK(m.beam6s.awake == beams);
  CHECK(m.particles.integrated.size() == 9);
  const double centre_mass = m.particles.lumped_mass[n.g[4]];

  // The centre: 4 patch bars, 2 beam bars and the beam's hinge, 2 Beam6.
  m.set_passive(n.g[4], true);
  CHECK(m.check() == "");
  CHECK(m.state(n.g[4]) == State::Passive);
  CHECK_FALSE(integrated(m, n.g[4]));
  CHECK(m.particles.integrated.size() == 8);
  CHECK(m.bars.size() == bars);
  CHECK(m.bars.awake == bars - 6);
  CHECK(m.hinges.awake == hinges - 1);
  CHECK(m.beam6s.awake == beams - 2);
  for (std::size_t e = m.bars.awake; e < m.bars.size(); ++e)
    CHECK((m.bars[e].i == n.g[4] || m.bars[e].j == n.g[4]));
  // Dormant elements lump nothing: the centre keeps none, a neighbour on the
  // patch (2 of its 3 bars left) loses half a bar of 0.5 kg/m x 1 m.
  CHECK(m.particles.lumped_mass[n.g[4]] == doctest::Approx(0.0));
  CHECK(centre_mass > 0);

  m.set_passive(n.g[4], false);
  CHECK(m.check() == "");
  CHECK(m.bars.awake == bars);
  CHECK(m.hinges.awake == hinges);
  CHECK(m.beam6s.awake == beams);
  CHECK(integrated(m, n.g[4]));
  CHECK(m.particles.lumped_mass[n.g[4]] == doctest::Approx(centre_mass));
}

TEST_CASE("a passive corner's neighbour loses the mass of the dormant bar only") {
  Model m;
  std::vector<ParticleId> g;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 2; ++c) g.push_back(m.add_particle(Vec3(c, r, 0)));
  m.add_quad_grid(g, 2, 2, Section{1e4, 0, 0, 0.5});  // 4 bars of 1 m, 0.25 kg at each end
  CHECK(m.particles.lumped_mass[g[1]] == doctest::Approx(0.5));
  m.set_passive(g[0], true);
  CHECK(m.particles.lumped_mass[g[1]] == doctest::Approx(0.25));
  CHECK(m.particles.lumped_mass[g[3]] == doctest::Approx(0.5));
  CHECK(m.bars.awake == 2);
  CHECK(m.check() == "");
}

TEST_CASE("rollback restores the integrated list and the element partition exactly") {
  Net n;
  Model& m = n.m;
  m.set_passive(n.g[0], true);
  const auto list = m.particles.integrated.raw();
  const auto bars = m.bars.items.raw();
  const std::size_t awake = m.bars.awake;
  m.begin_transaction();
  m.set_passive(n.g[4], true);
  m.set_passive(n.g[0], false);
  m.insert_particle(n.g[3], n.g[4]);  // a new hinge and bars next to a passive particle
  m.delete_particle(m.add_particle(Vec3(5, 5, 5)));
  CHECK(m.check() == "");
  m.rollback_transaction();
  CHECK(m.particles.integrated.raw() == list);
  CHECK(m.bars.awake == awake);
  REQUIRE(m.bars.size() == bars.size());
  for (std::size_t e = 0; e < bars.size(); ++e) {
    CHECK(m.bars[e].i == bars[e].i);
    CHECK(m.bars[e].j == bars[e].j);
    CHECK(m.bars[e].dart == bars[e].dart);
  }
  CHECK(m.check() == "");
}

TEST_CASE("a step moves no passive particle and feels none of its elements") {
  // Cable chain a - b - c along x, a locked, EA 100 N, prestress 10 N, rest
  // lengths 1 m, 5 N pulling b and c along +x. With c passive at x = 2.5 the
  // stretched b-c cable (65 N) must not act: b settles where the a-b cable
  // carries 5 N, 10 + 100 (L - 1) = 5, L = 0.95.
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1.1, 0, 0)),
                   c = m.add_particle(Vec3(2.5, 0, 0));
  m.add_cable(a, b, Section{100, 0, 10, 0}, 1.0);
  m.add_cable(b, c, Section{100, 0, 10, 0}, 1.0);
  m.set_lock(a, kLockTranslation);
  m.set_load(b, Vec3(5, 0, 0));
  m.set_load(c, Vec3(5, 0, 0));
  m.set_passive(c, true);
  Solver s(m);
  s.compute_forces();
  // T_ab = 10 + 100 (1.1 - 1) = 20 N towards a, plus the 5 N load.
  CHECK(m.particles.force[b].x() == doctest::Approx(-15.0));
  CHECK(m.particles.force[c].isZero());
  CHECK(s.reaction(a).x() == doctest::Approx(-20.0));
  const RunResult coarse = s.run(1e-9, 100000);
  CHECK(coarse.converged);
  CHECK(m.particles.position[c] == Vec3(2.5, 0, 0));
  CHECK(m.particles.velocity[c].isZero());
  CHECK(m.particles.position[b].x() == doctest::Approx(0.95).epsilon(1e-8));
  // Reactivated, c and its cable take part: T_bc = 5 N, T_ab = 10 N, so
  // b at 1.0 and c at 1.95.
  m.set_passive(c, false);
  const RunResult fine = s.run(1e-9, 100000);
  CHECK(fine.converged);
  CHECK(m.particles.position[b].x() == doctest::Approx(1.0).epsilon(1e-8));
  CHECK(m.particles.position[c].x() == doctest::Approx(1.95).epsilon(1e-8));
  CHECK(m.check() == "");
}

TEST_CASE("every integrator leaves a passive particle frozen and its elements out") {
  // The chain of the test above, with each integrator: b settles at 0.95
  // (the a-b cable carrying the 5 N load alone), c stays at 2.5.
  std::vector<Integrator> all(kIntegrators.begin(), kIntegrators.end());
  all.insert(all.end(), kConstraintIntegrators.begin(), kConstraintIntegrators.end());
  for (Integrator integrator : all) {
    CAPTURE(integrator_name(integrator));
    Model m;
    const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1.1, 0, 0)),
                     c = m.add_particle(Vec3(2.5, 0, 0));
    m.add_cable(a, b, Section{100, 0, 10, 0}, 1.0);
    m.add_cable(b, c, Section{100, 0, 10, 0}, 1.0);
    m.set_lock(a, kLockTranslation);
    m.set_load(b, Vec3(5, 0, 0));
    m.set_passive(c, true);
    Solver s(m);
    s.settings.integrator = integrator;
    const RunResult r = s.run(1e-8, 200000);
    CHECK(r.converged);
    CHECK(m.particles.position[c] == Vec3(2.5, 0, 0));
    CHECK(m.particles.position[b].x() == doctest::Approx(0.95).epsilon(1e-7));
  }
}
