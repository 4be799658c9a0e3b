// Discrete-shell bending hinges (Goal::Bend, physics/shell_bending.hpp):
// flat placements of the rest triangles pull nothing and the forces are the
// energy's gradient; a strip bent onto a cylinder stores the plate's
// (1/2) D kappa^2 per area; a simply supported plate strip reaches one
// equilibrium under every integrator, softer than the plate by a measured
// factor; the model database keeps the hinges.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "every_integrator.hpp"
#include "physics/shell_bending.hpp"
#include "physics/solver.hpp"
#include "reload.hpp"

using namespace tendril;
using test::every_integrator;

namespace {

// A flat strip (length L along x, width W along y) of nx x ny quads, each
// split by one diagonal, alternating: the grid's particles, and a bending
// hinge of stiffness D on every interior edge; bars of axial stiffness EA
// on every edge for the membrane.
struct Strip {
  Model m;
  int nx, ny;
  std::vector<ParticleId> p;
  std::vector<std::size_t> hinges;
  double L, W;

  Strip(double L_, double W_, int nx_, int ny_, double D, double EA) : nx(nx_), ny(ny_), L(L_), W(W_) {
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i) p.push_back(m.add_particle(Vec3(L * i / nx, W * j / ny, 0)));
    std::vector<std::array<ParticleId, 3>> triangles;
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        const ParticleId a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
        if ((i + j) % 2 == 0) triangles.insert(triangles.end(), {{a, b, c}, {a, c, d}});
        else triangles.insert(triangles.end(), {{a, b, d}, {b, c, d}});
      }
    // Every edge with the corners opposite it.
    std::map<std::pair<ParticleId, ParticleId>, std::vector<ParticleId>> edges;
    for (const auto& t : triangles)
      for (int k = 0; k < 3; ++k) {
        const ParticleId u = t[k], v = t[(k + 1) % 3];
        edges[{std::min(u, v), std::max(u, v)}].push_back(t[(k + 2) % 3]);
      }
    for (const auto& [e, opposite] : edges) {
      m.add_elastic_bar(e.first, e.second, Section{EA, 0, 0, 0});
      if (opposite.size() != 2) continue;
      const Vec3* x = m.particles.position.data();
      BendHinge h;
      REQUIRE(bend_hinge(x[e.first], x[e.second], x[opposite[0]], x[opposite[1]], h));
      Goal g;
      g.kind = Goal::Bend;
      g.i = e.first, g.j = e.second, g.k = opposite[0], g.l = opposite[1];
      g.hinge = h.K;
      g.hinge_area = h.area;
      g.weight = D;
      hinges.push_back(m.add_goal(g));
    }
  }
  ParticleId at(int i, int j) const { return p[std::size_t(j * (nx + 1) + i)]; }

  double energy(const std::vector<Vec3>& x) const {
    double E = 0;
    for (std::size_t k : hinges) {
      const Goal& g = std::as_const(m.goals)[k];
      const Vec3 v = g.hinge[0] * x[g.i] + g.hinge[1] * x[g.j] + g.hinge[2] * x[g.k] + g.hinge[3] * x[g.l];
      E += 0.5 * g.weight / g.hinge_area * v.squaredNorm();
    }
    return E;
  }
};

}  // namespace

TEST_CASE("bending hinges: flat placements pull nothing, the forces are the energy's gradient") {
  Strip s(2, 0.4, 10, 4, 3.0, 1e3);
  const Mat3 R = Eigen::AngleAxisd(0.9, Vec3(1, -2, 0.5).normalized()).toRotationMatrix();
  std::vector<Vec3> x(s.m.particles.capacity());
  for (ParticleId q : s.p) x[q] = R * s.m.particles.position[q] + Vec3(1, 2, 3);
  for (std::size_t k : s.hinges) {
    const BendPulls f = bend_pulls(std::as_const(s.m.goals)[k], x.data());
    for (const Vec3& pull : f.f) CHECK(pull.norm() < 1e-10);  // rounding: w |K| |x| ~ 1e3 N
  }
  // A curved placement: each corner's force is minus the gradient of the
  // strip's energy (central differences, step 1e-6 m).
  for (ParticleId q : s.p) {
    const Vec3 r = s.m.particles.position[q];
    x[q] = Vec3(r.x(), r.y(), 0.3 * std::sin(r.x()) + 0.2 * r.x() * r.y());
  }
  std::vector<Vec3> F(x.size(), Vec3::Zero());
  for (std::size_t k : s.hinges) {
    const BendPulls f = bend_pulls(std::as_const(s.m.goals)[k], x.data());
    for (int a = 0; a < 4; ++a) F[f.p[a]] += f.f[a];
  }
  for (ParticleId q : {s.at(3, 2), s.at(0, 0), s.at(7, 4)}) {
    for (int axis = 0; axis < 3; ++axis) {
      const double h = 1e-6;
      std::vector<Vec3> up = x, down = x;
      up[q][axis] += h;
      down[q][axis] -= h;
      const double gradient = (s.energy(up) - s.energy(down)) / (2 * h);
      CHECK(F[q][axis] == doctest::Approx(-gradient).epsilon(1e-6).scale(1));
    }
  }
}

TEST_CASE("bending hinges: a strip bent onto a cylinder stores the plate's energy") {
  // (1/2) D / R^2 per area; the edges on the strip's two ends are no hinges,
  // so the sum covers the strip less half a quad at each end: 1 - 1/nx of
  // the plate's energy (measured 0.9493 at nx = 20, 0.9748 at 40).
  const double L = 2, W = 0.4, R = 1.5, D = 7.0;
  for (int nx : {20, 40}) {
    Strip s(L, W, nx, nx / 5, D, 1e3);
    std::vector<Vec3> x(s.m.particles.capacity());
    for (ParticleId q : s.p) {
      const Vec3 r = s.m.particles.position[q];
      x[q] = Vec3(R * std::sin(r.x() / R), r.y(), R * (1 - std::cos(r.x() / R)));
    }
    const double exact = 0.5 * D * L * W / (R * R);
    CAPTURE(nx);
    CHECK(s.energy(x) / exact == doctest::Approx(1 - 1.0 / nx).epsilon(2e-3));
  }
}

TEST_CASE("bending hinges: a simply supported plate strip, every integrator to one equilibrium, softer than the plate") {
  // Steel-like plate, t = 5 mm, nu = 0 (so the plate strip bends as a beam
  // of width W), L = 1 m, W = 0.2 m in 20 x 4 quads, q = 20 N/m^2: the
  // plate's midspan sag is 5 q L^4 / (384 D) = 0.125 mm. The hinges' strip
  // sags more, by the same factor all along it (its shape is the beam's):
  // 1.243 with the diagonals alternating, 1.047 with them all one way
  // (measured; the same by an independent dense solve of the hinges'
  // quadratic form). Near free edges the isometric model is soft, which is
  // why m:strip builds grillages (docs/lua-api.md, "Bending strips").
  const double E = 2e11, t = 0.005, D = E * t * t * t / 12, q = 20, L = 1, W = 0.2;
  const int nx = 20, ny = 4;
  const double exact = 5 * q * std::pow(L, 4) / (384 * D);
  for (Integrator integrator : every_integrator()) {
    if (integrator == Integrator::Midpoint) continue;  // converges, in 10x the steps
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Strip s(L, W, nx, ny, D, E * t * W / ny);
    for (int j = 0; j <= ny; ++j) {
      s.m.set_lock(s.at(0, j), 7);
      s.m.set_lock(s.at(nx, j), 7);
      for (int i = 1; i < nx; ++i) {
        const double tributary = (L / nx) * (W / ny) * ((j == 0 || j == ny) ? 0.5 : 1.0);
        s.m.set_load(s.at(i, j), Vec3(0, 0, -q * tributary));
      }
    }
    Solver solver(s.m);
    solver.settings.integrator = integrator;
    // 3e-6 N of 0.05 N loads: above the round-off floor of the stiff bars (k ~ 1e9 N/m, ~5e-7 N).
    const RunResult r = solver.run(RunLimits{3e-6, 0, 400000});
    CAPTURE(r.residual);
    CAPTURE(r.steps);
    CHECK(r.converged);
    CHECK(-s.m.particles.position[s.at(nx / 2, ny / 2)].z() / exact == doctest::Approx(1.2432).epsilon(1e-3));
  }
}

TEST_CASE("bending hinges: the model database keeps them") {
  Strip s(1, 0.2, 4, 2, 2.5, 1e3);
  s.m.particles.position[s.at(2, 1)] = Vec3(0.5, 0.1, 0.05);  // the weights stay those it was made with
  Model loaded;
  CHECK(test::reload(s.m, loaded, "bend.xml").find("kind=\"bend\"") != std::string::npos);
  REQUIRE(loaded.goals.size() == s.m.goals.size());
  const Goal& a = std::as_const(loaded.goals)[0];
  const Goal& b = std::as_const(s.m.goals)[0];
  CHECK(a.kind == Goal::Bend);
  CHECK(a.hinge == b.hinge);
  CHECK(a.hinge_area == b.hinge_area);
  CHECK(a.weight == 2.5);
}
