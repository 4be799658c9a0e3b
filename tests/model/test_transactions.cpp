// Transactions: everything done between begin and rollback is undone exactly
// (map, columns, particles, blocks, element buffers), and the undo log grows
// with what a production touched, not with the model.
#include <doctest/doctest.h>

#include <random>
#include <sstream>

#include "model/model.hpp"

using namespace tendril;

namespace {

// Every stored bit of the model, as text (hexfloat doubles).
std::string dump(Model& m) {
  std::ostringstream o;
  o << std::hexfloat;
  o << "darts " << m.map.capacity() << ' ' << m.map.dart_count() << '\n';
  for (Dart d = 0; d < m.map.capacity(); ++d) {
    o << d << ':' << m.map.alive(d);
    if (!m.map.alive(d)) {
      o << '\n';
      continue;
    }
    for (int i = 0; i < 3; ++i) o << ' ' << m.map.alpha(i, d);
    const Model& c = m;
    o << ' ' << c.dart_particle[d] << ' ' << c.dart_block[d] << ' ' << c.dart_bar[d] << ' ' << c.dart_hinge[d] << ' '
      << c.ring_next[d] << ' ' << c.ring_prev[d] << ' ' << c.rest_length[d] << ' ' << c.dart_beam6[d] << ' '
      << c.beam_end[d].coeffs().transpose() << '\n';
  }
  const Particles& P = m.particles;
  o << "particles " << P.capacity() << ' ' << P.live << '\n';
  for (ParticleId p = 0; p < P.capacity(); ++p) {
    o << p << ':' << int(P.alive[p]) << ' ' << P.generation[p];
    if (!P.alive[p]) {
      o << '\n';
      continue;
    }
    for (const Vec3* v : {&P.position[p], &P.velocity[p], &P.load[p]}) o << ' ' << v->transpose();
    o << ' ' << P.point_mass[p] << ' ' << P.lumped_mass[p] << ' ' << int(P.lock[p]) << ' ' << int(P.passive[p]) << ' '
      << int(P.active[p]) << ' ' << P.first_dart[p] << ' ' << P.degree[p];
    for (const Vec3* v : {&P.angular_velocity[p], &P.moment[p]}) o << ' ' << v->transpose();
    o << ' ' << P.orientation[p].coeffs().transpose() << ' ' << P.rot_degree[p] << ' ' << P.rotational_slot[p] << '\n';
  }
  o << "rotating";
  for (ParticleId p : P.rotational) o << ' ' << p;
  o << '\n';
  o << "integrated";
  for (ParticleId p : P.integrated) o << ' ' << p << '@' << P.integrated_slot[p];
  o << "\nawake " << m.bars.awake << ' ' << m.hinges.awake << ' ' << m.beam6s.awake << '\n';
  o << "free";
  for (ParticleId p : P.free_slots) o << ' ' << p;
  o << "\nblocks " << m.blocks.size() << ' ' << m.block_count() << '\n';
  for (const Block& b : m.blocks)
    o << int(b.kind) << ' ' << b.closed << ' ' << int(b.dofs) << ' ' << b.section.EA << ' ' << b.section.EI << ' '
      << b.section.GJ << ' ' << b.dart << ' ' << b.darts << ' ' << b.alive << ' ' << b.generation << '\n';
  for (const Bar& b : m.bars.items)
    o << "bar " << b.i << ' ' << b.j << ' ' << b.rest_length << ' ' << b.EA << ' ' << b.dart << '\n';
  for (const Hinge& h : m.hinges.items) o << "hinge " << h.i << ' ' << h.j << ' ' << h.k << ' ' << h.dart << '\n';
  for (const Beam6& b : m.beam6s.items)
    o << "beam6 " << b.i << ' ' << b.j << ' ' << b.end_i.coeffs().transpose() << ' ' << b.end_j.coeffs().transpose()
      << ' ' << b.rest_length << ' ' << b.GJ << ' ' << b.dart << '\n';
  return o.str();
}

struct Scene {
  Model m;
  std::vector<ParticleId> ps;
  Scene() {
    for (int b = 0; b < 4; ++b) {
      std::vector<ParticleId> row;
      for (int i = 0; i < 8; ++i) row.push_back(m.add_particle(Vec3(i, b, 0.1 * i * b)));
      m.add_beam(row, Section{1e6, 10, 0, 0.5}, b == 3);
      ps.insert(ps.end(), row.begin(), row.end());
    }
    m.add_cable(ps[0], ps[8], Section{1e4, 0, 5, 0.1});
    m.add_cable(ps[9], ps[17], Section{1e4, 0, 5, 0.1});
    m.set_lock(ps[0], kLockTranslation);
    m.set_beam_formulation(1, 6);  // the second row and the ring rotate
    m.set_beam_formulation(3, 6);
  }
  // One random primitive operation; invalid ones throw and change nothing.
  void random_op(std::mt19937& rng) {
    auto any = [&] {
      std::vector<ParticleId> live;
      for (ParticleId p = 0; p < m.particles.capacity(); ++p)
        if (m.particles.valid(p)) live.push_back(p);
      return live[rng() % live.size()];
    };
    try {
      switch (rng() % 12) {
        case 0: m.insert_particle(any(), any()); break;
        case 1: m.remove_from_beam(any()); break;
        case 2: m.merge({any(), any()}); break;
        case 3: m.explode(any()); break;
        case 4: m.add_cable(any(), any(), Section{1e3, 0, 0, 0}); break;
        case 5: m.add_beam_from(any(), Vec3(0, 0, 1), 3, Section{1e5, 1, 0, 0.2}); break;
        case 6: m.particles.position[any()] += Vec3(0.01, 0, 0); break;
        case 7: m.set_lock(any(), kLockZ); break;
        case 8: {
          auto bs = m.live_blocks();
          BlockId b = bs[rng() % bs.size()];
          if (m.blocks[b].kind == BlockKind::Cable) m.delete_cable(b);
          else m.delete_beam(b);
          break;
        }
        case 9: {
          auto bs = m.live_blocks();
          m.set_beam_formulation(bs[rng() % bs.size()], rng() % 2 ? 6 : 3);
          break;
        }
        case 10: m.set_orientation(any(), Quat(0.5, 0.5, 0.5, 0.5)); break;
        case 11: m.set_passive(any(), rng() % 2); break;  // elements change sides
      }
    } catch (const ModelError&) {
    }
  }
};

}  // namespace

TEST_CASE("rollback restores every stored bit after a sequence of operations") {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    CAPTURE(seed);
    Scene s;
    std::mt19937 rng(seed);
    for (int warm = 0; warm < 20; ++warm) s.random_op(rng);  // holes, recycled slots
    REQUIRE(s.m.check() == "");
    const std::string before = dump(s.m);
    s.m.begin_transaction();
    for (int k = 0; k < 30; ++k) s.random_op(rng);
    CHECK(dump(s.m) != before);
    s.m.rollback_transaction();
    CHECK(dump(s.m) == before);
    CHECK(s.m.check() == "");
    // The model goes on working after a rollback.
    for (int k = 0; k < 30; ++k) s.random_op(rng);
    CHECK(s.m.check() == "");
  }
}

TEST_CASE("commit keeps the changes and stops logging") {
  Scene s;
  s.m.begin_transaction();
  ParticleId q = s.m.insert_particle(s.ps[1], s.ps[2]);
  s.m.commit_transaction();
  CHECK_FALSE(s.m.in_transaction());
  CHECK(s.m.particle_valid(q));
  CHECK(s.m.map.undo_log().size() == 0);
  s.m.particles.position[q] = Vec3(9, 9, 9);  // outside a transaction: not logged
  CHECK(s.m.map.undo_log().size() == 0);
  CHECK_THROWS_AS((s.m.begin_transaction(), s.m.begin_transaction()), std::logic_error);
  s.m.rollback_transaction();
  CHECK(s.m.check() == "");
}

TEST_CASE("the undo log of one rule 13 does not grow with the model") {
  auto entries = [](int beams) {
    Model m;
    std::vector<ParticleId> first;
    for (int b = 0; b < beams; ++b) {
      std::vector<ParticleId> row;
      for (int i = 0; i < 10; ++i) row.push_back(m.add_particle(Vec3(i, b, 0)));
      m.add_beam(row, Section{1e6, 10, 0, 0});
      first.push_back(row[4]);
    }
    m.begin_transaction();
    ParticleId mid = first[first.size() / 2];
    m.insert_particle(mid, m.particles_of(m.blocks_of(mid)[0])[5]);
    std::size_t n = m.map.undo_log().size();
    m.rollback_transaction();
    return n;
  };
  const std::size_t small = entries(10), large = entries(10000);
  CHECK(small > 0);
  CHECK(large <= small + 4);  // vector growth may log a few more lengths
}

TEST_CASE("the undo log of a formulation switch and of rule 13 on a 6-DOF beam does not grow with the model") {
  auto entries = [](int beams, bool insert) {
    Model m;
    std::vector<ParticleId> first;
    std::vector<BlockId> ids;
    for (int b = 0; b < beams; ++b) {
      std::vector<ParticleId> row;
      for (int i = 0; i < 10; ++i) row.push_back(m.add_particle(Vec3(i, b, 0)));
      ids.push_back(m.add_beam(row, Section{1e6, 10, 0, 0}));
      if (b % 2) m.set_beam_formulation(ids.back(), 6);  // half the model rotates
      first.push_back(row[4]);
    }
    const BlockId target = ids[2 * (ids.size() / 4) + 1];  // a 6-DOF beam
    m.begin_transaction();
    if (insert) {
      const auto ps = m.particles_of(target);
      m.insert_particle(ps[4], ps[5]);
    } else {
      m.set_beam_formulation(target, 3);
      m.set_beam_formulation(target, 6);
    }
    std::size_t n = m.map.undo_log().size();
    m.rollback_transaction();
    CHECK(m.check() == "");
    return n;
  };
  for (bool insert : {false, true}) {
    CAPTURE(insert);
    const std::size_t small = entries(10, insert), large = entries(4000, insert);
    CHECK(small > 0);
    CHECK(large <= small + 8);  // vector growth may log a few more lengths
  }
}
