// Binary PLY through OpenMesh (meshing/ply_openmesh.hpp): a model's patches
// written by OpenMesh read back (by OpenMesh, and by tendril.import) to the
// same vertices in single precision and the same quads, consistently
// wound; a mesh written by OpenMesh itself imports; a binary PLY with edges
// and a non-manifold one are refused.
#include <doctest/doctest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <set>
#include <sstream>

#include "io/input_file.hpp"
#include "model/model.hpp"
#include "ply_openmesh.hpp"

using namespace tendril;

TEST_CASE("binary PLY: a model's patches through OpenMesh and back") {
  Model m;
  std::vector<ParticleId> grid;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) grid.push_back(m.add_particle(Vec3(0.5 * c, 0.25 * r, 0.1 * r * c + 1.0 / 3)));
  Section s;
  s.EA = 10;
  m.add_quad_grid(grid, 3, 4, s);
  const ParticleId a = m.add_particle(Vec3(9, 9, 9)), b = m.add_particle(Vec3(9, 9, 8));
  m.add_cable(a, b, s);  // no patch: not in the file
  const std::string bytes = meshing::patches_ply_binary(m);
  CHECK(bytes.find("format binary_little_endian") != std::string::npos);
  const ImportedMesh back = meshing::read_binary_ply(bytes, "patches.ply");
  REQUIRE(back.vertices.size() == 12);
  for (std::size_t k = 0; k < 12; ++k)
    CHECK((back.vertices[k] - m.particles.position[grid[k]]).norm() < 1e-6);  // single precision
  REQUIRE(back.groups.size() == 1);
  CHECK(back.groups[0].name == "faces");
  REQUIRE(back.groups[0].faces.size() == 6);
  // Every quad of the grid, wound alike: each interior edge walked once each way.
  std::set<std::pair<std::size_t, std::size_t>> directed;
  std::set<std::set<std::size_t>> quads;
  for (const auto& f : back.groups[0].faces) {
    REQUIRE(f.size() == 4);
    quads.insert(std::set<std::size_t>(f.begin(), f.end()));
    for (std::size_t k = 0; k < 4; ++k) CHECK(directed.insert({f[k], f[(k + 1) % 4]}).second);
  }
  for (std::size_t r = 0; r < 2; ++r)
    for (std::size_t c = 0; c < 3; ++c)
      CHECK(quads.count({4 * r + c, 4 * r + c + 1, 4 * r + c + 5, 4 * r + c + 4}) == 1);

  Model empty;
  CHECK_THROWS_WITH(meshing::patches_ply_binary(empty), "save_ply: a binary PLY holds patches, and the model has none");
}

TEST_CASE("binary PLY: a mesh OpenMesh writes imports; edges and non-manifold faces are refused") {
  using Mesh = OpenMesh::PolyMesh_ArrayKernelT<>;
  Mesh mesh;
  std::vector<Mesh::VertexHandle> v;
  for (int k = 0; k < 5; ++k) v.push_back(mesh.add_vertex(Mesh::Point(float(k % 3), float(k / 3), 0.5f)));
  mesh.add_face(v[0], v[1], v[4], v[3]);
  mesh.add_face(v[1], v[2], v[4]);
  std::ostringstream out;
  REQUIRE(OpenMesh::IO::write_mesh(mesh, out, ".ply", OpenMesh::IO::Options::Binary));
  const ImportedMesh m = meshing::read_binary_ply(out.str(), "drawn.ply");
  REQUIRE(m.vertices.size() == 5);
  CHECK(m.vertices[4] == Vec3(1, 1, 0.5));
  REQUIRE(m.groups.size() == 1);
  CHECK(m.groups[0].faces == std::vector<std::vector<std::size_t>>{{0, 1, 4, 3}, {1, 2, 4}});

  // Three faces on one edge: OpenMesh splits vertices; the file is refused, not altered.
  std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex 5\nproperty float x\nproperty float y\n"
                       "property float z\nelement face 3\nproperty list uchar int vertex_indices\nend_header\n";
  std::string body;
  auto put = [&](const auto& x) { body.append(reinterpret_cast<const char*>(&x), sizeof x); };
  for (int k = 0; k < 5; ++k) put(float(k)), put(float(k * k)), put(0.0f);
  for (const auto& tri : {std::array{0, 1, 2}, std::array{0, 1, 3}, std::array{0, 1, 4}}) {
    put(std::uint8_t(3));
    for (int i : tri) put(i);
  }
  CHECK_THROWS_WITH_AS(meshing::read_binary_ply(header + body, "fan.ply"),
                       doctest::Contains("fan.ply: OpenMesh read 11 of 5 vertices and 3 of 3 faces"), InputError);
  const std::string edges = "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                            "property float z\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  CHECK_THROWS_WITH_AS(meshing::read_binary_ply(edges, "edges.ply"),
                       "edges.ply: a binary PLY's edges are not read (OpenMesh reads faces); save it as ASCII PLY",
                       InputError);
}
