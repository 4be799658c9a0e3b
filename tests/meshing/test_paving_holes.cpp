// Rule 20 with holes (meshing/paving.hpp): an outer loop and inner loops
// paved by fronts that advance and join. All quads, the boundary exactly the
// given loops (unmoved), the topology of a disc with holes, a minimum scaled
// Jacobian of 0.5 on the benchmark's ring and on a square with a square hole;
// bad loops are refused with the model unchanged.
#include <doctest/doctest.h>

#include <cstdio>
#include <numbers>
#include <set>
#include <utility>

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

std::vector<Vec3> shifted(std::vector<Vec3> loop, const Vec3& by) {
  for (Vec3& x : loop) x += by;
  return loop;
}

// The boundary edges of the mesh are exactly the loops' edges (vertices
// numbered through the loops), the loops' points unmoved; V - E + F is
// 1 - holes.
Quality measure(const char* name, const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes) {
  const QuadMesh mesh = paving(outer, holes);
  std::vector<std::vector<Vec3>> loops{outer};
  loops.insert(loops.end(), holes.begin(), holes.end());
  std::set<std::pair<Index, Index>> expected;
  Index first = 0;
  for (const auto& loop : loops) {
    for (Index i = 0; i < loop.size(); ++i) {
      const Index a = first + i, b = first + (i + 1) % Index(loop.size());
      expected.insert({std::min(a, b), std::max(a, b)});
      CHECK(mesh.positions[a] == loop[i]);
    }
    first += Index(loop.size());
  }
  const EdgeTable t = edge_table(to_polygons(mesh).faces, mesh.positions.size(), "test");
  std::set<std::pair<Index, Index>> boundary;
  for (Index e = 0; e < t.ends.size(); ++e)
    if (t.boundary(e)) boundary.insert({std::min(t.ends[e][0], t.ends[e][1]), std::max(t.ends[e][0], t.ends[e][1])});
  CHECK(boundary == expected);
  const long euler = long(mesh.positions.size()) - long(t.ends.size()) + long(mesh.quads.size());
  CHECK(euler == 1 - long(holes.size()));
  const Quality q = quality(mesh);
  std::printf("paving %-24s boundary %3u  quads %4zu  J min %.3f mean %.3f  angles %5.1f..%5.1f  irregular %.3f\n", name,
              first, q.quads, q.jacobian_min, q.jacobian_mean, q.angle_min, q.angle_max, q.irregular_fraction);
  return q;
}

}  // namespace

TEST_CASE("paving with holes: the benchmark's ring and a square with a square hole reach J min 0.5") {
  // bench_meshing's ring: radii 10.2 and 5.1 m, unit spacing on both loops.
  const auto outer = circle_loop(64, 32 / std::numbers::pi), inner = circle_loop(32, 16 / std::numbers::pi);
  CHECK(measure("ring 10.2/5.1", outer, {inner}).jacobian_min >= 0.5);
  // The hole's orientation does not matter.
  CHECK(measure("ring, hole reversed", outer, {{inner.rbegin(), inner.rend()}}).jacobian_min >= 0.5);
  const auto square = square_loop(20), hole = shifted(square_loop(8), Vec3(6, 6, 0));
  CHECK(measure("square 20, hole 8", square, {hole}).jacobian_min >= 0.5);
  CHECK(measure("square 20, hole 6 off centre", square, {shifted(square_loop(6), Vec3(4, 9, 0))}).jacobian_min >= 0.4);
  CHECK(measure("square 20, two holes", square,
                {shifted(square_loop(4), Vec3(4, 4, 0)), shifted(square_loop(4), Vec3(12, 11, 0))})
            .jacobian_min >= 0.4);
}

TEST_CASE("paving with holes on the model: two ring beams bound one patch") {
  Model m;
  std::vector<ParticleId> outer, inner;
  for (const Vec3& x : circle_loop(32, 16 / std::numbers::pi)) outer.push_back(m.add_particle(x));
  for (const Vec3& x : circle_loop(16, 8 / std::numbers::pi)) inner.push_back(m.add_particle(x));
  m.add_beam(outer, beam_section(), true);
  m.add_beam(inner, beam_section(), true);
  const Fingerprint before(m);
  const CommittedPatch r = patch_by_paving(m, outer, {inner}, patch_section());
  CHECK(m.check() == "");
  std::vector<ParticleId> loops = outer;
  loops.insert(loops.end(), inner.begin(), inner.end());
  for (std::size_t i = 0; i < loops.size(); ++i) {
    CHECK(r.particles[i] == loops[i]);
    CHECK(m.particles.position[loops[i]] == before.position[loops[i]]);
    CHECK(m.state(loops[i]) == State::Shared);
  }
  for (ParticleId p : r.created) CHECK(m.state(p) == State::Simple);
  const PatchMesh pm = patch_mesh(m, r.patch);
  // An annulus: V - E + F = 0, with E = (4F + boundary) / 2.
  const std::size_t v = pm.particles.size(), f = pm.mesh.quads.size();
  CHECK(long(v + f) - long((4 * f + loops.size()) / 2) == 0);
  CHECK(quality(m, r.patch).jacobian_min >= 0.5);
}

TEST_CASE("paving with holes refuses crossing, touching, outside, nested and odd loops, leaving the model unchanged") {
  Model m;
  auto particles = [&](const std::vector<Vec3>& xs) {
    std::vector<ParticleId> out;
    for (const Vec3& x : xs) out.push_back(m.add_particle(x));
    return out;
  };
  const auto outer = particles(square_loop(10));
  const auto crossing = particles(shifted(square_loop(4), Vec3(8.5, 3.5, 0)));
  const auto touching = particles({Vec3(0, 4.5, 0), Vec3(2, 3.5, 0), Vec3(3, 4.5, 0), Vec3(2, 5.5, 0)});  // a corner on the outer loop
  const auto outside = particles(shifted(square_loop(2), Vec3(20, 0, 0)));
  const auto big = particles(shifted(square_loop(6), Vec3(2, 2, 0)));
  const auto small = particles(shifted(square_loop(2), Vec3(4, 4, 0)));
  const auto bow = particles({Vec3(3, 3, 0), Vec3(5, 5, 0), Vec3(5, 3, 0), Vec3(3, 5, 0)});
  const auto triangle = particles({Vec3(6, 6, 0), Vec3(7, 6, 0), Vec3(7, 7, 0)});
  m.add_beam(outer, beam_section(), true);
  const Fingerprint before(m);
  auto refused = [&](const std::vector<std::vector<ParticleId>>& holes, const char* message) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(patch_by_paving(m, outer, holes, patch_section()), doctest::Contains(message), ModelError);
    CHECK(Fingerprint(m) == before);
  };
  refused({crossing}, "hole 1 touches or crosses the outer loop");
  refused({touching}, "hole 1 touches or crosses the outer loop");
  refused({outside}, "hole 1 is not inside the outer loop");
  refused({big, small}, "hole 2 and hole 1 are nested");
  refused({bow}, "hole 1 intersects itself");
  refused({triangle}, "needs an even number of particles");
  refused({{outer[0], outer[1], outer[2]}}, "appears twice in the loops");
  refused({{small[0], small[1]}}, "hole 1 needs at least 3 points");
}
