// Rule 21 (meshing/projection.hpp): rows interpolated between two sequences,
// open and closed, counts, positions, bars, quality, and refusals that leave
// the model unchanged.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "helpers.hpp"
#include "patch_mesh.hpp"
#include "projection.hpp"
#include "quality.hpp"

using namespace tendril;
using namespace tendril::meshing;
using namespace tendril::meshing::test;

namespace {
std::vector<ParticleId> row(Model& m, int n, double y, double z = 0) {
  std::vector<ParticleId> ps;
  for (int i = 0; i < n; ++i) ps.push_back(m.add_particle(Vec3(i, y, z)));
  return ps;
}
}  // namespace

TEST_CASE("projection between two straight rows of 4 with 1 interior row") {
  Model m;
  const auto a = row(m, 4, 0), b = row(m, 4, 2);
  const CommittedPatch r = patch_by_projection(m, a, b, 1, patch_section());
  CHECK(m.check() == "");
  CHECK(r.created.size() == 4);
  CHECK(m.particle_count() == 12);
  CHECK(patch_mesh(m, r.patch).mesh.quads.size() == 6);
  CHECK(m.bars.size() == 17);  // 3 rows of 3 plus 4 columns of 2
  for (int i = 0; i < 4; ++i) {
    CHECK(r.particles[i] == a[i]);
    CHECK(r.particles[4 + i] == b[i]);
    CHECK(m.particles.position[r.created[i]] == Vec3(i, 1, 0));
    CHECK(m.state(r.created[i]) == State::Simple);
  }
  const Quality q = quality(m, r.patch);
  CHECK(q.jacobian_min == 1.0);
  CHECK(q.jacobian_mean == 1.0);
  CHECK(q.angle_min == doctest::Approx(90).epsilon(1e-12));
  CHECK(q.angle_max == doctest::Approx(90).epsilon(1e-12));
  CHECK(q.interior_vertices == 2);
  CHECK(q.irregular_fraction == 0);
}

TEST_CASE("projection rows sit at equal fractions along each rung") {
  const std::vector<Vec3> a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0.5, 0)};
  const std::vector<Vec3> b{Vec3(0, 2, 1), Vec3(1, 3, 1), Vec3(2, 2, 2)};
  const QuadMesh mesh = projection(a, b, 3);
  CHECK(mesh.positions.size() == 15);
  CHECK(mesh.quads.size() == 8);  // 4 bands of 2
  for (int k = 1; k <= 3; ++k)
    for (int i = 0; i < 3; ++i)
      CHECK((mesh.positions[6 + (k - 1) * 3 + i] - (a[i] + k * 0.25 * (b[i] - a[i]))).norm() <= 1e-15);
  CHECK(mesh.quads[0] == QuadIndices{0, 1, 7, 6});
  CHECK(mesh.quads[7] == QuadIndices{13, 14, 5, 4});
  // No interior rows: one band straight from A to B.
  const QuadMesh band = projection(a, b, 0);
  CHECK(band.positions.size() == 6);
  CHECK(band.quads == std::vector<QuadIndices>{{0, 1, 4, 3}, {1, 2, 5, 4}});
}

TEST_CASE("projection of a rectangle of 5 x 4 quads has quality 1") {
  Model m;
  std::vector<ParticleId> a, b;
  for (int i = 0; i <= 5; ++i) {
    a.push_back(m.add_particle(Vec3(0.4 * i, 0, 0)));
    b.push_back(m.add_particle(Vec3(0.4 * i, 1.2, 0)));
  }
  const CommittedPatch r = patch_by_projection(m, a, b, 3, patch_section());
  const Quality q = quality(m, r.patch);
  CHECK(q.quads == 20);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(1e-12));
  CHECK(q.jacobian_mean == doctest::Approx(1).epsilon(1e-12));
  CHECK(q.interior_vertices == 12);
  CHECK(q.irregular_fraction == 0);
  for (std::size_t e = 0; e < m.bars.size(); ++e) {
    const double len = m.bars[e].rest_length;
    CHECK((std::abs(len - 0.4) <= 1e-12 || std::abs(len - 0.3) <= 1e-12));
  }
}

TEST_CASE("projection between two rings closes into a tube") {
  Model m;
  std::vector<ParticleId> a, b;
  for (int i = 0; i < 6; ++i) {
    const double t = 2 * std::numbers::pi * i / 6;
    a.push_back(m.add_particle(Vec3(std::cos(t), std::sin(t), 0)));
    b.push_back(m.add_particle(Vec3(std::cos(t), std::sin(t), 2)));
  }
  m.add_beam(a, beam_section(), true);
  m.add_beam(b, beam_section(), true);
  const CommittedPatch r = patch_by_projection(m, a, b, 2, patch_section(), true);
  CHECK(m.check() == "");
  CHECK(r.created.size() == 12);
  CHECK(patch_mesh(m, r.patch).mesh.quads.size() == 18);
  const Quality q = quality(m, r.patch);
  CHECK(q.jacobian_min == doctest::Approx(1).epsilon(1e-12));
  CHECK(q.interior_vertices == 12);  // both interior rings, valence 4
  CHECK(q.irregular_fraction == 0);
  for (ParticleId p : a) CHECK(m.state(p) == State::Shared);
}

TEST_CASE("projection refuses bad sequences and leaves the model unchanged") {
  Model m;
  const auto a = row(m, 4, 0), b = row(m, 4, 2), c = row(m, 3, 4);
  const ParticleId on_a1 = m.add_particle(Vec3(1, 0, 0));  // where a[1] is
  const ParticleId on_b0 = m.add_particle(Vec3(0, 2, 0));  // where b[0] is
  m.add_beam(a, beam_section());
  m.delete_particle(m.add_particle(Vec3(5, 5, 5)));
  const Fingerprint before(m);
  auto refused = [&](const std::vector<ParticleId>& x, const std::vector<ParticleId>& y, int rows, const char* message,
                     bool closed = false, Section s = patch_section()) {
    CAPTURE(message);
    CHECK_THROWS_WITH_AS(patch_by_projection(m, x, y, rows, s, closed), doctest::Contains(message), ModelError);
    CHECK(Fingerprint(m) == before);
  };
  refused(a, c, 1, "differ in length (4 and 3)");
  refused({a[0]}, {b[0]}, 1, "at least 2 particles, got 1");
  refused({a[0], a[1]}, {b[0], b[1]}, 1, "at least 3 particles when closed, got 2", true);
  refused(a, b, -1, "rows must be between 0 and 10000, got -1");
  refused(a, {b[0], b[1], a[2], b[3]}, 1, "appears twice");
  refused(a, {b[0], on_a1, b[2], b[3]}, 1, "A[1] and B[1] coincide");
  refused(a, {b[0], on_b0, b[2], b[3]}, 1, "consecutive points B[0] and B[1] coincide");
  refused(a, {b[0], b[1], b[2], 4242}, 1, "4242");
  refused(a, b, 1, "EA must be > 0", false, Section{0, 0, 0, 0});
}
