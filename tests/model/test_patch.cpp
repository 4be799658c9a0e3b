// add_patch: quads of existing particles sewn by alpha2 into one patch.
#include <doctest/doctest.h>

#include "model/model.hpp"

using namespace tendril;

namespace {
std::vector<ParticleId> grid_particles(Model& m, int rows, int cols) {
  std::vector<ParticleId> ps;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) ps.push_back(m.add_particle(Vec3(c, r, 0)));
  return ps;
}
}  // namespace

TEST_CASE("add_patch sews an L of three quads given with mixed orientations") {
  Model m;
  auto p = grid_particles(m, 3, 3);  // p[r*3+c]
  // Quads (0,0), (0,1) and (1,0); the last one is wound the other way.
  std::vector<Model::Quad> quads{{p[0], p[1], p[4], p[3]}, {p[1], p[2], p[5], p[4]}, {p[3], p[6], p[7], p[4]}};
  BlockId b = m.add_patch(quads, Section{1e3, 0, 0, 0});
  CHECK(m.check() == "");
  CHECK(m.map.dart_count() == 24);
  CHECK(m.bars.size() == 10);  // 12 quad sides, 2 shared
  std::size_t sewn = 0;
  for (Dart d = 0; d < m.map.capacity(); ++d) sewn += m.map.alive(d) && !m.map.is_free(2, d);
  CHECK(sewn == 8);
  CHECK(m.map.orbit_size(kVertexOrbit, m.particles.first_dart[p[4]]) == 6);  // three quads meet at p4
  CHECK(m.particles_of(b).size() == 8);
  CHECK(m.state(p[4]) == State::Simple);
  CHECK(m.state(p[8]) == State::Isolated);
}

TEST_CASE("add_patch refuses non-manifold edges, separate pieces and bad quads, leaving the model unchanged") {
  Model m;
  auto p = grid_particles(m, 3, 3);
  ParticleId extra = m.add_particle(Vec3(0.5, 0.5, 1));
  const Section s{1e3, 0, 0, 0};
  CHECK_THROWS_WITH_AS(m.add_patch({{p[0], p[1], p[4], p[3]}, {p[1], p[0], p[3], extra}, {p[0], p[1], extra, p[4]}}, s),
                       doctest::Contains("more than two quads"), ModelError);
  CHECK_THROWS_WITH_AS(m.add_patch({{p[0], p[1], p[4], p[3]}, {p[4], p[5], p[8], p[7]}}, s),
                       doctest::Contains("separate pieces"), ModelError);
  CHECK_THROWS_WITH_AS(m.add_patch({{p[0], p[1], p[1], p[3]}}, s), doctest::Contains("repeats particle"), ModelError);
  CHECK_THROWS_AS(m.add_patch({}, s), ModelError);
  CHECK(m.map.dart_count() == 0);
  CHECK(m.block_count() == 0);
  CHECK(m.check() == "");
}
