// CST triangulation by edge classification (meshing/edge_classification.hpp,
// thesis fig. 5.30): on grids every horizontal edge is one class and every
// diagonal points the same way; around odd-valence vertices (a paved circle,
// an odd Catmull-Clark patch) the propagation conflicts and is refused, or
// accepted with seams; the triangles give the quads and bars back exactly.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <numbers>
#include <set>

#include "catmull_clark_rules.hpp"
#include "edge_classification.hpp"
#include "helpers.hpp"
#include "patch_mesh.hpp"
#include "paving.hpp"
#include "paving_shapes.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {

using Edge = std::pair<Index, Index>;
Edge undirected(Index a, Index b) { return {std::min(a, b), std::max(a, b)}; }

std::set<Edge> edges_of(const std::vector<QuadIndices>& quads) {
  std::set<Edge> out;
  for (const QuadIndices& q : quads)
    for (int k = 0; k < 4; ++k) out.insert(undirected(q[k], q[(k + 1) % 4]));
  return out;
}

// The same quad: equal as cyclic sequences, either way round.
bool same_quad(const QuadIndices& a, const QuadIndices& b) {
  for (int start = 0; start < 4; ++start)
    for (int dir : {1, 3}) {
      bool equal = true;
      for (int k = 0; k < 4; ++k) equal = equal && a[k] == b[(start + k * dir) % 4];
      if (equal) return true;
    }
  return false;
}

// Every check that holds whatever the mesh: two triangles per quad made of its
// corners, sides 1 and 2 on quad edges of the classes the frame says, and the
// reverse shift giving back the quads and bars.
void check_triangulation(const QuadMesh& mesh, const EdgeClasses& c) {
  const std::vector<Triangle> tris = cst_triangles(c);
  REQUIRE(tris.size() == 2 * mesh.quads.size());
  std::map<Edge, Index> edge_id;
  for (Index e = 0; e < c.edges.ends.size(); ++e) edge_id[undirected(c.edges.ends[e][0], c.edges.ends[e][1])] = e;
  const std::set<Index> seams(c.seams.begin(), c.seams.end());
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const Triangle &a = tris[2 * q], &b = tris[2 * q + 1];
    for (const Triangle& t : {a, b}) {
      const Index warp = edge_id.at(undirected(t[0], t[1])), weft = edge_id.at(undirected(t[1], t[2]));
      CHECK(edge_id.count(undirected(t[2], t[0])) == 0);  // the diagonal is no quad edge
      // Off the seams the edge classes agree with the triangle's own frame.
      if (!seams.count(warp)) CHECK(c.yarn[warp] == Yarn::Warp);
      if (!seams.count(weft)) CHECK(c.yarn[weft] == Yarn::Weft);
    }
  }
  const std::vector<QuadIndices> back = quads_from_triangles(tris);
  REQUIRE(back.size() == mesh.quads.size());
  for (std::size_t q = 0; q < back.size(); ++q) CHECK(same_quad(back[q], mesh.quads[q]));
  std::set<Edge> bars;
  for (const auto& e : bars_from_triangles(tris)) bars.insert(undirected(e[0], e[1]));
  CHECK(bars == edges_of(mesh.quads));
  CHECK(bars_from_triangles(tris).size() == c.edges.ends.size());
}

}  // namespace

TEST_CASE("edge classification: on a grid, horizontal edges are warp, vertical weft, diagonals parallel") {
  QuadMesh grid = unit_grid(4, 6);
  // A G-map has no orientation: wind every other quad the other way.
  for (std::size_t q = 0; q < grid.quads.size(); q += 2) std::reverse(grid.quads[q].begin(), grid.quads[q].end());
  const EdgeClasses c = classify_edges(grid);
  CHECK(c.seams.empty());
  CHECK(c.flips.empty());
  std::size_t warp = 0;
  for (Index e = 0; e < c.edges.ends.size(); ++e) {
    const Vec3 d = grid.positions[c.edges.ends[e][1]] - grid.positions[c.edges.ends[e][0]];
    const bool horizontal = d.y() == 0;
    CHECK((c.yarn[e] == Yarn::Warp) == horizontal);
    warp += c.yarn[e] == Yarn::Warp;
  }
  CHECK(warp == 5 * 6);  // 5 rows of 6 horizontal edges
  CHECK(c.edges.ends.size() - warp == 4 * 7);
  // Every quad's diagonal runs from its (0,0) to its (1,1) corner: the same
  // grid direction everywhere, whichever way the quad was wound.
  const std::vector<Triangle> tris = cst_triangles(c);
  const Vec3 first = grid.positions[tris[0][2]] - grid.positions[tris[0][0]];
  CHECK(std::abs(first.x()) == 1);
  CHECK(std::abs(first.y()) == 1);
  for (std::size_t q = 0; q < grid.quads.size(); ++q) {
    CHECK(grid.positions[tris[2 * q][2]] - grid.positions[tris[2 * q][0]] == first);
    CHECK(tris[2 * q + 1][0] == tris[2 * q][2]);
  }
  check_triangulation(grid, c);
}

TEST_CASE("edge classification: a warp direction picks the class and the sense of u") {
  const QuadMesh grid = unit_grid(3, 3);
  ClassifyOptions o;
  o.warp = Vec3(0, -1, 0);
  const EdgeClasses c = classify_edges(grid, o);
  for (Index e = 0; e < c.edges.ends.size(); ++e) {
    const Vec3 d = grid.positions[c.edges.ends[e][1]] - grid.positions[c.edges.ends[e][0]];
    CHECK((c.yarn[e] == Yarn::Warp) == (d.x() == 0));
  }
  for (const QuadIndices& f : c.frame) CHECK(grid.positions[f[1]].y() < grid.positions[f[0]].y());  // u points down
  check_triangulation(grid, c);
}

TEST_CASE("edge classification: a paved circle conflicts around odd valences; seams make it usable") {
  const QuadMesh circle = paving(circle_loop(32, 16 / std::numbers::pi));
  try {
    classify_edges(circle);
    FAIL("a paved circle with valence 3 and 5 vertices cannot be classified consistently");
  } catch (const ModelError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("edge classification: warp and weft cannot be assigned consistently") == 0);
    CHECK(what.find("interior vertex of valence ") != std::string::npos);
    CHECK((what.find("valence 3") != std::string::npos || what.find("valence 5") != std::string::npos));
  }
  ClassifyOptions o;
  o.allow_seams = true;
  const EdgeClasses c = classify_edges(circle, o);
  CHECK(!c.seams.empty());
  CHECK(c.seams.size() < c.edges.ends.size() / 4);  // a few seams, not a random labelling
  for (Index e : c.seams) CHECK(!c.edges.boundary(e));
  std::printf("paved circle: %zu quads, %zu edges, %zu seams, %zu flips\n", circle.quads.size(), c.edges.ends.size(),
              c.seams.size(), c.flips.size());
  check_triangulation(circle, c);
}

TEST_CASE("edge classification: Catmull-Clark patches by the valence of their centre") {
  Model m;
  for (int n : {4, 5, 6}) {
    CAPTURE(n);
    std::vector<Vec3> loop;
    for (int i = 0; i < n; ++i)
      loop.push_back(Vec3(std::cos(2 * std::numbers::pi * i / n), std::sin(2 * std::numbers::pi * i / n), 0));
    const QuadMesh mesh = loop_catmull_clark(loop, 2);
    if (n % 2) {
      CHECK_THROWS_WITH_AS(classify_edges(mesh), doctest::Contains("an interior vertex of valence 5"), ModelError);
      continue;
    }
    const EdgeClasses c = classify_edges(mesh);
    CHECK(c.seams.empty());
    // Valence 4 is a grid; around valence 6 the frames come back turned by 180
    // degrees: classes agree, diagonals change direction across flips.
    CHECK(c.flips.empty() == (n == 4));
    check_triangulation(mesh, c);
  }
}

TEST_CASE("edge classification on a patch of the model, in particle ids") {
  Model m;
  std::vector<ParticleId> loop;
  for (const Vec3& x : square_loop(4)) loop.push_back(m.add_particle(x));
  const CommittedPatch r = patch_by_paving(m, loop, patch_section());
  const Fingerprint before(m);
  const PatchTriangulation t = cst_triangulation(m, r.patch);
  CHECK(Fingerprint(m) == before);  // changes nothing
  CHECK(t.triangles.size() == 32);
  CHECK(t.seams.empty());
  CHECK(t.flips.empty());
  CHECK(t.warp_edges == 20);
  CHECK(t.weft_edges == 20);
  std::set<ParticleId> on_patch;
  for (ParticleId p : m.particles_of(r.patch)) on_patch.insert(p);
  for (const auto& tri : t.triangles)
    for (ParticleId p : tri) CHECK(on_patch.count(p) == 1);
  // Warp sides are all parallel to one axis of the square.
  const Vec3 first = m.particles.position[t.triangles[0][1]] - m.particles.position[t.triangles[0][0]];
  for (const auto& tri : t.triangles) {
    const Vec3 side = m.particles.position[tri[1]] - m.particles.position[tri[0]];
    CHECK(std::abs(side.normalized().dot(first.normalized())) == doctest::Approx(1));
  }
  CHECK_THROWS_WITH_AS(cst_triangulation(m, BlockId(7)), doctest::Contains("triangulation"), ModelError);
}

TEST_CASE("edge classification: the reverse shift refuses what cst_triangles cannot have made") {
  CHECK_THROWS_WITH_AS(quads_from_triangles({{0, 1, 2}}), doctest::Contains("odd number of triangles"), ModelError);
  CHECK_THROWS_WITH_AS(quads_from_triangles({{0, 1, 2}, {3, 4, 5}}), doctest::Contains("do not share their diagonal"),
                       ModelError);
  CHECK_THROWS_WITH_AS(classify_edges(QuadMesh{}), doctest::Contains("no quads"), ModelError);
}
