// Patch rules 23, 24, 26 and 27: remove_from_patch, explode_from + remove,
// merge_patches and delete_patch; counts, refusals and rollback.
#include <doctest/doctest.h>

#include "model/model.hpp"

using namespace tendril;

namespace {
const Section kSection{1e3, 0, 0, 0};

std::vector<ParticleId> grid_particles(Model& m, int rows, int cols, double x0 = 0) {
  std::vector<ParticleId> ps;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) ps.push_back(m.add_particle(Vec3(x0 + c, r, 0)));
  return ps;
}

// Quads of the grid cells in columns [c0, c1) of a rows x cols particle grid.
std::vector<Model::Quad> cells(const std::vector<ParticleId>& p, int rows, int cols, int c0, int c1) {
  std::vector<Model::Quad> q;
  for (int r = 0; r + 1 < rows; ++r)
    for (int c = c0; c < c1; ++c) q.push_back({p[r * cols + c], p[r * cols + c + 1], p[(r + 1) * cols + c + 1], p[(r + 1) * cols + c]});
  return q;
}

struct Counts {
  std::size_t darts, bars, blocks, particles;
  bool operator==(const Counts&) const = default;
};
Counts counts(const Model& m) { return {m.map.dart_count(), m.bars.size(), m.block_count(), m.particle_count()}; }
}  // namespace

TEST_CASE("delete_patch removes darts and bars; particles still on a cable survive") {
  Model m;
  auto p = grid_particles(m, 3, 3);
  BlockId patch = m.add_quad_grid(p, 3, 3, kSection);
  ParticleId q = m.add_particle(Vec3(0, 0, 2));
  BlockId cable = m.add_cable(p[0], q, kSection);
  CHECK(counts(m) == Counts{34, 13, 2, 10});
  CHECK(m.state(p[0]) == State::Shared);
  m.delete_patch(patch);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{2, 1, 1, 2});
  CHECK(m.state(p[0]) == State::Simple);
  CHECK(m.block_valid(cable));
  CHECK_FALSE(m.block_valid(patch));
  CHECK_FALSE(m.particle_valid(p[4]));
  CHECK_THROWS_WITH_AS(m.delete_patch(cable), doctest::Contains("is not a patch"), ModelError);
  CHECK_THROWS_WITH_AS(m.delete_patch(patch), doctest::Contains("does not exist"), ModelError);
  CHECK(counts(m) == Counts{2, 1, 1, 2});
  CHECK(m.check() == "");
}

TEST_CASE("remove_from_patch drops a corner quad, or the whole patch from its centre") {
  Model m;
  auto p = grid_particles(m, 3, 3);
  BlockId b = m.add_quad_grid(p, 3, 3, kSection);
  CHECK(counts(m) == Counts{32, 12, 1, 9});
  m.remove_from_patch(p[0]);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{24, 10, 1, 8});  // one quad and its two outer edges go
  CHECK_FALSE(m.particle_valid(p[0]));
  CHECK(m.state(p[1]) == State::Simple);
  CHECK(m.particles_of(b).size() == 8);
  m.remove_from_patch(p[4]);  // the centre touches the three quads left
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{0, 0, 0, 0});
  CHECK_FALSE(m.block_valid(b));
}

TEST_CASE("remove_from_patch splits a strip into two patches with the same section") {
  Model m;
  auto p = grid_particles(m, 2, 6);  // top row p0..p5, bottom row p6..p11: five quads
  Section s{2e3, 0, 5, 0.1};
  BlockId b = m.add_quad_grid(p, 2, 6, s);
  CHECK(counts(m) == Counts{40, 16, 1, 12});
  m.remove_from_patch(p[2]);  // quads 1 and 2 go; p8 is left isolated
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{24, 11, 2, 10});
  CHECK_FALSE(m.particle_valid(p[8]));
  auto live = m.live_blocks();
  REQUIRE(live.size() == 2);
  BlockId other = live[0] == b ? live[1] : live[0];
  CHECK(m.blocks[other].kind == BlockKind::Patch);
  CHECK(m.blocks[other].section.EA == 2e3);
  CHECK(m.blocks[other].section.prestress == 5);
  std::size_t sizes = m.particles_of(b).size() * 10 + m.particles_of(other).size();
  CHECK((sizes == 46 || sizes == 64));  // a lone quad (4 particles) and two quads (6)
  CHECK(m.state(p[3]) == State::Simple);
  CHECK(m.state(p[1]) == State::Simple);
}

TEST_CASE("remove_from_patch refuses shared, locked, passive and beam particles, leaving the model unchanged") {
  Model m;
  auto p = grid_particles(m, 3, 3);
  m.add_quad_grid(p, 3, 3, kSection);
  ParticleId q = m.add_particle(Vec3(0, 0, 2));
  m.add_cable(p[0], q, kSection);
  ParticleId r = m.add_particle(Vec3(5, 0, 0)), t = m.add_particle(Vec3(6, 0, 0)), u = m.add_particle(Vec3(7, 0, 0));
  m.add_beam({r, t, u}, Section{1e3, 1, 0, 0});
  m.set_lock(p[8], kLockTranslation);
  m.set_passive(p[6], true);
  ParticleId lone = m.add_particle(Vec3(9, 9, 9));
  const Counts before = counts(m);
  CHECK(before == Counts{32 + 2 + 4, 12 + 1 + 2, 3, 14});
  for (ParticleId x : {p[0], p[8], p[6], t, lone})
    CHECK_THROWS_WITH_AS(m.remove_from_patch(x), doctest::Contains("only a simple particle of one patch"), ModelError);
  CHECK_THROWS_WITH_AS(m.remove_from_patch(999), doctest::Contains("does not exist"), ModelError);
  CHECK(counts(m) == before);
  CHECK(m.check() == "");
  // Rule 24: explode the shared particle from the patch, then rule 23.
  ParticleId own = m.explode_from(p[0], 0);
  CHECK(m.state(p[0]) == State::Simple);  // on the cable only
  m.remove_from_patch(own);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{30, 13, 3, 14});
}

TEST_CASE("merge_patches sews two patches along their common column") {
  Model m;
  auto p = grid_particles(m, 3, 5);  // column 2 is common
  BlockId a = m.add_patch(cells(p, 3, 5, 0, 2), kSection);
  BlockId b = m.add_patch(cells(p, 3, 5, 2, 4), Section{5e3, 0, 0, 0});
  CHECK(counts(m) == Counts{64, 24, 2, 15});
  CHECK(m.state(p[7]) == State::Shared);
  CHECK(m.merge_patches(a, b) == a);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{64, 22, 1, 15});  // as a 2 x 4 quad grid
  CHECK_FALSE(m.block_valid(b));
  CHECK(m.state(p[7]) == State::Simple);
  CHECK(m.particles_of(a).size() == 15);
  std::size_t sewn = 0;
  for (Dart d = 0; d < m.map.capacity(); ++d) sewn += m.map.alive(d) && !m.map.is_free(2, d);
  CHECK(sewn == 4 * 10);  // 10 interior edges, 4 darts each
  for (std::size_t e = 0; e < m.bars.size(); ++e) CHECK(m.bars[e].EA == 1e3);  // a's section everywhere
  // Rule 23 on the merged patch works across the seam.
  m.remove_from_patch(p[7]);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{32, 14, 2, 12});  // columns 0 and 3 remain, apart
}

TEST_CASE("merge_patches refuses patches without a common boundary edge and third quads on an edge") {
  Model m;
  auto p = grid_particles(m, 3, 3);
  BlockId a = m.add_quad_grid(p, 3, 3, kSection);
  ParticleId x = m.add_particle(Vec3(3, 3, 0)), y = m.add_particle(Vec3(2, 3, 0)), z = m.add_particle(Vec3(3, 2, 0));
  BlockId corner = m.add_patch({{p[8], y, x, z}}, kSection);  // touches a at one particle
  ParticleId u = m.add_particle(Vec3(0, 1, 1)), v = m.add_particle(Vec3(1, 1, 1));
  BlockId fin = m.add_patch({{p[1], p[4], v, u}}, kSection);  // on a's interior edge p1-p4
  ParticleId c = m.add_particle(Vec3(9, 0, 0));
  BlockId cable = m.add_cable(p[2], c, kSection);
  const Counts before = counts(m);
  CHECK(before == Counts{32 + 8 + 8 + 2, 12 + 4 + 4 + 1, 4, 9 + 3 + 2 + 1});
  CHECK_THROWS_WITH_AS(m.merge_patches(a, corner), doctest::Contains("share no boundary edge"), ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(a, fin), doctest::Contains("more than two quads"), ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(fin, a), doctest::Contains("more than two quads"), ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(a, a), doctest::Contains("both arguments"), ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(a, cable), doctest::Contains("is not a patch"), ModelError);
  CHECK_THROWS_WITH_AS(m.merge_patches(a, 77), doctest::Contains("does not exist"), ModelError);
  CHECK(counts(m) == before);
  CHECK(m.check() == "");
}

TEST_CASE("patch operations roll back inside a transaction") {
  Model m;
  auto p = grid_particles(m, 3, 5);
  BlockId a = m.add_patch(cells(p, 3, 5, 0, 2), kSection);
  BlockId b = m.add_patch(cells(p, 3, 5, 2, 4), kSection);
  const Counts before = counts(m);
  auto same = [&] {
    CHECK(m.check() == "");
    CHECK(counts(m) == before);
    CHECK(m.block_valid(a));
    CHECK(m.block_valid(b));
    CHECK(m.state(p[7]) == State::Shared);
  };
  m.begin_transaction();
  m.merge_patches(a, b);
  m.rollback_transaction();
  same();
  m.begin_transaction();
  m.remove_from_patch(p[5]);  // splits nothing, but drops a quad
  m.remove_from_patch(p[1]);
  m.rollback_transaction();
  same();
  m.begin_transaction();
  m.delete_patch(a);
  CHECK(counts(m) == Counts{32, 12, 1, 9});
  m.rollback_transaction();
  same();
  // A split rolled back: strip of five quads cut in the middle.
  Model s;
  auto q = grid_particles(s, 2, 6);
  s.add_quad_grid(q, 2, 6, kSection);
  const Counts strip = counts(s);
  s.begin_transaction();
  s.remove_from_patch(q[2]);
  CHECK(s.block_count() == 2);
  s.rollback_transaction();
  CHECK(s.check() == "");
  CHECK(counts(s) == strip);
  CHECK(s.particles_of(0).size() == 12);
}

TEST_CASE("merge_patches sews a patch wound the other way and keeps a's rest length on the seam") {
  Model m;
  auto p = grid_particles(m, 2, 3);  // p0 p1 p2 / p3 p4 p5
  BlockId a = m.add_patch({{p[0], p[1], p[4], p[3]}}, kSection);
  m.particles.position[p[2]] = Vec3(2, 0, 0.5);
  m.particles.position[p[1]] = Vec3(1, 0, 0.1);  // b's rest lengths differ on the seam
  BlockId b = m.add_patch({{p[1], p[4], p[5], p[2]}}, kSection);  // reversed winding
  m.particles.position[p[1]] = Vec3(1, 0, 0);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{16, 8, 2, 6});
  m.merge_patches(a, b);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{16, 7, 1, 6});
  for (std::size_t e = 0; e < m.bars.size(); ++e)
    if ((m.bars[e].i == p[1] && m.bars[e].j == p[4]) || (m.bars[e].i == p[4] && m.bars[e].j == p[1]))
      CHECK(m.bars[e].rest_length == doctest::Approx(1.0));
  m.remove_from_patch(p[0]);
  CHECK(m.check() == "");
  CHECK(counts(m) == Counts{8, 4, 1, 4});
}
