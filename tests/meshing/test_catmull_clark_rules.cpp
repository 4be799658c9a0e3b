// Rules 19 and 25 on the model (meshing/catmull_clark_rules.hpp): counts,
// boundary particles unmoved, new boundary points on the chords, map valid,
// states, quality in closed form, and refusals that leave the model as it was.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "catmull_clark.hpp"
#include "catmull_clark_rules.hpp"
#include "helpers.hpp"
#include "patch_mesh.hpp"
#include "quality.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {

std::vector<ParticleId> circle(Model& m, int n, double radius = 1, double wave = 0) {
  std::vector<ParticleId> ps;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    ps.push_back(m.add_particle(Vec3(radius * std::cos(a), radius * std::sin(a), wave * std::cos(2 * a))));
  }
  return ps;
}

std::size_t pow_int(std::size_t b, int e) {
  std::size_t r = 1;
  while (e-- > 0) r *= b;
  return r;
}

}  // namespace

TEST_CASE("rule 19: n particles and k levels give n 4^k quads, the loop unmoved, a valid map") {
  for (int n : {3, 4, 5, 7, 8}) {
    for (int levels : {0, 1, 2}) {
      CAPTURE(n);
      CAPTURE(levels);
      Model m;
      const auto loop = circle(m, n, 1.5, 0.3);  // a saddle-like, non-planar loop
      m.add_beam(loop, beam_section(), true);
      const Fingerprint before(m);
      const CommittedPatch r = patch_from_loop(m, loop, levels, patch_section());
      CHECK(m.check() == "");
      const std::size_t quads = n * pow_int(4, levels);
      const std::size_t vertices = 1 + quads + n * pow_int(2, levels);
      CHECK(m.map.dart_count() == before.darts + 8 * quads);
      CHECK(r.particles.size() == vertices);
      CHECK(r.created.size() == vertices - n);
      CHECK(m.particle_count() == vertices);
      CHECK(m.particles_of(r.patch).size() == vertices);
      CHECK(m.blocks[r.patch].kind == BlockKind::Patch);
      const PatchMesh pm = patch_mesh(m, r.patch);
      CHECK(pm.mesh.quads.size() == quads);
      for (int i = 0; i < n; ++i) {
        CHECK(r.particles[i] == loop[i]);
        CHECK(m.particles.position[loop[i]] == before.position[loop[i]]);
        CHECK(m.state(loop[i]) == State::Shared);  // beam and patch
      }
      for (ParticleId p : r.created) CHECK(m.state(p) == State::Simple);
    }
  }
}

TEST_CASE("rule 19: new boundary particles lie on the chords between loop particles") {
  Model m;
  const auto loop = circle(m, 5, 2, 0.4);
  const CommittedPatch r = patch_from_loop(m, loop, 2, patch_section());
  // With 2 further levels every chord carries 3 new points at 1/4, 1/2, 3/4.
  const QuadMesh expect = loop_catmull_clark({m.particles.position[loop[0]], m.particles.position[loop[1]],
                                              m.particles.position[loop[2]], m.particles.position[loop[3]],
                                              m.particles.position[loop[4]]},
                                             2);
  std::size_t on_chord = 0;
  for (ParticleId p : r.created) {
    const Vec3& x = m.particles.position[p];
    for (int i = 0; i < 5; ++i) {
      const Vec3 a = m.particles.position[loop[i]], b = m.particles.position[loop[(i + 1) % 5]];
      for (double t : {0.25, 0.5, 0.75})
        if ((x - (a + t * (b - a))).norm() <= 1e-14) ++on_chord;
    }
  }
  CHECK(on_chord == 15);
  for (std::size_t i = 0; i < expect.positions.size(); ++i)
    CHECK(m.particles.position[r.particles[i]] == expect.positions[i]);
}

TEST_CASE("rule 19: a regular n-gon at level 0 has scaled Jacobian sin(2 pi / n)") {
  for (int n : {3, 4, 5, 6, 8, 12}) {
    CAPTURE(n);
    Model m;
    const CommittedPatch r = patch_from_loop(m, circle(m, n), 0, patch_section());
    // Each quad is corner, edge midpoint, centre, edge midpoint: angles
    // 180 - 360/n at the corner, 90 at the midpoints, 360/n at the centre.
    const Quality q = quality(m, r.patch);
    const double centre = 360.0 / n;
    CHECK(q.jacobian_min == doctest::Approx(std::sin(2 * std::numbers::pi / n)).epsilon(1e-12));
    CHECK(q.jacobian_mean == doctest::Approx(std::sin(2 * std::numbers::pi / n)).epsilon(1e-12));
    CHECK(q.angle_min == doctest::Approx(std::min({centre, 180 - centre, 90.0})).epsilon(1e-12));
    CHECK(q.angle_max == doctest::Approx(std::max({centre, 180 - centre, 90.0})).epsilon(1e-12));
    CHECK(q.interior_vertices == 1);
    CHECK(q.irregular_vertices == (n == 4 ? 0u : 1u));
  }
}

TEST_CASE("rule 19: a square loop subdivides into a uniform grid") {
  Model m;
  const std::vector<ParticleId> loop{m.add_particle(Vec3(0, 0, 0)), m.add_particle(Vec3(1, 0, 0)),
                                     m.add_particle(Vec3(1, 1, 0)), m.add_particle(Vec3(0, 1, 0))};
  const CommittedPatch r = patch_from_loop(m, loop, 2, patch_section());
  const Quality q = quality(m, r.patch);
  CHECK(q.quads == 64);  // an 8 x 8 grid
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(1e-12));
  CHECK(q.angle_min == doctest::Approx(90).epsilon(1e-12));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(1e-12));
  CHECK(q.interior_vertices == 49);
  CHECK(q.irregular_fraction == 0);
  for (ParticleId p : r.particles) {  // every particle on the 1/8 lattice
    const Vec3 x = m.particles.position[p] * 8;
    CHECK((x - x.array().round().matrix()).norm() <= 1e-12);
  }
  // Bars: 2 * 8 * 9 edges, rest lengths 1/8.
  CHECK(m.bars.size() == 144);
  for (std::size_t e = 0; e < m.bars.size(); ++e) CHECK(m.bars[e].rest_length == doctest::Approx(0.125).epsilon(1e-12));
}

TEST_CASE("rule 19 refuses bad loops and leaves the model unchanged") {
  Model m;
  const auto loop = circle(m, 6);
  m.add_beam(loop, beam_section(), true);
  const ParticleId twin = m.add_particle(m.particles.position[loop[2]]);
  const ParticleId a = m.add_particle(Vec3(0, 0, 5)), b = m.add_particle(Vec3(1, 0, 5)),
                   c = m.add_particle(Vec3(2, 0, 5));
  m.delete_particle(m.add_particle(Vec3(9, 9, 9)));  // a free slot to keep
  const Fingerprint before(m);
  auto refused = [&](const std::vector<ParticleId>& ps, int levels, const Section& s, const char* message) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(patch_from_loop(m, ps, levels, s), doctest::Contains(message), ModelError);
    CHECK(Fingerprint(m) == before);
  };
  refused({loop[0], loop[1]}, 0, patch_section(), "needs at least 3 particles, got 2");
  refused({loop[0], loop[1], loop[0]}, 0, patch_section(), "appears twice");
  refused({loop[0], loop[1], 999}, 0, patch_section(), "999");
  refused({loop[0], loop[1], loop[2], twin}, 0, patch_section(), "coincide");
  refused({a, b, c}, 0, patch_section(), "encloses no area");
  refused(loop, -1, patch_section(), "levels must be between 0 and 8, got -1");
  refused(loop, 9, patch_section(), "got 9");
  refused(loop, 1, Section{0, 0, 0, 0}, "EA must be > 0");
  refused(loop, 1, Section{1, 0, NAN, 0}, "prestress");
  // A figure eight in the plane: zero net area.
  const std::vector<ParticleId> eight{m.add_particle(Vec3(0, 0, 7)), m.add_particle(Vec3(1, 1, 7)),
                                      m.add_particle(Vec3(1, 0, 7)), m.add_particle(Vec3(0, 1, 7))};
  const Fingerprint with_eight(m);
  CHECK_THROWS_WITH_AS(patch_from_loop(m, eight, 0, patch_section()), doctest::Contains("encloses no area"), ModelError);
  CHECK(Fingerprint(m) == with_eight);
}

TEST_CASE("rule 25: subdividing a patch quadruples its quads and keeps its boundary") {
  Model m;
  std::vector<ParticleId> grid;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) grid.push_back(m.add_particle(Vec3(c, r, 0.1 * c * r)));
  // Displace the interior so smoothing has something to do.
  m.particles.position[grid[5]] += Vec3(0.2, -0.1, 0.3);
  m.particles.position[grid[10]] += Vec3(-0.15, 0.1, -0.2);
  const BlockId old = m.add_quad_grid(grid, 4, 4, patch_section());
  const PatchMesh before = patch_mesh(m, old);
  const QuadMesh expect = catmull_clark(before.mesh);
  const SubdividedPatch r = subdivide_patch(m, old);
  CHECK(m.check() == "");
  CHECK(r.replaced == old);
  CHECK(m.block_valid(old));  // deleting it is the caller's job until core has delete_patch
  CHECK(m.blocks[r.patch].section.prestress == patch_section().prestress);
  const PatchMesh after = patch_mesh(m, r.patch);
  CHECK(after.mesh.quads.size() == 36);
  CHECK(after.particles.size() == 16 + 9 + 24);  // vertices + faces + edges
  CHECK(r.created.size() == 33);
  CHECK(m.particle_count() == 49);
  // Old particles reused: the 12 on the boundary unmoved, the 4 inside moved
  // to their Catmull-Clark positions.
  std::size_t unmoved = 0;
  for (std::size_t i = 0; i < before.particles.size(); ++i) {
    CHECK(r.particles[i] == before.particles[i]);
    CHECK(m.particles.position[r.particles[i]] == expect.positions[i]);
    unmoved += m.particles.position[r.particles[i]] == before.mesh.positions[i];
  }
  CHECK(unmoved == 12);
  const Quality q = quality(m, r.patch);
  CHECK(q.interior_vertices == 25);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("rule 25 leaves locked and shared interior particles where they are") {
  Model m;
  std::vector<ParticleId> grid;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) grid.push_back(m.add_particle(Vec3(c, r, 0)));
  m.particles.position[grid[5]] += Vec3(0.2, -0.1, 0.3);
  m.particles.position[grid[6]] += Vec3(0.1, 0.1, 0.1);
  m.particles.position[grid[9]] += Vec3(0.0, 0.2, -0.2);
  const BlockId old = m.add_quad_grid(grid, 4, 4, patch_section());
  m.set_lock(grid[5], kLockTranslation);
  const ParticleId anchor = m.add_particle(Vec3(1, 2, -3));
  m.add_cable(grid[6], anchor, Section{1e4, 0, 0, 0});
  const Vec3 locked = m.particles.position[grid[5]], hung = m.particles.position[grid[6]];
  const Vec3 free = m.particles.position[grid[9]];
  subdivide_patch(m, old);
  CHECK(m.check() == "");
  CHECK(m.particles.position[grid[5]] == locked);
  CHECK(m.particles.position[grid[6]] == hung);
  CHECK(m.particles.position[grid[9]] != free);
}

TEST_CASE("rule 25 refuses what is not a patch and leaves the model unchanged") {
  Model m;
  const auto loop = circle(m, 4);
  const BlockId beam = m.add_beam(loop, beam_section(), true);
  const BlockId patch = patch_from_loop(m, loop, 0, patch_section()).patch;
  const Fingerprint before(m);
  CHECK_THROWS_WITH_AS(subdivide_patch(m, beam), doctest::Contains("is a beam, not a patch"), ModelError);
  CHECK_THROWS_AS(subdivide_patch(m, 77), ModelError);
  CHECK_THROWS_WITH_AS(subdivide_patch(m, patch, Section{-1, 0, 0, 0}), doctest::Contains("EA"), ModelError);
  CHECK(Fingerprint(m) == before);
}
