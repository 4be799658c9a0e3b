// Pin-ended strut of thesis 5.4.1.2 (Adriaenssens & Barnes 2001): L = 10 m,
// 64 segments, EI = 100 kNm^2, EA = 100 MN, buckled into an elastica by
// moving one roller towards the other. Mid-span deflection and axial load are
// compared with the exact inextensible elastica:
//   k = sin(theta0/2),  P = EI (2K(k)/L)^2,  chord = L (2E(k)/K(k) - 1),
//   delta = k L / K(k).
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

struct ElasticaResult {
  double deflection, load, exact_deflection, exact_load;
};

ElasticaResult buckle(double theta0_deg, Damping damping = Damping::Kinetic, double viscous = 0) {
  const double L = 10, EI = 1e5, EA = 1e8;
  const int n = 64;
  const double k = std::sin(theta0_deg * std::numbers::pi / 360);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  const double chord = L * (2 * E / K - 1);
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(L * i / n, 0, 0)));
  m.add_beam(ps, Section{EA, EI, 0, 0});
  // Start from a half sine wave with the right chord and roughly the right
  // arc length; the rest lengths stay those of the straight strut.
  const double amp = k * L / K;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    m.particles.position[ps[i]] = Vec3(chord * s, amp * std::sin(std::numbers::pi * s), 0);
  }
  for (ParticleId p : ps) m.set_lock(p, kLockZ);
  m.set_lock(ps.front(), kLockX | kLockY | kLockZ);
  m.set_lock(ps.back(), kLockX | kLockY | kLockZ);
  Solver solver(m);
  solver.settings.damping = damping;
  solver.settings.viscous = viscous;
  RunResult r = solver.run(1e-3, 2'000'000);
  REQUIRE(r.converged);
  REQUIRE(m.check() == "");
  ElasticaResult out;
  out.deflection = m.particles.position[ps[n / 2]].y();
  out.load = -solver.reaction(ps.back()).x();
  out.exact_deflection = k * L / K;
  out.exact_load = EI * std::pow(2 * K / L, 2);
  MESSAGE("theta0=" << theta0_deg << " steps=" << r.steps << " delta=" << out.deflection << " exact="
                    << out.exact_deflection << " P=" << out.load << " exact=" << out.exact_load);
  return out;
}

}  // namespace

TEST_CASE("elastica: mid-span deflection and axial load within 1% of the exact elastica") {
  for (double theta0 : {40.0, 80.0, 120.0}) {
    CAPTURE(theta0);
    ElasticaResult r = buckle(theta0);
    CHECK(std::abs(r.deflection / r.exact_deflection - 1) < 0.01);
    CHECK(std::abs(r.load / r.exact_load - 1) < 0.01);
  }
}

TEST_CASE("elastica with viscous damping reaches the same equilibrium") {
  ElasticaResult r = buckle(80.0, Damping::Viscous, 0.02);
  CHECK(std::abs(r.deflection / r.exact_deflection - 1) < 0.01);
  CHECK(std::abs(r.load / r.exact_load - 1) < 0.01);
}
