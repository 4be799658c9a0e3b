// A prestressed two-bar truss hanging as a shallow V: supports at x = -+a,
// apex a rise h below them, bars of axial stiffness EA prestressed to T0 in
// their initial (rest) length L0 = sqrt(a^2 + h^2), a vertical load P at the
// apex. It drops by w until
//   2 N(w) (h + w) / L(w) = P,  L(w) = sqrt(a^2 + (h + w)^2),
//   N(w) = T0 + EA (L(w) - L0) / L0   (the bar law of eq. 3.32),
// whose left side grows with w (N and the slope both do): one root, found by
// bisection. Large displacement: w is well over h here. Each bar may be split
// into collinear segments; straight arms are exact at any split, so what more
// segments change is the work of finding them (their sideways stiffness is
// only the tension's, N / segment length).
#include <cmath>

#include "case.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

constexpr double kHalfSpan = 5, kRise = 0.5, kEA = 1e6, kPrestress = 1e4, kLoad = 2e4;

struct Exact {
  double drop, bar_force;
};

Exact exact() {
  const double L0 = std::hypot(kHalfSpan, kRise);
  auto force = [&](double w) { return kPrestress + kEA * (std::hypot(kHalfSpan, kRise + w) - L0) / L0; };
  auto carried = [&](double w) { return 2 * force(w) * (kRise + w) / std::hypot(kHalfSpan, kRise + w); };
  double lo = 0, hi = 10 * kHalfSpan;  // carried(0) = 2 T0 h / L0 < P < carried(10 a)
  for (int i = 0; i < 200; ++i) {
    const double w = 0.5 * (lo + hi);
    (carried(w) < kLoad ? lo : hi) = w;
  }
  const double w = 0.5 * (lo + hi);
  return {w, force(w)};
}

Outcome run_truss(const Setting& setting) {
  const int n = setting.segments;  // over both bars: n / 2 each
  const int half = n / 2;
  const double L0 = std::hypot(kHalfSpan, kRise);
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;  // 0 .. 1 along the V
    const double x = -kHalfSpan + 2 * kHalfSpan * s;
    ps.push_back(m.add_particle(Vec3(x, 0, -kRise * (1 - std::abs(x) / kHalfSpan))));
  }
  for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{kEA, 0, kPrestress, 0}, L0 / half);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  m.set_load(ps[half], Vec3(0, 0, -kLoad));

  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-3, 2'000'000);  // 1 mN against P = 20 kN
  const Exact e = exact();
  const double drop = -m.particles.position[ps[half]].z() - kRise;
  const double bar_force = solver.reaction(ps.front()).norm();
  out.error = std::max(relative_error(drop, e.drop), relative_error(bar_force, e.bar_force));
  return out;
}

}  // namespace

Case two_bar_truss_case() {
  Case c;
  c.name = "two_bar_truss";
  c.reference =
      "prestressed two-bar truss (V, 10 m span, 0.5 m rise, apex load 20 kN): exact large-displacement "
      "equilibrium; max of apex drop and bar force errors";
  c.resolution = "segments over both bars";
  c.formulations = {"cable"};
  c.segments = {2, 8, 32, 128};
  c.quick_segments = {2, 32};
  c.defaults.formulation = "cable";
  c.defaults.segments = 2;
  c.tolerance = 0.005;
  c.run = run_truss;
  return c;
}

}  // namespace tendril::validate
