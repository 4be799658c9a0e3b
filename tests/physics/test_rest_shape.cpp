// Beams curved at rest (Model::set_rest_shape, m:beam{rest = "current"}):
// an arc built so stays put, a ring curved at rest under a diametral load
// against the thin-ring formula, and Bathe & Bolourchi's bend as one curved
// 6-DOF beam against Simo & Vu-Quoc.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "benchmark_models.hpp"
#include "model/model.hpp"
#include "physics/element_forces.hpp"
#include "physics/solver.hpp"
#include "query/member_forces.hpp"

using namespace tendril;

namespace {

constexpr double kPi = std::numbers::pi;

// A quarter circle of radius R in z = 0, n segments, its first particle
// held (translation), nothing else: with rest = current nothing may move.
struct Arc {
  static constexpr double R = 2;
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam;
  explicit Arc(int n, int dofs) {
    for (int i = 0; i <= n; ++i) {
      const double a = kPi / 2 * i / n;
      ps.push_back(m.add_particle(Vec3(R * std::cos(a), R * std::sin(a), 0)));
    }
    beam = m.add_beam(ps, Section{1e6, 10, 0, 0});
    if (dofs == 6) m.set_beam_formulation(beam, 6);
    m.set_lock(ps[0], dofs == 6 ? kLockTranslation | kLockRotation : kLockTranslation);
  }
  double largest_move(const std::vector<Vec3>& from) const {
    double d = 0;
    for (std::size_t k = 0; k < ps.size(); ++k) d = std::max(d, (m.particles.position[ps[k]] - from[k]).norm());
    return d;
  }
  std::vector<Vec3> positions() const {
    std::vector<Vec3> out;
    for (ParticleId p : ps) out.push_back(m.particles.position[p]);
    return out;
  }
};

}  // namespace

TEST_CASE("rest shape: an arc built with rest = current stays put; straight at rest it springs open") {
  for (int dofs : {3, 6}) {
    CAPTURE(dofs);
    Arc arc(32, dofs);
    CHECK(arc.m.rest_shape(arc.beam) == RestShape::Straight);
    arc.m.set_rest_shape(arc.beam, RestShape::Current);
    CHECK(arc.m.rest_shape(arc.beam) == RestShape::Current);
    CHECK(arc.m.check() == "");
    const std::vector<Vec3> start = arc.positions();
    Solver solver(arc.m);
    for (int k = 0; k < 2000; ++k) solver.step();
    // No initial stress: residual ~0 (against EI / R^2 = 2.5 N) and no
    // displacement beyond 1e-9 of R.
    MESSAGE("arc at rest, " << dofs << " DOF: residual " << solver.residual() << " N, largest move "
                            << arc.largest_move(start) << " m");
    CHECK(solver.residual() < 1e-9 * 2.5);
    CHECK(arc.largest_move(start) < 1e-9 * Arc::R);
    // Straight at rest again, the arc is bending-active: it springs open.
    arc.m.set_rest_shape(arc.beam, RestShape::Straight);
    CHECK(arc.m.check() == "");
    for (int k = 0; k < 200; ++k) solver.step();
    CHECK(arc.largest_move(start) > 1e-3 * Arc::R);
  }
}

TEST_CASE("rest shape: a 3-DOF arc built with rest = current has exactly no moment, as forces and reports measure it") {
  // The rest curvature, the hinge's force and the member report all measure
  // eq. 3.41 with model/hinge_curvature.hpp on the same positions, so their
  // difference is exactly 0, not a rounding error.
  Arc arc(32, 3);
  arc.m.set_rest_shape(arc.beam, RestShape::Current);
  const Vec3* x = arc.m.particles.position.raw().data();
  int hinges = 0;
  for (const Hinge& h : arc.m.hinges.items) {
    CHECK(h.rest_curvature == doctest::Approx(1 / Arc::R).epsilon(1e-3));
    const HingeForces f = hinge_forces(h, x);
    CHECK(f.fi == Vec3::Zero());
    CHECK(f.fk == Vec3::Zero());
    ++hinges;
  }
  CHECK(hinges == 31);
  const MemberForces report = member_forces(arc.m, arc.beam);
  CHECK(report.vertices.size() == 31);
  for (const VertexMoment& v : report.vertices) CHECK(v.moment == 0.0);
}

TEST_CASE("rest shape: a curved rest shape survives switching 3 -> 6 -> 3 DOF") {
  Arc arc(32, 3);
  arc.m.set_rest_shape(arc.beam, RestShape::Current);
  const std::vector<Vec3> start = arc.positions();
  const double kappa = arc.m.hinges[0].rest_curvature;
  CHECK(kappa == doctest::Approx(1 / Arc::R).epsilon(1e-3));  // 2 sin(a) / Lc of the polygon
  arc.m.set_beam_formulation(arc.beam, 6);
  arc.m.set_lock(arc.ps[0], kLockTranslation | kLockRotation);
  CHECK(arc.m.check() == "");
  Solver solver(arc.m);
  for (int k = 0; k < 2000; ++k) solver.step();
  // The 6-DOF beam ends are tilted by the hinges' rest turning angle,
  // 2 asin(kappa l / 2): the same polygon, unstressed (to rounding).
  MESSAGE("arc 3 -> 6 DOF: residual " << solver.residual() << ", largest move " << arc.largest_move(start));
  CHECK(arc.largest_move(start) < 1e-9 * Arc::R);
  arc.m.set_beam_formulation(arc.beam, 3);
  CHECK(arc.m.check() == "");
  for (std::size_t h = 0; h < arc.m.hinges.size(); ++h)
    CHECK(arc.m.hinges[h].rest_curvature == doctest::Approx(kappa).epsilon(1e-9));
}

TEST_CASE("rest shape: rule 13 on a curved beam gives the new vertex its neighbours' rest curvature") {
  Arc arc(8, 3);
  arc.m.set_rest_shape(arc.beam, RestShape::Current);
  const double kappa = arc.m.hinges[0].rest_curvature;
  const ParticleId q = arc.m.insert_particle(arc.ps[3], arc.ps[4]);
  CHECK(arc.m.check() == "");
  for (std::size_t h = 0; h < arc.m.hinges.size(); ++h)
    if (arc.m.hinges[h].j == q) CHECK(arc.m.hinges[h].rest_curvature == doctest::Approx(kappa));
  // Rule 9 on a Current beam: the joint it makes is stress free as built.
  const ParticleId p = arc.m.add_particle(Vec3(-0.5, 2.2, 0));
  arc.m.extend_beam(arc.beam, arc.ps.back(), p);
  CHECK(arc.m.check() == "");
  Solver solver(arc.m);
  solver.step();
  CHECK(arc.m.particles.force[p].norm() < 1e-9);
}

TEST_CASE("rest shape: a ring curved at rest under a diametral load within 1% of the thin-ring formula") {
  // delta = P R^3 / EI (pi/4 - 2/pi) (Roark): R = 1 m, EI = 1 N m^2, P = 1 mN.
  for (int n : {64}) {
    validate::SqueezedRing ring(n);
    CHECK(ring.m.check() == "");
    Solver solver(ring.m);
    const RunResult r = solver.run(1e-9, 2'000'000);
    REQUIRE(r.converged);
    MESSAGE("squeezed ring, " << n << " segments: shortening " << ring.shortening() << " m vs "
                              << validate::SqueezedRing::exact_shortening(ring.P) << " m; error " << ring.error()
                              << "; steps " << r.steps);
    CHECK(ring.error() < 0.01);
  }
}

TEST_CASE("rest shape: Bathe & Bolourchi's bend as one curved 6-DOF beam within 0.5% of Simo & Vu-Quoc") {
  // 16 elements; 300 lb, then 600 lb from there. Simo & Vu-Quoc's tips
  // (our x, y = their y, x): (58.84, 22.33, 40.08) and (47.23, 15.79,
  // 53.37) in; the error is |tip - reference| / |reference - start|.
  validate::BentCantilever bend(16, 300);
  Solver solver(bend.m);
  REQUIRE(solver.run(1e-6, 2'000'000).converged);
  const double e300 = bend.tip_error(300);
  bend.m.set_load(bend.tip(), Vec3(0, 0, 600));
  REQUIRE(solver.run(1e-6, 2'000'000).converged);
  const double e600 = bend.tip_error(600);
  const Vec3 tip = bend.m.particles.position[bend.tip()];
  MESSAGE("45-degree bend, one beam, 16 elements: errors " << e300 << " (300 lb), " << e600 << " (600 lb); tip at 600 lb ("
                                                           << tip.x() << ", " << tip.y() << ", " << tip.z() << ")");
  CHECK(e300 < 0.005);
  CHECK(e600 < 0.005);
}
