// Rule 16 (split_beam) and set_rest_length.
#include <doctest/doctest.h>

#include <cmath>

#include "model/model.hpp"

using namespace tendril;

namespace {
std::vector<ParticleId> line(Model& m, int n) {
  std::vector<ParticleId> ps;
  for (int k = 0; k < n; ++k) ps.push_back(m.add_particle(Vec3(k, 0.1 * k * k, 0)));
  return ps;
}
}  // namespace

TEST_CASE("split_beam breaks an open beam at an interior simple particle") {
  Model m;
  auto ps = line(m, 5);
  BlockId b = m.add_beam(ps, Section{1e6, 10, 0, 2});
  m.particles.velocity[ps[2]] = Vec3(1, 2, 3);
  m.set_lock(ps[2], kLockTranslation);
  CHECK(m.hinges.size() == 3);
  auto [q, nb] = m.split_beam(b, ps[2]);
  CHECK(m.check() == "");
  CHECK(nb != b);
  CHECK(m.block_count() == 2);
  CHECK(m.particle_count() == 6);
  CHECK(m.bars.size() == 4);
  CHECK(m.hinges.size() == 2);
  CHECK(m.particles_of(b) == std::vector<ParticleId>{ps[0], ps[1], ps[2]});
  CHECK(m.particles_of(nb) == std::vector<ParticleId>{q, ps[3], ps[4]});
  CHECK(m.particles.position[q] == m.particles.position[ps[2]]);
  CHECK(m.particles.velocity[q] == Vec3(1, 2, 3));
  CHECK(m.particles.lock[q] == kLockTranslation);
  CHECK(m.blocks[nb].section.EI == 10);
  CHECK(m.blocks[nb].darts == 4);
  CHECK(m.blocks[b].darts == 4);
  CHECK(m.state(q) == State::Lock);
  CHECK(m.state(ps[1]) == State::Simple);
  // Lumped masses: each end keeps half of its one segment.
  CHECK(m.particles.lumped_mass[q] == doctest::Approx(0.5 * 2 * (m.particles.position[ps[3]] - m.particles.position[q]).norm()));
}

TEST_CASE("split_beam refusals leave the model unchanged") {
  Model m;
  auto ps = line(m, 4);
  BlockId b = m.add_beam(ps, Section{1e6, 10, 0, 2});
  ParticleId x = m.add_particle(Vec3(1, 5, 0));
  BlockId c = m.add_cable(ps[1], x, Section{1e4, 0, 0, 0});
  CHECK_THROWS_AS(m.split_beam(b, ps[0]), ModelError);  // an end
  CHECK_THROWS_AS(m.split_beam(b, ps[1]), ModelError);  // shared
  CHECK_THROWS_AS(m.split_beam(c, x), ModelError);      // not a beam
  CHECK_THROWS_AS(m.split_beam(b, x), ModelError);      // not on the beam
  CHECK(m.check() == "");
  CHECK(m.block_count() == 2);
  CHECK(m.particle_count() == 5);
  CHECK(m.particles_of(b) == ps);
  // Rule 17: explode from the beam, then split at the copy.
  ParticleId p1 = m.explode_from(ps[1], b);
  auto [q, nb] = m.split_beam(b, p1);
  CHECK(m.check() == "");
  CHECK(m.particles_of(b) == std::vector<ParticleId>{ps[0], p1});
  CHECK(m.particles_of(nb) == std::vector<ParticleId>{q, ps[2], ps[3]});
  CHECK(m.state(ps[1]) == State::Simple);  // on the cable alone
}

TEST_CASE("split_beam opens a ring into one beam") {
  Model m;
  std::vector<ParticleId> ps;
  for (int k = 0; k < 4; ++k) ps.push_back(m.add_particle(Vec3(std::cos(k * 1.5708), std::sin(k * 1.5708), 0)));
  BlockId b = m.add_beam(ps, Section{1e6, 10, 0, 1}, true);
  CHECK(m.hinges.size() == 4);
  auto [q, nb] = m.split_beam(b, ps[2]);
  CHECK(m.check() == "");
  CHECK(nb == b);
  CHECK(!m.blocks[b].closed);
  CHECK(m.block_count() == 1);
  CHECK(m.hinges.size() == 3);
  CHECK(m.bars.size() == 4);
  CHECK(m.particles_of(b) == std::vector<ParticleId>{q, ps[3], ps[0], ps[1], ps[2]});
}

TEST_CASE("split_beam rolls back in a transaction") {
  Model m;
  auto ps = line(m, 5);
  BlockId b = m.add_beam(ps, Section{1e6, 10, 0, 2});
  const std::size_t bars = m.bars.size(), hinges = m.hinges.size();
  const double mass = m.particles.lumped_mass[ps[2]];
  m.begin_transaction();
  m.split_beam(b, ps[2]);
  m.set_rest_length(ps[0], ps[1], 3.0);
  m.rollback_transaction();
  CHECK(m.check() == "");
  CHECK(m.block_count() == 1);
  CHECK(m.particle_count() == 5);
  CHECK(m.particles_of(b) == ps);
  CHECK(m.bars.size() == bars);
  CHECK(m.hinges.size() == hinges);
  CHECK(m.particles.lumped_mass[ps[2]] == mass);
  CHECK(m.edge_rest_length(ps[0], ps[1]) == doctest::Approx((m.particles.position[ps[1]] - m.particles.position[ps[0]]).norm()));
}

TEST_CASE("split_beam on a 6-DOF beam keeps valid Beam6 elements") {
  Model m;
  auto ps = line(m, 5);
  BlockId b = m.add_beam(ps, Section{1e6, 10, 0, 2});
  m.set_beam_formulation(b, 6);
  CHECK(m.check() == "");
  auto [q, nb] = m.split_beam(b, ps[2]);
  CHECK(m.check() == "");
  CHECK(m.beam_formulation(nb) == 6);
  CHECK(m.beam6s.size() == 4);
  CHECK(m.bars.size() == 0);
  CHECK(m.particles_of(nb) == std::vector<ParticleId>{q, ps[3], ps[4]});
  m.set_rest_length(q, ps[3], 2.0);
  CHECK(m.check() == "");
  CHECK(m.beam6s[m.dart_beam6[m.particles.first_dart[q]]].rest_length == 2.0);
}

TEST_CASE("set_rest_length changes one edge and its lumped masses") {
  Model m;
  auto ps = line(m, 3);
  m.add_beam(ps, Section{1e6, 10, 0, 2});
  const double before = m.particles.lumped_mass[ps[0]];
  m.set_rest_length(ps[1], ps[0], 4.0);
  CHECK(m.check() == "");
  CHECK(m.edge_rest_length(ps[0], ps[1]) == 4.0);
  CHECK(m.particles.lumped_mass[ps[0]] == doctest::Approx(4.0));
  CHECK(before != doctest::Approx(4.0));
  CHECK_THROWS_AS(m.set_rest_length(ps[0], ps[1], 0), ModelError);
  CHECK_THROWS_AS(m.set_rest_length(ps[0], ps[2], 1), ModelError);
  CHECK(m.edge_rest_length(ps[0], ps[1]) == 4.0);
}
