#pragma once
// Reference models with exact answers, shared by the tests of the
// constraint-based solvers: the pin-ended elastica of thesis 5.4.1.2 (3 or 6
// DOF) and the hanging chain against the elastic catenary (Irvine 1981).
#include <cmath>
#include <numbers>
#include <vector>

#include "model/model.hpp"
#include "physics/solver.hpp"

namespace tendril::reference {

// L = 10 m, EI = 100 kNm^2, EA = 100 MN, buckled until the end slope is
// theta0: k = sin(theta0/2), chord = L (2E/K - 1), deflection = k L / K,
// P = EI (2K / L)^2. Started from a half sine wave of the exact amplitude.
struct Strut {
  Model m;
  std::vector<ParticleId> ps;
  BlockId beam = 0;
  double exact_deflection = 0, exact_load = 0;

  explicit Strut(double theta0_deg = 80, int n = 64, int dofs = 3) {
    const double L = 10, EI = 1e5, EA = 1e8;
    const double k = std::sin(theta0_deg * std::numbers::pi / 360);
    const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
    const double chord = L * (2 * E / K - 1);
    for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(L * i / n, 0, 0)));
    beam = m.add_beam(ps, Section{EA, EI, 0, 0});
    exact_deflection = k * L / K;
    exact_load = EI * std::pow(2 * K / L, 2);
    for (int i = 0; i <= n; ++i) {
      const double s = double(i) / n;
      m.particles.position[ps[i]] = Vec3(chord * s, exact_deflection * std::sin(std::numbers::pi * s), 0);
    }
    for (ParticleId p : ps) m.set_lock(p, kLockZ);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
    if (dofs == 6) m.set_beam_formulation(beam, 6);
  }
  double deflection_error() const {
    return std::abs(m.particles.position[ps[ps.size() / 2]].y() / exact_deflection - 1);
  }
  double load_error(const Solver& s) const { return std::abs(-s.reaction(ps.back()).x() / exact_load - 1); }
};

// 10 m span, 12 m unstretched, 2 kg/m, EA = 100 kN, n cables.
struct Chain {
  static constexpr double span = 10, length = 12, rho = 2.0, EA = 1e5;
  Model m;
  std::vector<ParticleId> ps;
  explicit Chain(int n = 80) {
    m.gravity = Vec3(0, 0, -9.81);
    for (int i = 0; i <= n; ++i) {
      const double s = double(i) / n;
      ps.push_back(m.add_particle(Vec3(span * s, 0, -2 * s * (1 - s))));
    }
    for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{EA, 0, 0, rho}, length / n);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
  }
  double sag() const { return -m.particles.position[ps[ps.size() / 2]].z(); }
  static double exact_sag() {
    const double W = rho * 9.81 * length;
    auto span_of = [&](double H) { return 2 * H * length / W * std::asinh(W / (2 * H)) + H * length / EA; };
    double lo = 1e-6 * W, hi = 1e6 * W;  // the span grows with H
    for (int i = 0; i < 300; ++i) {
      const double H = std::sqrt(lo * hi);
      (span_of(H) < span ? lo : hi) = H;
    }
    const double H = std::sqrt(lo * hi);
    return H * length / W * (std::sqrt(1 + std::pow(W / (2 * H), 2)) - 1) + W * length / (8 * EA);
  }
  double sag_error() const { return std::abs(sag() / exact_sag() - 1); }
};

}  // namespace tendril::reference
