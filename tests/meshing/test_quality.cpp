// Quality metrics (meshing/quality.hpp) against closed-form numbers: the unit
// grid, sheared and trapezoidal quads, a reflex quad, a warped quad, a
// cylinder strip of planar rectangles, and a mesh with one valence-3 vertex.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "helpers.hpp"
#include "quality.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {
constexpr double kTol = 1e-12;
const double kDeg = 180 / std::numbers::pi;
}  // namespace

TEST_CASE("quality of a unit square grid: Jacobian 1, right angles, no irregular vertex") {
  const Quality q = quality(unit_grid(3, 4));
  CHECK(q.quads == 12);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(kTol));
  CHECK(q.jacobian_mean == doctest::Approx(1).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(90).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(kTol));
  CHECK(q.interior_vertices == 6);  // (3-1) x (4-1)
  CHECK(q.irregular_vertices == 0);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("quality of a sheared grid: the scaled Jacobian is the sine of the shear angle") {
  // Every quad is a parallelogram with corner angles 60 and 120 degrees.
  QuadMesh m = unit_grid(2, 3);
  for (Vec3& x : m.positions) x = Vec3(x.x() + 0.5 * x.y(), x.y() * std::sqrt(3.0) / 2, 0);
  const Quality q = quality(m);
  CHECK(q.jacobian_min == doctest::Approx(std::sqrt(3.0) / 2).epsilon(kTol));
  CHECK(q.jacobian_mean == doctest::Approx(std::sqrt(3.0) / 2).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(60).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(120).epsilon(kTol));
  CHECK(q.interior_vertices == 2);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("quality of trapezoids: 45 and 135 degree corners give sqrt(2)/2") {
  QuadMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(4, 0, 0), Vec3(3, 1, 0), Vec3(1, 1, 0),       // isosceles
                 Vec3(10, 0, 0), Vec3(13, 0, 0), Vec3(12, 1, 0), Vec3(10, 1, 0)};  // right trapezoid
  m.quads = {{0, 1, 2, 3}, {4, 5, 6, 7}};
  const auto iso = corner_jacobians(m.positions[0], m.positions[1], m.positions[2], m.positions[3]);
  for (double j : iso) CHECK(j == doctest::Approx(std::sqrt(0.5)).epsilon(kTol));
  const auto right = corner_jacobians(m.positions[4], m.positions[5], m.positions[6], m.positions[7]);
  CHECK(right[0] == doctest::Approx(1).epsilon(kTol));
  CHECK(right[1] == doctest::Approx(std::sqrt(0.5)).epsilon(kTol));
  CHECK(right[2] == doctest::Approx(std::sqrt(0.5)).epsilon(kTol));
  CHECK(right[3] == doctest::Approx(1).epsilon(kTol));
  const Quality q = quality(m);
  CHECK(q.jacobian_min == doctest::Approx(std::sqrt(0.5)).epsilon(kTol));
  CHECK(q.jacobian_mean == doctest::Approx(std::sqrt(0.5)).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(45).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(135).epsilon(kTol));
  CHECK(q.interior_vertices == 0);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("quality of a reflex quad: negative Jacobian and an angle above 180 degrees") {
  // An arrowhead: the corner at (0.5, 0.5) points inwards.
  QuadMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0.5, 0.5, 0), Vec3(0, 2, 0)};
  m.quads = {{0, 1, 2, 3}};
  const auto j = corner_jacobians(m.positions[0], m.positions[1], m.positions[2], m.positions[3]);
  CHECK(j[0] == doctest::Approx(1).epsilon(kTol));
  CHECK(j[1] == doctest::Approx(1 / (2 * std::sqrt(2.5))).epsilon(kTol));
  CHECK(j[2] == doctest::Approx(-0.8).epsilon(kTol));
  CHECK(j[3] == doctest::Approx(1 / (2 * std::sqrt(2.5))).epsilon(kTol));
  // Winding the quad the other way round gives the same numbers.
  CHECK(scaled_jacobian(m.positions[3], m.positions[2], m.positions[1], m.positions[0]) ==
        doctest::Approx(-0.8).epsilon(kTol));
  const Quality q = quality(m);
  CHECK(q.jacobian_min == doctest::Approx(-0.8).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(std::atan(1.0 / 3) * kDeg).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(360 - std::acos(-0.6) * kDeg).epsilon(kTol));
}

TEST_CASE("quality of a warped quad: corners against the average normal") {
  // One corner lifted by 1: the average normal is (-1, -1, 2) / sqrt(6).
  QuadMesh m;
  m.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 1), Vec3(0, 1, 0)};
  m.quads = {{0, 1, 2, 3}};
  const auto j = corner_jacobians(m.positions[0], m.positions[1], m.positions[2], m.positions[3]);
  CHECK(j[0] == doctest::Approx(2 / std::sqrt(6.0)).epsilon(kTol));
  CHECK(j[1] == doctest::Approx(3 / std::sqrt(12.0)).epsilon(kTol));
  CHECK(j[2] == doctest::Approx(2 / std::sqrt(6.0)).epsilon(kTol));
  CHECK(j[3] == doctest::Approx(3 / std::sqrt(12.0)).epsilon(kTol));
  const Quality q = quality(m);
  CHECK(q.jacobian_min == doctest::Approx(2 / std::sqrt(6.0)).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(60).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(kTol));
}

TEST_CASE("quality of a curved strip of planar rectangles is 1") {
  // Half a cylinder of radius 2 in 6 facets, 3 rows high: each quad is a
  // planar rectangle, so curvature of the patch alone costs nothing.
  QuadMesh m;
  for (int r = 0; r <= 3; ++r)
    for (int k = 0; k <= 6; ++k) {
      const double a = std::numbers::pi * k / 6;
      m.positions.push_back(Vec3(2 * std::cos(a), 2 * std::sin(a), 0.7 * r));
    }
  for (Index r = 0; r < 3; ++r)
    for (Index k = 0; k < 6; ++k) m.quads.push_back({r * 7 + k, r * 7 + k + 1, (r + 1) * 7 + k + 1, (r + 1) * 7 + k});
  const Quality q = quality(m);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(90).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(kTol));
  CHECK(q.interior_vertices == 10);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("quality counts one irregular vertex among seven interior ones") {
  // Three 60/120-degree rhombi around the origin (valence 3 there), each cut
  // into 2 x 2: interior vertices are the origin, three spoke midpoints and
  // three rhombus centres.
  MeshBuilder b;
  auto mid = [](const Vec3& x, const Vec3& y) -> Vec3 { return (x + y) * 0.5; };
  const Vec3 o(0, 0, 0);
  std::array<Vec3, 3> spoke;
  for (int k = 0; k < 3; ++k) spoke[k] = Vec3(std::cos(2 * std::numbers::pi * k / 3), std::sin(2 * std::numbers::pi * k / 3), 0);
  for (int k = 0; k < 3; ++k) {
    const Vec3 s0 = spoke[k], s1 = spoke[(k + 1) % 3];
    const Vec3 c = s0 + s1;
    const Vec3 centre = (o + c) * 0.5;
    b.quad(o, mid(o, s0), centre, mid(o, s1));
    b.quad(mid(o, s0), s0, mid(s0, c), centre);
    b.quad(centre, mid(s0, c), c, mid(c, s1));
    b.quad(mid(o, s1), centre, mid(c, s1), s1);
  }
  const Quality q = quality(b.mesh);
  CHECK(q.quads == 12);
  CHECK(b.mesh.positions.size() == 19);
  CHECK(q.interior_vertices == 7);
  CHECK(q.irregular_vertices == 1);
  CHECK(q.irregular_fraction == doctest::Approx(1.0 / 7).epsilon(kTol));
  CHECK(q.jacobian_min == doctest::Approx(std::sqrt(3.0) / 2).epsilon(1e-9));
  CHECK(q.angle_min == doctest::Approx(60).epsilon(1e-9));
  CHECK(q.angle_max == doctest::Approx(120).epsilon(1e-9));
}

TEST_CASE("quality of a patch block of a model equals that of its quads") {
  Model m;
  std::vector<ParticleId> grid;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 5; ++c) grid.push_back(m.add_particle(Vec3(0.5 * c, 0.5 * r, 1)));
  const BlockId patch = m.add_quad_grid(grid, 4, 5, patch_section());
  const Quality q = quality(m, patch);
  CHECK(q.quads == 12);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(kTol));
  CHECK(q.jacobian_mean == doctest::Approx(1).epsilon(kTol));
  CHECK(q.angle_min == doctest::Approx(90).epsilon(kTol));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(kTol));
  CHECK(q.interior_vertices == 6);
  CHECK(q.irregular_fraction == 0);

  const BlockId beam = m.add_beam({grid[0], grid[1]}, beam_section());
  CHECK_THROWS_WITH_AS(quality(m, beam), doctest::Contains("not a patch"), ModelError);
  CHECK_THROWS_AS(quality(m, 99), ModelError);
}

TEST_CASE("quality refuses an empty mesh and broken quads") {
  CHECK_THROWS_WITH_AS(quality(QuadMesh{}), doctest::Contains("no quads"), ModelError);
  QuadMesh m = unit_grid(1, 1);
  m.quads[0][2] = 7;
  CHECK_THROWS_WITH_AS(quality(m), doctest::Contains("uses vertex 7"), ModelError);
  m.quads[0][2] = 0;
  CHECK_THROWS_WITH_AS(quality(m), doctest::Contains("repeats vertex 0"), ModelError);
}
