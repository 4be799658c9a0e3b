#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/ply.hpp"

using namespace tendril;

TEST_CASE("ply: vertices 0-based in id order, edges of cables and beams (a ring closed), faces of patches, block ids") {
  Model m;
  ParticleId hole = m.add_particle(Vec3(9, 9, 9));  // deleted below: numbering closes the gap
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
  m.add_beam({a, b, c}, Section{1e5, 10, 0, 0});
  ParticleId e = m.add_particle(Vec3(0, 0, 1)), f = m.add_particle(Vec3(1, 0, 1)), g = m.add_particle(Vec3(0, 1, 1));
  m.add_beam({e, f, g}, Section{1e5, 10, 0, 0}, true);
  std::vector<ParticleId> grid;
  for (int r = 0; r < 2; ++r)
    for (int col = 0; col < 2; ++col) grid.push_back(m.add_particle(Vec3(col, r, 2)));
  m.add_quad_grid(grid, 2, 2, Section{100, 0, 0, 0});
  m.delete_particle(hole);
  REQUIRE(m.check() == "");
  const std::string expected =
      "ply\nformat ascii 1.0\ncomment tendril model; units: m\n"
      "element vertex 10\nproperty double x\nproperty double y\nproperty double z\n"
      "element edge 5\nproperty int vertex1\nproperty int vertex2\nproperty int block\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty int block\n"
      "end_header\n"
      "0 0 0\n1 0 0\n2 0 0\n0 0 1\n1 0 1\n0 1 1\n0 0 2\n1 0 2\n0 1 2\n1 1 2\n"
      "0 1 0\n1 2 0\n"
      "3 4 1\n4 5 1\n5 3 1\n"
      "4 6 7 9 8 2\n";
  CHECK(ply_string(m) == expected);
  const std::string path = (std::filesystem::temp_directory_path() / "tendril_test_io_small.ply").string();
  save_ply(m, path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  CHECK(text.str() == expected);
  CHECK_THROWS_AS(save_ply(m, "/nonexistent-dir/x.ply"), OutputError);
}
