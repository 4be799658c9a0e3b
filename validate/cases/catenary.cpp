// A chain of cables hanging under its own weight (10 m span, 12 m unstretched,
// 2 kg/m, EA = 100 kN) against the elastic catenary (Irvine 1981). For a
// symmetric span s, unstretched length L0, weight W and horizontal tension H:
//   s   = (2 H L0 / W) asinh(W / 2H) + H L0 / EA
//   sag = (H L0 / W) (sqrt(1 + (W / 2H)^2) - 1) + W L0 / (8 EA)
// H from the first by bisection, then the mid-span sag from the second.
#include <cmath>

#include "case.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

constexpr double kSpan = 10, kLength = 12, kLineMass = 2, kEA = 1e5, kG = 9.81;

double exact_sag() {
  const double W = kLineMass * kG * kLength;
  auto span_of = [&](double H) { return 2 * H * kLength / W * std::asinh(W / (2 * H)) + H * kLength / kEA; };
  double lo = 1e-6 * W, hi = 1e6 * W;  // the span grows with H
  for (int i = 0; i < 300; ++i) {
    const double H = std::sqrt(lo * hi);
    (span_of(H) < kSpan ? lo : hi) = H;
  }
  const double H = std::sqrt(lo * hi);
  return H * kLength / W * (std::sqrt(1 + std::pow(W / (2 * H), 2)) - 1) + W * kLength / (8 * kEA);
}

Outcome run_catenary(const Setting& setting) {
  const int n = setting.segments;  // even: a particle at mid-span
  Model m;
  m.gravity = Vec3(0, 0, -kG);
  std::vector<ParticleId> ps;
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    ps.push_back(m.add_particle(Vec3(kSpan * s, 0, -2 * s * (1 - s))));  // a shallow parabola to start
  }
  for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{kEA, 0, 0, kLineMass}, kLength / n);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);

  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-6, 2'000'000);  // 1 uN against 235 N of weight
  out.error = relative_error(-m.particles.position[ps[n / 2]].z(), exact_sag());
  return out;
}

}  // namespace

Case catenary_case() {
  Case c;
  c.name = "catenary";
  c.reference = "hanging chain, 12 m over a 10 m span: elastic catenary (Irvine), mid-span sag";
  c.resolution = "cables of the chain";
  c.formulations = {"cable"};
  c.segments = {20, 40, 80, 160};
  c.quick_segments = {20, 80};
  c.defaults.formulation = "cable";
  c.defaults.segments = 80;
  c.tolerance = 0.005;
  c.run = run_catenary;
  return c;
}

}  // namespace tendril::validate
