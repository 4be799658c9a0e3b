// Multi-resolution tensile patch (thesis 5.5.2.3): states after building,
// refining and coarsening, exact rollback of a refused change, and the
// coarse and the fine solution of a prestressed square membrane under its
// own weight against each other and against the linear membrane.
#include <doctest/doctest.h>

#include <cmath>

#include "multires.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using namespace tendril::meshing;

namespace {

// An n x n quad grid over a square of side a in the xy plane, boundary locked.
struct Square {
  Model m;
  std::vector<ParticleId> g;
  BlockId patch;
  Square(int n, double a, const Section& s) {
    for (int r = 0; r <= n; ++r)
      for (int c = 0; c <= n; ++c) {
        g.push_back(m.add_particle(Vec3(a * c / n, a * r / n, 0)));
        if (r == 0 || c == 0 || r == n || c == n) m.set_lock(g.back(), kLockTranslation);
      }
    patch = m.add_quad_grid(g, n + 1, n + 1, s);
  }
};

std::size_t passive_count(const Model& m) {
  std::size_t n = 0;
  for (ParticleId p = 0; p < m.particles.capacity(); ++p) n += m.particles.valid(p) && m.particles.passive[p];
  return n;
}

}  // namespace

TEST_CASE("multires: coarse mode, refine and coarsen leave the states and buffers they promise") {
  Square sq(2, 2.0, Section{1e3, 0, 100, 1.0});  // 3 x 3 particles, 12 bars
  Model& m = sq.m;
  MultiresPatch mr = multires_patch(m, sq.patch, 2);
  CHECK(m.check() == "");
  CHECK(mr.coarse_mode());
  CHECK(mr.particles.size() == 16);  // 5 x 5 fine particles, 9 of them coarse
  CHECK(m.particle_count() == 25);
  CHECK(passive_count(m) == 16);
  CHECK(m.particles.integrated.size() == 9);
  CHECK(m.bars.size() == 12 + 40);
  CHECK(m.bars.awake == 12);  // every fine bar touches a fine-only particle
  CHECK(m.state(sq.g[4]) == State::Shared);  // the centre: on both patches
  // The fine section is the coarse one over the factor.
  CHECK(m.blocks[mr.fine].section.EA == doctest::Approx(500));
  CHECK(m.blocks[mr.fine].section.prestress == doctest::Approx(50));
  CHECK(m.blocks[mr.fine].section.line_mass == doctest::Approx(0.5));
  // Boundary edge points between locked corners are locked, interior ones not.
  std::size_t locked = 0;
  for (ParticleId p : mr.particles) locked += m.particles.lock[p] == kLockTranslation;
  CHECK(locked == 8);

  // The coarse net sags; refine puts the fine particles on its surface.
  m.particles.position[sq.g[4]] = Vec3(1, 1, -0.2);
  multires_refine(m, mr);
  CHECK(m.check() == "");
  CHECK_FALSE(mr.coarse_mode());
  CHECK(passive_count(m) == 0);
  CHECK(m.particles.integrated.size() == 25);
  CHECK(m.block_count(BlockKind::Patch) == 1);
  CHECK(m.bars.size() == 40);
  CHECK(m.bars.awake == 40);
  for (std::size_t k = 0; k < mr.particles.size(); ++k) {
    const Vec3 x = m.particles.position[mr.particles[k]];
    // Bilinear over the quads around the centre: z is -0.2 times the
    // centre's weight, i.e. -0.2 (1 - |x - 1|)(1 - |y - 1|).
    CHECK(x.z() == doctest::Approx(-0.2 * (1 - std::abs(x.x() - 1)) * (1 - std::abs(x.y() - 1))));
  }
  CHECK(m.state(sq.g[4]) == State::Simple);

  multires_coarsen(m, mr);
  CHECK(m.check() == "");
  CHECK(mr.coarse_mode());
  CHECK(passive_count(m) == 16);
  CHECK(m.bars.size() == 52);
  CHECK(m.bars.awake == 12);
  CHECK(m.block_count(BlockKind::Patch) == 2);
  // The re-created links take the current distances as rest lengths.
  double rest = 0;
  for (std::size_t e = 0; e < m.bars.awake; ++e)
    if ((m.bars[e].i == sq.g[1] && m.bars[e].j == sq.g[4]) || (m.bars[e].i == sq.g[4] && m.bars[e].j == sq.g[1]))
      rest = m.bars[e].rest_length;
  CHECK(rest == doctest::Approx(std::sqrt(1 + 0.04)).epsilon(1e-12));
}

TEST_CASE("multires: refused requests change nothing") {
  Square sq(2, 2.0, Section{1e3, 0, 100, 1.0});
  Model& m = sq.m;
  CHECK_THROWS_WITH_AS(multires_patch(m, sq.patch, 1), doctest::Contains("factor"), ModelError);
  CHECK_THROWS_WITH_AS(multires_patch(m, sq.patch + 7, 2), doctest::Contains("7"), ModelError);
  m.set_passive(sq.g[4], true);
  CHECK_THROWS_WITH_AS(multires_patch(m, sq.patch, 2), doctest::Contains("passive"), ModelError);
  m.set_passive(sq.g[4], false);
  CHECK(m.particle_count() == 9);
  MultiresPatch mr = multires_patch(m, sq.patch, 3);
  CHECK_THROWS_WITH_AS(multires_coarsen(m, mr), doctest::Contains("already coarse"), ModelError);
  multires_refine(m, mr);
  CHECK_THROWS_WITH_AS(multires_refine(m, mr), doctest::Contains("already fine"), ModelError);
  CHECK(m.check() == "");
}

// Centre value of the 5-point net equation sum(w_nb - w) = -rhs on an n x n
// grid with w = 0 on the boundary (Gauss-Seidel to round-off).
double net_centre(int n, double rhs) {
  std::vector<double> w(std::size_t(n + 1) * (n + 1), 0.0);
  auto at = [&](int i, int j) -> double& { return w[std::size_t(i) * (n + 1) + j]; };
  for (int it = 0; it < 4000; ++it)
    for (int i = 1; i < n; ++i)
      for (int j = 1; j < n; ++j) at(i, j) = (at(i + 1, j) + at(i - 1, j) + at(i, j + 1) + at(i, j - 1) + rhs) / 4;
  return at(n / 2, n / 2);
}

double relative(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST_CASE("multires: the coarse and the refined fine solution of a prestressed square under its weight agree") {
  // Square membrane, side a = 4 m, boundary fixed, tension n = T/h = 1 kN/m
  // both ways, weight q = 2 mu g / h = 19.62 N/m^2 (bars of mu = 1 kg/m at
  // h = 1 m; the fine net: T/4, mu/4 at h/4, the same n and q). A net of
  // spacing h is the 5-point Laplacian n lap(w) = q: its centre sag is
  // net_centre(a/h, q h^2 / n) (9/8 q h^2 / n on the 4 x 4 net); the linear
  // membrane's is 0.0736713 q a^2 / n (series solution), 23.13 mm.
  const double a = 4, h = 1, T = 1000, mu = 1, g = 9.81;
  const double q = 2 * mu * g / h, tension = T / h;
  const double membrane = 0.0736713 * q * a * a / tension;
  const double coarse_net = net_centre(4, q * h * h / tension), fine_net = net_centre(16, q * h * h / 16 / tension);
  Square sq(4, a, Section{1e2, 0, T, mu});
  Model& m = sq.m;
  m.gravity = Vec3(0, 0, -g);
  MultiresPatch mr = multires_patch(m, sq.patch, 4);  // 16 x 16 fine quads, 264 of 289 particles passive
  CHECK(passive_count(m) == 264);
  Solver s(m);
  const RunResult coarse = s.run(1e-7, 200000);
  REQUIRE(coarse.converged);
  const ParticleId centre = sq.g[12];
  const double w_coarse = -m.particles.position[centre].z();
  multires_refine(m, mr);
  s.reset_motion();
  const RunResult fine = s.run(1e-7, 200000);
  REQUIRE(fine.converged);
  const double w_fine = -m.particles.position[centre].z();
  MESSAGE("centre sag: coarse " << w_coarse << " m (net " << coarse_net << "), fine " << w_fine << " m (net "
                                << fine_net << "), linear membrane " << membrane << " m; steps " << coarse.steps
                                << " + " << fine.steps);
  CHECK(coarse_net == doctest::Approx(9.0 / 8 * q * h * h / tension).epsilon(1e-12));
  // Each resolution solves its own net (stretching under EA = 100 N adds
  // < 0.05 %), the fine one within 0.3 % of the membrane, and the two
  // resolutions agree within 5 % (the coarse net's discretisation error).
  CHECK(relative(w_coarse, coarse_net) < 1e-3);
  CHECK(relative(w_fine, fine_net) < 1e-3);
  CHECK(relative(w_fine, membrane) < 0.005);
  CHECK(relative(w_coarse, w_fine) < 0.05);
  CHECK(relative(w_coarse, w_fine) > 0.03);  // the 4 x 4 net is measurably coarser (4.3 %)
  CHECK(m.check() == "");
}
