// One Catmull-Clark step (meshing/catmull_clark.hpp) against OpenMesh's
// uniform CatmullClarkT: every vertex of closed meshes (where no boundary rule
// applies) and every non-boundary vertex of an open, curved, irregular grid
// must agree to 1e-12. Plus our boundary rule (fixed vertices, midpoints),
// pinned vertices, counts and errors.
#include <doctest/doctest.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <cmath>

#include "catmull_clark.hpp"
#include "edge_table.hpp"
#include "helpers.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
  typedef OpenMesh::Vec3d Point;
  typedef OpenMesh::Vec3d Normal;
};
using OMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

OMesh to_openmesh(const PolygonMesh& m) {
  OMesh om;
  std::vector<OMesh::VertexHandle> vh;
  for (const Vec3& x : m.positions) vh.push_back(om.add_vertex(OMesh::Point(x.x(), x.y(), x.z())));
  for (const auto& f : m.faces) {
    std::vector<OMesh::VertexHandle> corners;
    for (Index v : f) corners.push_back(vh[v]);
    REQUIRE(om.add_face(corners).is_valid());
  }
  return om;
}

OMesh openmesh_catmull_clark(const PolygonMesh& m, int steps) {
  OMesh om = to_openmesh(m);
  OpenMesh::Subdivider::Uniform::CatmullClarkT<OMesh, double> cc;
  cc.attach(om);
  cc(steps);
  cc.detach();
  return om;
}

// Every vertex of `ours` that is not on its boundary has an OpenMesh vertex
// within 1e-12, which is not on OpenMesh's boundary either; returns how many
// were compared.
std::size_t compare_interior(const QuadMesh& ours, const OMesh& om) {
  const EdgeTable t = edge_table(to_polygons(ours).faces, ours.positions.size(), "test");
  const std::vector<bool> boundary = boundary_vertices(t, ours.positions.size());
  std::size_t compared = 0;
  double worst = 0;
  for (std::size_t v = 0; v < ours.positions.size(); ++v) {
    if (boundary[v]) continue;
    double best = INFINITY;
    OMesh::VertexHandle at;
    for (auto h : om.vertices()) {
      const auto& p = om.point(h);
      const double d = (Vec3(p[0], p[1], p[2]) - ours.positions[v]).norm();
      if (d < best) best = d, at = h;
    }
    CHECK_FALSE(om.is_boundary(at));
    worst = std::max(worst, best);
    ++compared;
  }
  CHECK(worst <= 1e-12);
  return compared;
}

PolygonMesh cube() {
  PolygonMesh m;
  for (int i = 0; i < 8; ++i) m.positions.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  m.positions[7] = Vec3(1.3, 1.1, 1.4);  // break the symmetry
  m.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return m;
}

// A 5 x 4 grid, curved and jittered, whose quads (1,2) and (1,3) are
// replaced by a triangle, a quad and a pentagon around an extra valence-3
// vertex: faces of three sizes and an extraordinary vertex in the interior.
PolygonMesh open_curved_grid() {
  PolygonMesh m;
  const int rows = 4, cols = 5;
  for (int r = 0; r <= rows; ++r)
    for (int c = 0; c <= cols; ++c) {
      const double x = c + 0.13 * std::sin(3.1 * r + c), y = r + 0.11 * std::cos(1.7 * c - r);
      m.positions.push_back(Vec3(x, y, 0.2 * x * x - 0.15 * x * y + 0.1 * y * y));
    }
  auto at = [&](int r, int c) { return Index(r * (cols + 1) + c); };
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      if (r == 1 && (c == 2 || c == 3)) continue;
      m.faces.push_back({at(r, c), at(r, c + 1), at(r + 1, c + 1), at(r + 1, c)});
    }
  m.positions.push_back(Vec3(2.9, 1.45, 0.9));
  const Index x = Index(m.positions.size() - 1);
  m.faces.push_back({at(1, 2), at(1, 3), x});
  m.faces.push_back({at(1, 3), at(1, 4), at(2, 4), at(2, 3), x});
  m.faces.push_back({at(1, 2), x, at(2, 3), at(2, 2)});
  return m;
}

}  // namespace

TEST_CASE("catmull_clark matches OpenMesh on a closed cube, one and two steps") {
  const PolygonMesh m = cube();
  const QuadMesh one = catmull_clark(m);
  CHECK(one.positions.size() == 26);  // 8 + 6 faces + 12 edges
  CHECK(one.quads.size() == 24);
  const OMesh om1 = openmesh_catmull_clark(m, 1);
  CHECK(om1.n_vertices() == 26);
  CHECK(om1.n_faces() == 24);
  CHECK(compare_interior(one, om1) == 26);

  const QuadMesh two = catmull_clark(one);
  CHECK(two.positions.size() == 98);
  CHECK(two.quads.size() == 96);
  CHECK(compare_interior(two, openmesh_catmull_clark(m, 2)) == 98);
}

TEST_CASE("catmull_clark matches OpenMesh on a closed mesh of triangles") {
  PolygonMesh tet;
  tet.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0.1), Vec3(0.2, 1, 0), Vec3(0.3, 0.4, 1.2)};
  tet.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const QuadMesh one = catmull_clark(tet);
  CHECK(one.quads.size() == 12);  // 3 quads per triangle
  CHECK(compare_interior(one, openmesh_catmull_clark(tet, 1)) == 4 + 4 + 6);
}

TEST_CASE("catmull_clark matches OpenMesh inside an open curved grid; the boundary follows our rule") {
  const PolygonMesh m = open_curved_grid();
  const QuadMesh ours = catmull_clark(m);
  const OMesh om = openmesh_catmull_clark(m, 1);
  CHECK(ours.positions.size() == om.n_vertices());
  CHECK(ours.quads.size() == om.n_faces());
  CHECK(ours.quads.size() == 18 * 4 + 3 + 5 + 4);
  // Compared: the interior input vertices, every face point, every interior
  // edge point.
  const EdgeTable t = edge_table(m.faces, m.positions.size(), "test");
  std::size_t interior_edges = 0;
  for (Index e = 0; e < t.ends.size(); ++e) interior_edges += !t.boundary(e);
  const std::size_t interior_inputs = 3 * 4 + 1;  // 3 x 4 grid interior plus the extra vertex
  CHECK(compare_interior(ours, om) == interior_inputs + m.faces.size() + interior_edges);

  // Boundary: input boundary vertices unmoved, boundary edge points at midpoints.
  const std::vector<bool> boundary = boundary_vertices(t, m.positions.size());
  std::size_t unmoved = 0;
  for (std::size_t v = 0; v < m.positions.size(); ++v)
    if (boundary[v]) unmoved += ours.positions[v] == m.positions[v];
  CHECK(unmoved == 18);  // the rim of a 5 x 4 grid
  const Index edge_base = Index(m.positions.size() + m.faces.size());
  for (Index e = 0; e < t.ends.size(); ++e)
    if (t.boundary(e)) {
      const Vec3 mid = (m.positions[t.ends[e][0]] + m.positions[t.ends[e][1]]) / 2;
      CHECK((ours.positions[edge_base + e] - mid).norm() == 0);
    }
}

TEST_CASE("catmull_clark numbers vertices: inputs, face points, edge points; quads wind as their face") {
  const QuadMesh grid = unit_grid(1, 2);  // 6 vertices, 2 quads, 7 edges
  const QuadMesh out = catmull_clark(grid);
  CHECK(out.positions.size() == 6 + 2 + 7);
  CHECK(out.quads.size() == 8);
  CHECK(out.positions[6] == Vec3(0.5, 0.5, 0));  // face point of quad 0
  CHECK(out.positions[7] == Vec3(1.5, 0.5, 0));
  CHECK(out.positions[8] == Vec3(0.5, 0, 0));  // edge 0: vertex 0 to 1, a boundary midpoint
  // The shared edge 1-4 is interior: (1 + 4 + two face points) / 4.
  CHECK(out.positions[9] == Vec3(1, 0.5, 0));
  CHECK(out.quads[0] == QuadIndices{0, 8, 6, 11});
  for (std::size_t v = 0; v < 6; ++v) CHECK(out.positions[v] == grid.positions[v]);  // all on the boundary
}

TEST_CASE("catmull_clark keeps pinned interior vertices in place") {
  QuadMesh grid = unit_grid(2, 2);
  grid.positions[4] = Vec3(1.2, 0.9, 0.5);  // the one interior vertex, displaced
  const QuadMesh free = catmull_clark(grid);
  std::vector<bool> pinned(9, false);
  pinned[4] = true;
  const QuadMesh held = catmull_clark(grid, pinned);
  CHECK(held.positions[4] == grid.positions[4]);
  CHECK(free.positions[4] != grid.positions[4]);
  // Regular valence 4: V' = (Q + 2R + V) / 4 by hand.
  Vec3 q = Vec3::Zero(), r = Vec3::Zero();
  for (int f = 0; f < 4; ++f) q += free.positions[9 + f] / 4;
  for (Index n : {1u, 3u, 5u, 7u}) r += (grid.positions[4] + grid.positions[n]) / 2 / 4;
  CHECK((free.positions[4] - (q + 2 * r + grid.positions[4]) / 4).norm() <= 1e-15);
  // Everything else is the same in both.
  for (std::size_t v = 0; v < free.positions.size(); ++v)
    if (v != 4) CHECK(free.positions[v] == held.positions[v]);
}

TEST_CASE("catmull_clark refuses broken input") {
  PolygonMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  m.faces = {{0, 1}};
  CHECK_THROWS_WITH_AS(catmull_clark(m), doctest::Contains("fewer than 3 corners"), ModelError);
  m.faces = {{0, 1, 3}};
  CHECK_THROWS_WITH_AS(catmull_clark(m), doctest::Contains("uses vertex 3"), ModelError);
  m.faces = {{0, 1, 2}};
  CHECK_THROWS_WITH_AS(catmull_clark(m, {true}), doctest::Contains("pinned has 1 flags for 3 vertices"), ModelError);
  m.positions.push_back(Vec3(0, 0, 1));
  m.positions.push_back(Vec3(0, 0, -1));
  m.faces = {{0, 1, 2}, {0, 1, 3}, {1, 0, 4}};
  CHECK_THROWS_WITH_AS(catmull_clark(m), doctest::Contains("more than two faces"), ModelError);
}
