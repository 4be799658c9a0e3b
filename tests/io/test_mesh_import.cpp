// Reading OBJ and ASCII PLY geometry (io/mesh_import.hpp): vertices,
// polylines and faces per group, the index forms of OBJ, tendril's own
// PLY read back block by block, and malformed files refused naming the
// line at fault.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "io/input_file.hpp"
#include "io/mesh_import.hpp"
#include "io/ply.hpp"

using namespace tendril;

namespace {

std::string refusal(const std::string& text, bool ply = false) {
  try {
    ply ? parse_ply(text, "f.ply") : parse_obj(text, "f.obj");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("OBJ: vertices, polylines and faces by group; v/vt/vn and negative indices") {
  const ImportedMesh m = parse_obj(R"(# from a CAD tool
mtllib rods.mtl
o rod
v 0 0 0
v 1.5 0 0
v 3 0 0.25
vt 0 0
vn 0 0 1
l 1 2 3
g roof panel
v 0 1 0
v 1 1 0
v 1 2 0
v 0 2 0
usemtl fabric
f -4/1/1 -3/1/1 -2//1 -1
g rod
l 3 1   # back to the rod's group
)",
                                   "f.obj");
  REQUIRE(m.vertices.size() == 7);
  CHECK(m.vertices[2].isApprox(Vec3(3, 0, 0.25)));
  REQUIRE(m.groups.size() == 2);
  CHECK(m.groups[0].name == "rod");
  CHECK(m.groups[0].lines == std::vector<std::vector<std::size_t>>{{0, 1, 2}, {2, 0}});
  CHECK(m.groups[0].faces.empty());
  CHECK(m.groups[1].name == "roof panel");
  CHECK(m.groups[1].faces == std::vector<std::vector<std::size_t>>{{3, 4, 5, 6}});
}

TEST_CASE("PLY: tendril's own PLY reads back a group per block, a beam's edges as one polyline") {
  Model model;
  std::vector<ParticleId> ps;
  for (int i = 0; i < 4; ++i) ps.push_back(model.add_particle(Vec3(i, 0, 0)));
  model.add_beam(ps, Section{1e6, 10, 0, 0});
  const ParticleId top = model.add_particle(Vec3(0, 0, 2));
  model.add_cable(top, ps[3], Section{1e5, 0, 0, 0});
  const auto dir = std::filesystem::temp_directory_path() / "tendril-mesh-import";
  std::filesystem::create_directories(dir);
  save_ply(model, (dir / "m.ply").string());
  const ImportedMesh m = import_mesh((dir / "m.ply").string());
  REQUIRE(m.vertices.size() == 5);
  REQUIRE(m.groups.size() == 2);
  CHECK(m.groups[0].name == "block-0");
  CHECK(m.groups[0].lines == std::vector<std::vector<std::size_t>>{{0, 1, 2, 3}});
  CHECK(m.groups[1].lines == std::vector<std::vector<std::size_t>>{{4, 3}});
  CHECK(m.vertices[4].isApprox(Vec3(0, 0, 2)));
}

TEST_CASE("Malformed OBJ and PLY are refused naming the file and line") {
  CHECK(refusal("v 0 0 0\nv 1 0\n") == "f.obj:2: a vertex needs x y z");
  CHECK(refusal("v 0 0 0\nv 1 0 nan\n") == "f.obj:2: 'nan' is not a finite number");
  CHECK(refusal("v 0 0 0\nl 1 2\n") == "f.obj:2: vertex 2 is not among the 1 vertices so far");
  CHECK(refusal("v 0 0 0\nl 1\n") == "f.obj:2: a polyline needs at least 2 vertices");
  CHECK(refusal("v 0 0 0\nv 1 0 0\nf 1 2\n") == "f.obj:3: a face needs at least 3 vertices");
  CHECK(refusal("v 0 0 0\nl 1 x\n") == "f.obj:2: 'x' is not a whole number");
  CHECK(refusal("ply\nformat binary_little_endian 1.0\n", true) == "f.ply:2: only ASCII PLY is read (save it as ASCII)");
  CHECK(refusal("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 0\n0 3\n",
                true) == "f.ply:12: vertex 3 is not among the 1 vertices");
  CHECK(refusal("ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
                "end_header\n0 0 0\n",
                true) == "f.ply:8: the file ends early");
  CHECK(refusal("solid\n", true) == "f.ply:1: a PLY file starts with 'ply'");
  CHECK_THROWS_WITH_AS(import_mesh("model.stl"), "model.stl: tendril imports .obj and .ply files", InputError);
}
