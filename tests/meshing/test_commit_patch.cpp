// commit_patch (meshing/commit_patch.hpp): the all-or-nothing step every
// meshing rule ends with. Plans that add_patch would refuse are refused
// before anything changes; an accepted plan moves, creates and sews exactly
// what it says.
#include <doctest/doctest.h>

#include "commit_patch.hpp"
#include "helpers.hpp"
#include "patch_mesh.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

TEST_CASE("commit_patch moves existing particles, adds new ones and sews one patch") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  PlannedPatch plan;
  plan.existing = {a, b};
  plan.mesh.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0.5), Vec3(2, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0), Vec3(2, 1, 0)};
  plan.mesh.quads = {{0, 1, 4, 3}, {1, 2, 5, 4}};
  const CommittedPatch r = commit_patch(m, plan, patch_section(), "test");
  CHECK(m.check() == "");
  CHECK(r.created.size() == 4);
  CHECK(r.particles.size() == 6);
  CHECK(r.particles[0] == a);
  CHECK(r.particles[1] == b);
  CHECK(m.particles.position[b] == Vec3(1, 0, 0.5));  // moved to its planned place
  CHECK(m.bars.size() == 7);
  CHECK(patch_mesh(m, r.patch).mesh.quads.size() == 2);
}

TEST_CASE("commit_patch refuses plans add_patch would refuse, before changing anything") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1e3, 0, 0, 0});
  m.delete_particle(m.add_particle(Vec3(3, 3, 3)));
  const Fingerprint before(m);
  auto refused = [&](const PlannedPatch& plan, const char* message, Section s = patch_section()) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(commit_patch(m, plan, s, "test"), doctest::Contains(message), ModelError);
    CHECK(Fingerprint(m) == before);
  };
  const QuadMesh grid = unit_grid(1, 2);  // 6 vertices, 2 quads
  refused({QuadMesh{grid.positions, {}}, {a}}, "no quads");
  refused({grid, {a, a}}, "used twice");
  refused({grid, {a, 77}}, "77");
  QuadMesh apart = grid;
  apart.positions.insert(apart.positions.end(), {Vec3(5, 0, 0), Vec3(6, 0, 0), Vec3(6, 1, 0), Vec3(5, 1, 0)});
  apart.quads.push_back({6, 7, 8, 9});
  refused({apart, {a}}, "2 separate pieces");
  QuadMesh spare = grid;
  spare.positions.push_back(Vec3(9, 9, 9));
  refused({spare, {a}}, "new vertex 6 is in no quad");
  QuadMesh flat = grid;
  flat.positions[4] = flat.positions[1];
  refused({flat, {a}}, "zero length");
  QuadMesh infinite = grid;
  infinite.positions[5].x() = INFINITY;
  refused({infinite, {a}}, "not finite");
  QuadMesh fan = grid;
  fan.positions.push_back(Vec3(1, -1, 0));
  fan.positions.push_back(Vec3(0, -1, 0));
  fan.quads.push_back({0, 1, 6, 7});
  fan.quads.push_back({1, 0, 7, 6});  // the edge 0-1 in three quads
  refused({fan, {a}}, "more than two faces");
  refused({grid, {a}}, "line_mass", Section{1, 0, 0, -1});
}
