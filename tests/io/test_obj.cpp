#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/atomic_file.hpp"
#include "io/obj.hpp"

using namespace tendril;

TEST_CASE("obj: units, vertices renumbered densely, a group per block, polylines for beams and cables, oriented quads") {
  Model m;
  ParticleId hole = m.add_particle(Vec3(9, 9, 9));  // deleted below: numbering closes the gap
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
  ParticleId d = m.add_particle(Vec3(0, 0.1, 0));
  m.add_beam({a, b, c}, Section{1e5, 10, 0, 0});
  m.add_cable(a, d, Section{1e3, 0, 0, 0});
  ParticleId e = m.add_particle(Vec3(0, 0, 1)), f = m.add_particle(Vec3(1, 0, 1)), g = m.add_particle(Vec3(0, 1, 1));
  m.add_beam({e, f, g}, Section{1e5, 10, 0, 0}, true);
  std::vector<ParticleId> grid;
  for (int r = 0; r < 2; ++r)
    for (int col = 0; col < 3; ++col) grid.push_back(m.add_particle(Vec3(0.5 * col, r == 0 ? 0.0 : -0.25, 2)));
  m.add_quad_grid(grid, 2, 3, Section{100, 0, 0, 0});
  m.delete_particle(hole);
  REQUIRE(m.check() == "");

  const std::string expected =
      "# tendril model; units: m\n"
      "v 0 0 0\n"
      "v 1 0 0\n"
      "v 2 0 0\n"
      "v 0 0.10000000000000001 0\n"
      "v 0 0 1\n"
      "v 1 0 1\n"
      "v 0 1 1\n"
      "v 0 0 2\n"
      "v 0.5 0 2\n"
      "v 1 0 2\n"
      "v 0 -0.25 2\n"
      "v 0.5 -0.25 2\n"
      "v 1 -0.25 2\n"
      "g beam-0\n"
      "l 1 2 3\n"
      "g cable-1\n"
      "l 1 4\n"
      "g beam-2\n"
      "l 5 6 7 5\n"
      "g patch-3\n"
      "f 8 9 12 11\n"
      "f 9 10 13 12\n";
  CHECK(obj_string(m) == expected);

  const std::string path = (std::filesystem::temp_directory_path() / "tendril_test_io_small.obj").string();
  save_obj(m, path);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  CHECK(text.str() == expected);
  CHECK_THROWS_AS(save_obj(m, "/nonexistent-dir/x.obj"), OutputError);
}

TEST_CASE("obj: every quad of a larger grid once, all wound like the first") {
  Model m;
  const int rows = 4, cols = 5;
  std::vector<ParticleId> grid;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) grid.push_back(m.add_particle(Vec3(c, r, 0)));
  m.add_quad_grid(grid, rows, cols, Section{100, 0, 0, 0});
  std::istringstream in(obj_string(m));
  std::string line;
  int faces = 0;
  std::vector<int> seen(std::size_t(rows - 1) * (cols - 1), 0);
  while (std::getline(in, line)) {
    if (line[0] != 'f') continue;
    ++faces;
    std::istringstream f(line.substr(2));
    int v[4];
    f >> v[0] >> v[1] >> v[2] >> v[3];
    // The lowest vertex first, then along +x: (r,c), (r,c+1), (r+1,c+1), (r+1,c), 1-based.
    const int r = (v[0] - 1) / cols, c = (v[0] - 1) % cols;
    CAPTURE(line);
    CHECK(v[1] == v[0] + 1);
    CHECK(v[2] == v[0] + cols + 1);
    CHECK(v[3] == v[0] + cols);
    ++seen[std::size_t(r) * (cols - 1) + c];
  }
  CHECK(faces == (rows - 1) * (cols - 1));
  CHECK(std::count(seen.begin(), seen.end(), 1) == (rows - 1) * (cols - 1));
}
