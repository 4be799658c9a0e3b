// Vertex states of thesis 4.2.6 as Model::state derives them: from the number
// of references a particle holds (blocks; a loop's beam twice, test_loops.cpp),
// its passive flag and its lock bits, never set by hand; and how they follow
// the primitive operations.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "model/model.hpp"

using namespace tendril;

namespace {

Section section() {
  Section s;
  s.EA = 1e5;
  s.EI = 1;
  return s;
}

}  // namespace

TEST_CASE("state: isolated, simple and shared follow the number of blocks") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0));
  const ParticleId b = m.add_particle(Vec3(1, 0, 0));
  const ParticleId c = m.add_particle(Vec3(2, 0, 0));
  CHECK(m.state(a) == State::Isolated);

  const BlockId c1 = m.add_cable(a, b, section());
  CHECK(m.state(a) == State::Simple);
  CHECK(m.state(b) == State::Simple);
  CHECK(m.state(c) == State::Isolated);

  const BlockId beam = m.add_beam({b, c}, section());
  CHECK(m.state(b) == State::Shared);
  CHECK(m.state(c) == State::Simple);
  CHECK(m.blocks_of(b) == std::vector<BlockId>{c1, beam});

  // Two darts of one block (a beam interior) are still one block: simple.
  const ParticleId d = m.add_particle(Vec3(3, 0, 0));
  const ParticleId e = m.add_particle(Vec3(4, 0, 0));
  m.add_beam({c, d, e}, section());
  CHECK(m.state(d) == State::Simple);
  CHECK(m.state(c) == State::Shared);

  m.delete_beam(beam);
  CHECK(m.state(b) == State::Simple);
  CHECK(m.check() == "");
}

TEST_CASE("state: passive, lock and full-lock take precedence, isolated first") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0));
  const ParticleId b = m.add_particle(Vec3(1, 0, 0));
  const ParticleId c = m.add_particle(Vec3(2, 0, 0));
  m.add_cable(a, b, section());
  m.add_cable(b, c, section());
  REQUIRE(m.state(b) == State::Shared);

  for (std::uint8_t bit : {kLockX, kLockY, kLockZ}) {
    m.set_lock(b, bit);
    CHECK(m.state(b) == State::Lock);
  }
  for (std::uint8_t bit : {kLockRX, kLockRY, kLockRZ}) {
    m.set_lock(b, bit);
    CHECK(m.state(b) == State::FullLock);
    m.set_lock(b, std::uint8_t(bit | kLockTranslation));
    CHECK(m.state(b) == State::FullLock);
  }
  m.set_lock(a, kLockTranslation);
  CHECK(m.state(a) == State::Lock);  // a simple particle locks the same way

  m.set_passive(b, true);
  CHECK(m.state(b) == State::Passive);  // passive wins over the lock
  CHECK(m.particles.active[b] == 0);
  m.set_passive(b, false);
  CHECK(m.state(b) == State::FullLock);
  CHECK(m.particles.active[b] == 1);
  m.set_lock(b, 0);
  CHECK(m.state(b) == State::Shared);

  // Isolated wins over everything: a passive or locked particle without blocks.
  const ParticleId lone = m.add_particle(Vec3(5, 5, 5));
  m.set_passive(lone, true);
  m.set_lock(lone, kLockRX);
  CHECK(m.state(lone) == State::Isolated);
  CHECK(m.particles.active[lone] == 0);
  CHECK(m.check() == "");
}

TEST_CASE("state: operations move particles between states") {
  Model m;
  std::vector<ParticleId> ps;
  for (int k = 0; k < 4; ++k) ps.push_back(m.add_particle(Vec3(k, 0, 0)));
  const BlockId beam = m.add_beam(ps, section());
  const ParticleId top = m.add_particle(Vec3(1, 3, 0));
  const BlockId cable = m.add_cable(top, m.add_particle(Vec3(1, 6, 0)), section());

  // Rule 3 joins two simple particles into a shared one.
  const ParticleId j = m.merge({ps[1], top});
  CHECK(m.state(j) == State::Shared);
  CHECK(m.blocks_of(j) == std::vector<BlockId>{beam, cable});

  // Rule 5 detaches the cable: both copies are simple again.
  REQUIRE_FALSE(m.particles.free_slots.empty());  // a recycled slot
  const ParticleId k = m.explode_from(j, cable);
  CHECK(m.state(j) == State::Simple);
  CHECK(m.state(k) == State::Simple);
  CHECK(m.blocks_of(k) == std::vector<BlockId>{cable});

  // Rule 13 adds a simple particle; rule 11 removes one.
  const ParticleId mid = m.insert_particle(ps[2], ps[3]);
  CHECK(m.state(mid) == State::Simple);
  m.remove_from_beam(mid);
  CHECK_FALSE(m.particle_valid(mid));
  CHECK_THROWS_AS(m.state(mid), ModelError);

  // Rule 7 deletes the cable and, by rule 2, its particles: their handles go stale.
  m.delete_cable(cable);
  CHECK_FALSE(m.particle_valid(k));
  CHECK(m.state(j) == State::Simple);
  CHECK(m.check() == "");
}

TEST_CASE("state names") {
  CHECK(std::string(state_name(State::Isolated)) == "isolated");
  CHECK(std::string(state_name(State::Passive)) == "passive");
  CHECK(std::string(state_name(State::Lock)) == "lock");
  CHECK(std::string(state_name(State::FullLock)) == "full-lock");
  CHECK(std::string(state_name(State::Simple)) == "simple");
  CHECK(std::string(state_name(State::Shared)) == "shared");
  CHECK(std::string(block_kind_name(BlockKind::Cable)) == "cable");
  CHECK(std::string(block_kind_name(BlockKind::Beam)) == "beam");
  CHECK(std::string(block_kind_name(BlockKind::Patch)) == "patch");
}
