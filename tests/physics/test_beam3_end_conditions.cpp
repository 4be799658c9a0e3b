// 3-DOF beams (spline beams, eq. 3.41-3.43) under an end moment, applied as
// a force couple across the end segment (physics/couples.cpp), and clamped
// by a clamp hinge against a fixed tangent (Model::set_clamp): the exact
// circle and Mattiasson's cantilever.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "benchmark_models.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

constexpr double kPi = std::numbers::pi;

// The radius of the circle through three points.
double circumradius(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double A = (b - c).norm(), B = (c - a).norm(), C = (a - b).norm();
  return A * B * C / (2 * (b - a).cross(c - a).norm());
}

}  // namespace

TEST_CASE("3-DOF beam: an end moment rolls a clamped cantilever into the exact circle (curvature M / EI)") {
  // L = 1 m, EI = 1 N m^2, EA = 1e5 N, 40 segments, M = pi EI / L: a half
  // circle of radius R = EI / M = L / pi, the tip at (0, 2R) above the root
  // with the root's tangent along x.
  validate::Cantilever3 c(40, 1.0, Section{1e5, 1, 0, 0});
  const double M = kPi, R = 1 / M;
  c.m.set_moment(c.tip(), Vec3(0, 0, M));
  Solver solver(c.m);
  const RunResult r = solver.run(1e-9, 2'000'000);
  REQUIRE(r.converged);
  CHECK(c.m.check() == "");
  const Vec3 tip = c.m.particles.position[c.tip()], root = c.m.particles.position[c.ps.front()];
  const double radius = circumradius(root, c.m.particles.position[c.ps[20]], tip);
  MESSAGE("3-DOF end moment, 40 segments: radius " << radius << " vs " << R << ", tip (" << tip.x() << ", " << tip.y()
                                                    << ") vs (0, " << 2 * R << "); steps " << r.steps);
  CHECK(std::abs(radius / R - 1) < 0.01);
  CHECK((tip - Vec3(0, 2 * R, 0)).norm() < 0.01 * 2 * R);
  // Without the moment's couple the beam would not move at all (the bug
  // this replaces: a moment on a 3-DOF particle was accepted and ignored).
  CHECK(tip.y() > R);
}

TEST_CASE("3-DOF beam: Mattiasson's cantilever with a clamped root within 0.5% at 20 segments") {
  // Elastica of a cantilever under a tip load P normal to its axis
  // (Mattiasson 1981, Table 1; reproduced by shooting on theta'' = -(P/EI)
  // cos(theta), theta(0) = 0, theta'(L) = 0): horizontal and vertical tip
  // displacements u/L, w/L for PL^2/EI = 1 ... 10.
  for (int dofs : {3, 6}) {
    CAPTURE(dofs);
    validate::Mattiasson c(20, dofs);
    Solver solver(c.m);
    for (int k = 0; k < 10; ++k) {
      const double load = k + 1;
      c.set_load(load);
      REQUIRE(solver.run(1e-8, 2'000'000).converged);
      const double eu = std::abs(c.u() / validate::Mattiasson::kTable[k][0] - 1);
      const double ew = std::abs(c.w() / validate::Mattiasson::kTable[k][1] - 1);
      MESSAGE("Mattiasson " << dofs << " DOF, PL^2/EI = " << load << ": u/L " << c.u() << " (" << eu << "), w/L "
                            << c.w() << " (" << ew << ")");
      CHECK(eu < 0.005);
      CHECK(ew < 0.005);
    }
    CHECK(c.m.check() == "");
  }
}

TEST_CASE("3-DOF beam: a clamp is a moment only, and refused where it cannot act") {
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= 4; ++i) ps.push_back(m.add_particle(Vec3(i, 0, 0)));
  const BlockId b = m.add_beam(ps, Section{1e4, 1, 0, 0});
  CHECK_THROWS_WITH_AS(m.set_clamp(ps[2], b), doctest::Contains("not an end of beam"), ModelError);
  m.set_clamp(ps[0], b, Vec3(0, 2, 0));  // at 90 degrees: a couple on the first segment, nothing else
  Vec3 t;
  CHECK(m.clamped(ps[0], b, &t));
  CHECK(t.isApprox(Vec3(0, 1, 0)));
  Solver solver(m);
  solver.step();
  Vec3 sum = Vec3::Zero();
  for (ParticleId p : ps) sum += m.particles.force[p];
  CHECK(sum.norm() < 1e-12);
  CHECK(m.particles.force[ps[1]].y() > 0);  // q pulled towards the clamp's tangent
  m.set_beam_formulation(b, 6);
  CHECK_THROWS_WITH_AS(m.set_clamp(ps[4], b), doctest::Contains("has 6 DOF"), ModelError);
  CHECK(m.check() == "");
}
