// Loops and reverted connections (thesis 6.2, 6.3.1): a beam joined to itself
// by rule 3 holds two references at the joint, so the joint is shared and
// rules 4 and 5 disconnect it again; rule 4 on a particle rule 3 made puts
// every particle back where it was relative to the joint, with its own locks.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>

#include "model/model.hpp"

namespace tendril {
namespace {

const Section kRod{1e6, 10};  // EA, EI

// An open beam of n particles on an arc of `turn` radians of a unit circle.
std::vector<ParticleId> arc(Model& m, int n, double turn, BlockId* beam) {
  std::vector<ParticleId> ps;
  for (int k = 0; k < n; ++k) {
    const double a = turn * k / (n - 1);
    ps.push_back(m.add_particle(Vec3(std::sin(a), 0, 1 - std::cos(a))));
  }
  *beam = m.add_beam(ps, kRod);
  return ps;
}

}  // namespace

TEST_CASE("a drop with a single joint: the joint holds the beam twice and is shared; rule 4 opens it") {
  Model m;
  BlockId beam;
  const auto ps = arc(m, 12, 1.8 * M_PI, &beam);
  const ParticleId joint = m.merge({ps.front(), ps.back()});
  CHECK(m.check() == "");
  CHECK(m.blocks_of(joint) == std::vector<BlockId>{beam});
  CHECK(m.references_of(joint) == std::vector<BlockId>{beam, beam});
  CHECK(m.state(joint) == State::Shared);
  CHECK(m.state(ps[5]) == State::Simple);

  const auto out = m.explode(joint);
  CHECK(m.check() == "");
  REQUIRE(out.size() == 2);
  const auto path = m.particles_of(beam);
  CHECK(path.front() == out[0]);  // the beam's start end comes first (its smaller dart)
  CHECK(path.back() == out[1]);
  // Back where the two ends were before the merge, exactly.
  CHECK((m.particles.position[out[0]] - Vec3(0, 0, 0)).norm() < 1e-15);
  const double a = 1.8 * M_PI;
  CHECK((m.particles.position[out[1]] - Vec3(std::sin(a), 0, 1 - std::cos(a))).norm() < 1e-15);
  CHECK(m.state(out[0]) == State::Simple);
  CHECK(m.state(out[1]) == State::Simple);
}

TEST_CASE("a drop with a double joint and a ring loop: rule 5 opens the loop at one joint") {
  Model m;
  BlockId beam;
  const auto ps = arc(m, 14, 1.8 * M_PI, &beam);
  const std::size_t n = ps.size();
  SUBCASE("double joint, inverse order") {
    const ParticleId j1 = m.merge({ps[0], ps[n - 1]});
    const ParticleId j2 = m.merge({ps[1], ps[n - 2]});
    CHECK(m.check() == "");
    CHECK(m.state(j1) == State::Shared);
    CHECK(m.state(j2) == State::Shared);
    const ParticleId q = m.explode_from(j2, beam);  // the beam is all j2 holds: one end leaves
    CHECK(m.check() == "");
    CHECK(m.state(j2) == State::Simple);
    CHECK(m.state(q) == State::Simple);
    CHECK(m.references_of(j1).size() == 2);
    const auto out = m.explode(j1);
    CHECK(m.check() == "");
    CHECK(out.size() == 2);
    CHECK(m.particle_count() == n);
    CHECK_FALSE(m.blocks[beam].closed);
  }
  SUBCASE("ring, ascending order") {
    const ParticleId j1 = m.merge({ps[0], ps[n - 2]});
    const ParticleId j2 = m.merge({ps[1], ps[n - 1]});
    CHECK(m.check() == "");
    CHECK(m.references_of(j1) == std::vector<BlockId>{beam, beam});
    CHECK(m.references_of(j2) == std::vector<BlockId>{beam, beam});
    m.explode(j1);
    m.explode(j2);
    CHECK(m.check() == "");
    CHECK(m.particle_count() == n);
    for (ParticleId p : m.particles_of(beam)) CHECK(m.state(p) == State::Simple);
  }
}

TEST_CASE("a loop joint with a cable on it: rule 5 takes the beam's references together, rule 4 one particle each") {
  Model m;
  BlockId beam;
  const auto ps = arc(m, 10, 1.8 * M_PI, &beam);
  const ParticleId joint = m.merge({ps.front(), ps.back()});
  const ParticleId anchor = m.add_particle(Vec3(0, 0, -1));
  const BlockId cable = m.add_cable(anchor, joint, Section{1e4});
  CHECK(m.references_of(joint) == std::vector<BlockId>{beam, beam, cable});
  SUBCASE("rule 5") {
    const ParticleId q = m.explode_from(joint, beam);
    CHECK(m.check() == "");
    CHECK(m.references_of(q) == std::vector<BlockId>{beam, beam});  // the loop stays closed on q
    CHECK(m.references_of(joint) == std::vector<BlockId>{cable});
  }
  SUBCASE("rule 4") {
    const auto out = m.explode(joint);
    CHECK(m.check() == "");
    CHECK(out.size() == 3);
    CHECK(m.blocks_of(out[2]) == std::vector<BlockId>{cable});
  }
}

TEST_CASE("rule 4 reverts rule 3: positions relative to the joint, each particle's own locks") {
  Model m;
  const ParticleId a0 = m.add_particle(Vec3(0, 0, 0)), a1 = m.add_particle(Vec3(1, 0, 0));
  const ParticleId b0 = m.add_particle(Vec3(1.2, 0.4, 0)), b1 = m.add_particle(Vec3(2, 1, 0));
  const ParticleId c0 = m.add_particle(Vec3(1.0, -0.3, 0.2)), c1 = m.add_particle(Vec3(1, -2, 0));
  const BlockId a = m.add_beam({a0, a1}, kRod), b = m.add_beam({b0, b1}, kRod), c = m.add_beam({c0, c1}, kRod);
  m.set_lock(b0, kLockZ);
  const ParticleId ab = m.merge({a1, b0});
  CHECK(m.particles.lock[ab] == kLockZ);
  const ParticleId abc = m.merge({ab, c0});  // a merge of a merge: each end remembers its own particle
  CHECK(m.references_of(abc) == std::vector<BlockId>{a, b, c});
  const Vec3 joint = m.particles.position[abc];

  SUBCASE("at once: every end back exactly") {
    const auto out = m.explode(abc);
    CHECK(m.check() == "");
    REQUIRE(out.size() == 3);
    CHECK((m.particles.position[out[0]] - Vec3(1, 0, 0)).norm() < 1e-15);
    CHECK((m.particles.position[out[1]] - Vec3(1.2, 0.4, 0)).norm() < 1e-15);
    CHECK((m.particles.position[out[2]] - Vec3(1.0, -0.3, 0.2)).norm() < 1e-15);
    CHECK(m.particles.lock[out[0]] == 0);
    CHECK(m.particles.lock[out[1]] == kLockZ);
    CHECK(m.particles.lock[out[2]] == 0);
  }
  SUBCASE("after the joint moved and was locked: relative to where it is, the new lock on all") {
    const Vec3 shift(0.5, -0.25, 2);
    m.particles.position[abc] = joint + shift;
    m.set_lock(abc, kLockX);  // z released, x added since the merges
    const auto out = m.explode(abc);
    CHECK((m.particles.position[out[1]] - (Vec3(1.2, 0.4, 0) + shift)).norm() < 1e-14);
    CHECK(m.particles.lock[out[0]] == kLockX);
    CHECK(m.particles.lock[out[1]] == kLockX);
    CHECK(m.particles.lock[out[2]] == kLockX);
  }
  SUBCASE("rule 5 places the detached end the same way; a second explode starts afresh") {
    const ParticleId q = m.explode_from(abc, c);
    CHECK((m.particles.position[q] - Vec3(1.0, -0.3, 0.2)).norm() < 1e-15);
    CHECK(m.particles.position[abc] == joint);  // the rest stays connected where it is
    const auto out = m.explode(abc);
    CHECK((m.particles.position[out[0]] - Vec3(1, 0, 0)).norm() < 1e-15);
    const ParticleId again = m.merge({out[0], out[1]});
    const auto back = m.explode(again);  // offsets from this merge only
    CHECK((m.particles.position[back[0]] - Vec3(1, 0, 0)).norm() < 1e-15);
    CHECK((m.particles.position[back[1]] - Vec3(1.2, 0.4, 0)).norm() < 1e-15);
  }
  SUBCASE("a rolled-back explode restores the memory of the merge") {
    m.begin_transaction();
    m.explode(abc);
    m.rollback_transaction();
    CHECK(m.check() == "");
    const auto out = m.explode(abc);
    CHECK((m.particles.position[out[2]] - Vec3(1.0, -0.3, 0.2)).norm() < 1e-15);
  }
}

TEST_CASE("particles exploded from one that was never merged stay where it is") {
  Model m;
  const ParticleId p = m.add_particle(Vec3(1, 2, 3));
  const BlockId c1 = m.add_cable(p, m.add_particle(Vec3(0, 0, 0)), Section{1e4});
  m.add_cable(p, m.add_particle(Vec3(5, 0, 0)), Section{1e4});
  const auto out = m.explode(p);
  for (ParticleId q : out) CHECK(m.particles.position[q] == Vec3(1, 2, 3));
  CHECK(m.blocks_of(out[0]) == std::vector<BlockId>{c1});
}

}  // namespace tendril
