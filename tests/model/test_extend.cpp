// Rule 9: a beam grown particle by particle from either end.
#include <doctest/doctest.h>

#include "model/model.hpp"

using namespace tendril;

TEST_CASE("extend_beam grows an open beam at either end") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
  BlockId beam = m.add_beam({a, b, c}, Section{1e6, 10, 0, 2});
  ParticleId d = m.add_particle(Vec3(3, 0.5, 0));
  m.extend_beam(beam, c, d);
  CHECK(m.check() == "");
  CHECK(m.particles_of(beam) == std::vector<ParticleId>{a, b, c, d});
  CHECK(m.hinges.size() == 2);
  CHECK(m.bars.size() == 3);
  ParticleId z = m.add_particle(Vec3(-1, 0, 0));
  m.extend_beam(beam, a, z);
  CHECK(m.check() == "");
  CHECK(m.particles_of(beam) == std::vector<ParticleId>{z, a, b, c, d});
  CHECK(m.particles.lumped_mass[z] == doctest::Approx(1.0));  // 2 kg/m over half of 1 m
  CHECK(m.state(d) == State::Simple);
  CHECK_THROWS_AS(m.extend_beam(beam, b, m.add_particle(Vec3(5, 5, 5))), ModelError);  // not an end
  CHECK_THROWS_AS(m.extend_beam(beam, d, a), ModelError);                               // already on it
  CHECK(m.check() == "");
}
