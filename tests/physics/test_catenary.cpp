// A hanging chain of cables under its own weight against the elastic
// catenary (Irvine 1981). For a symmetric span s, unstretched length L0,
// total weight W and horizontal tension H:
//   s   = (2 H L0 / W) asinh(W / 2H) + H L0 / EA
//   sag = (H L0 / W) (sqrt(1 + (W / 2H)^2) - 1) + W L0 / (8 EA)
#include <doctest/doctest.h>

#include <cmath>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {
double elastic_catenary_sag(double span, double L0, double W, double EA) {
  auto span_of = [&](double H) { return 2 * H * L0 / W * std::asinh(W / (2 * H)) + H * L0 / EA; };
  double lo = 1e-6 * W, hi = 1e6 * W;  // span grows with H
  for (int i = 0; i < 300; ++i) {
    double H = std::sqrt(lo * hi);
    (span_of(H) < span ? lo : hi) = H;
  }
  const double H = std::sqrt(lo * hi);
  return H * L0 / W * (std::sqrt(1 + std::pow(W / (2 * H), 2)) - 1) + W * L0 / (8 * EA);
}

struct Chain {
  static constexpr double span = 10, length = 12, rho = 2.0, EA = 1e5;
  static constexpr int n = 80;
  Model m;
  std::vector<ParticleId> ps;
  Chain() {
    m.gravity = Vec3(0, 0, -9.81);
    for (int i = 0; i <= n; ++i) {
      double s = double(i) / n;
      ps.push_back(m.add_particle(Vec3(span * s, 0, -2 * s * (1 - s))));
    }
    for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{EA, 0, 0, rho}, length / n);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
  }
  double sag() const { return -m.particles.position[ps[n / 2]].z(); }
  static double exact() { return elastic_catenary_sag(span, length, rho * 9.81 * length, EA); }
  static double weight() { return rho * length * 9.81; }
};

void check_catenary(Integrator integrator) {
  Chain c;
  CHECK(c.m.state(c.ps[1]) == State::Shared);
  Solver solver(c.m);
  solver.settings.integrator = integrator;
  RunResult r = solver.run(1e-6, 1'000'000);
  REQUIRE(r.converged);
  REQUIRE(c.m.check() == "");
  MESSAGE(std::string(integrator_name(integrator)) << ": steps=" << r.steps << " force evaluations=" << solver.force_evaluations()
                                      << " sag=" << c.sag() << " exact=" << Chain::exact());
  CHECK(std::abs(c.sag() / Chain::exact() - 1) < 0.005);
  // The supports carry the whole weight.
  CHECK((solver.reaction(c.ps.front()) + solver.reaction(c.ps.back())).z() ==
        doctest::Approx(Chain::weight()).epsilon(1e-6));
}

}  // namespace

TEST_CASE("catenary: sag of a hanging cable chain within 0.5%") { check_catenary(Integrator::Leapfrog); }

TEST_CASE("catenary with RK4: sag within 0.5%") { check_catenary(Integrator::RK4); }
