// Rule 20 (meshing/paving.hpp): all-quad meshes whose boundary is exactly the
// given loop, measured with the quality metrics on squares, a rectangle,
// circles, L-shapes (planar) and a saddle (non-planar); the table is printed.
// Refusals of short, odd, self-intersecting loops leave the model unchanged.
#include <doctest/doctest.h>

#include <cstdio>
#include <numbers>

#include "edge_table.hpp"
#include "helpers.hpp"
#include "patch_mesh.hpp"
#include "paving.hpp"
#include "paving_shapes.hpp"
#include "quality.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {

// The boundary of the paved mesh is exactly the loop, in order, unmoved.
void check_boundary_is_loop(const QuadMesh& mesh, const std::vector<Vec3>& loop) {
  const EdgeTable t = edge_table(to_polygons(mesh).faces, mesh.positions.size(), "test");
  std::size_t boundary_edges = 0, along_loop = 0;
  for (Index e = 0; e < t.ends.size(); ++e) {
    if (!t.boundary(e)) continue;
    ++boundary_edges;
    const Index a = std::min(t.ends[e][0], t.ends[e][1]), b = std::max(t.ends[e][0], t.ends[e][1]);
    along_loop += b < loop.size() && (b == a + 1 || (a == 0 && b == loop.size() - 1));
  }
  CHECK(boundary_edges == loop.size());
  CHECK(along_loop == loop.size());
  std::size_t unmoved = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) unmoved += mesh.positions[i] == loop[i];
  CHECK(unmoved == loop.size());
}

Quality measure(const char* name, const std::vector<Vec3>& loop) {
  const QuadMesh mesh = paving(loop);
  check_boundary_is_loop(mesh, loop);
  const Quality q = quality(mesh);
  std::printf("paving %-18s boundary %3zu  quads %4zu  J min %.3f mean %.3f  angles %5.1f..%5.1f  irregular %3zu/%3zu = %.3f\n",
              name, loop.size(), q.quads, q.jacobian_min, q.jacobian_mean, q.angle_min, q.angle_max,
              q.irregular_vertices, q.interior_vertices, q.irregular_fraction);
  return q;
}

void check_perfect_grid(const Quality& q, std::size_t quads, std::size_t interior) {
  CHECK(q.quads == quads);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(1e-9));
  CHECK(q.angle_min == doctest::Approx(90).epsilon(1e-9));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(1e-9));
  CHECK(q.interior_vertices == interior);
  CHECK(q.irregular_vertices == 0);
}

}  // namespace

TEST_CASE("paving: squares, a rectangle and L-shapes with unit spacing become the unit grid") {
  check_perfect_grid(measure("square 8", square_loop(8)), 64, 49);
  check_perfect_grid(measure("square 16", square_loop(16)), 256, 225);
  // Width 4: the last rows from opposite sides meet and are zipped by seams.
  check_perfect_grid(measure("rectangle 10 x 4", polygon_loop({Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(10, 4, 0), Vec3(0, 4, 0)})),
                     40, 27);
  // Width 3 leaves a one-element strip with a bend: a strip closure.
  check_perfect_grid(measure("L 6/3", l_loop(6, 3)), 27, 16);
  check_perfect_grid(measure("L 12/6", l_loop(12, 6)), 108, 85);
}

TEST_CASE("paving: circles reach a minimum scaled Jacobian of 0.7") {
  // 32 and 64 points at spacing ~1: areas 81.5 and 326 (quads of ~1).
  const Quality c32 = measure("circle 32", circle_loop(32, 16 / std::numbers::pi));
  CHECK(c32.jacobian_min >= 0.70);
  CHECK(c32.jacobian_mean >= 0.90);
  CHECK(c32.angle_min >= 45);
  CHECK(c32.angle_max <= 136);
  CHECK(c32.quads >= 75);
  CHECK(c32.quads <= 95);
  CHECK(c32.irregular_fraction <= 0.2);
  const Quality c64 = measure("circle 64", circle_loop(64, 32 / std::numbers::pi));
  CHECK(c64.jacobian_min >= 0.70);
  CHECK(c64.jacobian_mean >= 0.94);
  CHECK(c64.quads >= 300);
  CHECK(c64.quads <= 350);
  CHECK(c64.irregular_fraction <= 0.06);
}

TEST_CASE("paving: stars, whose small concave middle fronts need thin rows or a second strategy") {
  // Five tips: the plain strategy cannot advance the star-shaped middle
  // front; the second run's thin rows get it through.
  const auto five = star_loop(5, 10, 5);
  REQUIRE(five.size() == 70);
  CHECK(measure("star 5, 10/5 m", five).jacobian_min >= 0.7);
  CHECK(measure("star 5, 10/6 m", star_loop(5, 10, 6)).jacobian_min >= 0.7);
  CHECK(measure("star 6, 10/6 m", star_loop(6, 10, 6)).jacobian_min >= 0.7);
}

TEST_CASE("paving: a saddle loop gets a harmonic interior between its heights") {
  const double wave = 1.5;
  const auto loop = circle_loop(32, 16 / std::numbers::pi, wave);
  const Quality q = measure("saddle 32", loop);
  CHECK(q.jacobian_min >= 0.65);
  const QuadMesh mesh = paving(loop);
  double lowest = 0, highest = 0;
  for (std::size_t v = loop.size(); v < mesh.positions.size(); ++v) {
    lowest = std::min(lowest, mesh.positions[v].z());
    highest = std::max(highest, mesh.positions[v].z());
  }
  // Maximum principle: inside the range of the loop, and really curved.
  CHECK(lowest > -wave);
  CHECK(highest < wave);
  CHECK(highest - lowest > 0.5);
}

TEST_CASE("paving on the model: a ring beam becomes the boundary of a patch") {
  Model m;
  std::vector<ParticleId> ring;
  for (const Vec3& x : circle_loop(24, 4)) ring.push_back(m.add_particle(x));
  m.add_beam(ring, beam_section(), true);
  const Fingerprint before(m);
  const CommittedPatch r = patch_by_paving(m, ring, patch_section());
  CHECK(m.check() == "");
  for (std::size_t i = 0; i < ring.size(); ++i) {
    CHECK(r.particles[i] == ring[i]);
    CHECK(m.particles.position[ring[i]] == before.position[ring[i]]);
    CHECK(m.state(ring[i]) == State::Shared);
  }
  for (ParticleId p : r.created) CHECK(m.state(p) == State::Simple);
  const PatchMesh pm = patch_mesh(m, r.patch);
  // A disc: V - E + F = 1, with E = (4F + boundary) / 2.
  const std::size_t v = pm.particles.size(), f = pm.mesh.quads.size();
  CHECK(v + f - (4 * f + ring.size()) / 2 == 1);
  CHECK(v == ring.size() + r.created.size());
  const Quality q = quality(m, r.patch);
  CHECK(q.jacobian_min >= 0.7);
}

TEST_CASE("paving refuses short, odd, repeated, flat and self-intersecting loops, leaving the model unchanged") {
  Model m;
  std::vector<ParticleId> square;
  for (const Vec3& x : square_loop(2)) square.push_back(m.add_particle(x));  // 8 points
  std::vector<ParticleId> line;
  for (int i = 0; i < 8; ++i) line.push_back(m.add_particle(Vec3(i, 5, 0)));
  // An edge doubling back across the first one.
  std::vector<ParticleId> crossed;
  for (const Vec3& x : {Vec3(0, 0, 1), Vec3(3, 0, 1), Vec3(3, 3, 1), Vec3(1, 3, 1), Vec3(1, -1, 1), Vec3(0.5, -1, 1),
                        Vec3(0.5, 2, 1), Vec3(0, 2, 1)})
    crossed.push_back(m.add_particle(x));
  std::vector<ParticleId> nine = square;
  nine.push_back(m.add_particle(Vec3(-1, 1, 0)));
  m.add_beam(square, beam_section(), true);
  m.delete_particle(m.add_particle(Vec3(7, 7, 7)));
  const Fingerprint before(m);
  auto refused = [&](const std::vector<ParticleId>& loop, const char* message, Section s = patch_section()) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(patch_by_paving(m, loop, s), doctest::Contains(message), ModelError);
    CHECK(Fingerprint(m) == before);
  };
  refused({square.begin(), square.begin() + 6}, "needs at least 8 particles, got 6");
  refused(nine, "needs an even number of particles");
  std::vector<ParticleId> twice = square;
  twice[3] = twice[0];
  refused(twice, "appears twice");
  refused(line, "encloses no area");
  refused(crossed, "intersects itself");
  std::vector<ParticleId> dead = square;
  dead[2] = 12345;
  refused(dead, "12345");
  refused(square, "EA must be > 0", Section{0, 0, 0, 0});
}

TEST_CASE("simple_polygon: exact tests for crossings, touching corners and folds") {
  const std::vector<Vec2> square{Vec2(0, 0), Vec2(1, 0), Vec2(1, 1), Vec2(0, 1)};
  CHECK(simple_polygon(square));
  CHECK_FALSE(simple_polygon({Vec2(0, 0), Vec2(1, 1), Vec2(1, 0), Vec2(0, 1)}));  // bow tie
  // A corner touching a non-adjacent edge.
  CHECK_FALSE(simple_polygon({Vec2(0, 0), Vec2(2, 0), Vec2(2, 2), Vec2(1, 0), Vec2(0, 2)}));
  // Folding back along an edge.
  CHECK_FALSE(simple_polygon({Vec2(0, 0), Vec2(2, 0), Vec2(1, 0), Vec2(1, 1)}));
  // Nearly collinear but not touching: exact predicates keep it simple.
  CHECK(simple_polygon({Vec2(0, 0), Vec2(1, 1e-17), Vec2(2, 0), Vec2(2, 1), Vec2(0, 1)}));
  CHECK_THROWS_WITH_AS(pave_2d({Vec2(0, 0), Vec2(0, 1), Vec2(1, 1), Vec2(1, 0)}), doctest::Contains("counter-clockwise"),
                       ModelError);
}
