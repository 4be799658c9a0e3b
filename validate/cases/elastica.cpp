// Pin-ended strut of thesis 5.4.1.2 (Adriaenssens & Barnes 2001): L = 10 m,
// EI = 100 kNm^2, EA = 100 MN, buckled by moving one pin towards the other
// until the end slope is theta0 = 80 degrees. Against the exact inextensible
// elastica (complete elliptic integrals K, E of k = sin(theta0 / 2)):
//   chord = L (2E/K - 1),  mid-span deflection = k L / K,  P = EI (2K / L)^2.
#include <cmath>
#include <numbers>

#include "case.hpp"
#include "model/model.hpp"

namespace tendril::validate {

namespace {

constexpr double kLength = 10, kEI = 1e5, kEA = 1e8, kTheta0Deg = 80;

Outcome run_elastica(const Setting& setting) {
  const int n = setting.segments;  // even: a particle at mid-span
  const double k = std::sin(kTheta0Deg * std::numbers::pi / 360);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  const double chord = kLength * (2 * E / K - 1);
  const double exact_deflection = k * kLength / K;
  const double exact_load = kEI * std::pow(2 * K / kLength, 2);

  // Rest lengths from the straight strut; then the pins move to the exact
  // chord and the strut starts as a half sine wave of the exact amplitude.
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(kLength * i / n, 0, 0)));
  m.add_beam(ps, Section{kEA, kEI, 0, 0});
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    m.particles.position[ps[i]] = Vec3(chord * s, exact_deflection * std::sin(std::numbers::pi * s), 0);
  }
  for (ParticleId p : ps) m.set_lock(p, kLockZ);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);

  Solver solver(m);
  solver.settings = setting.solver;
  Outcome out = relax(solver, 1e-3, 2'000'000);  // 1 mN against P = 12.8 kN
  const double deflection = m.particles.position[ps[n / 2]].y();
  const double load = -solver.reaction(ps.back()).x();
  out.error = std::max(relative_error(deflection, exact_deflection), relative_error(load, exact_load));
  return out;
}

}  // namespace

Case elastica_case() {
  Case c;
  c.name = "elastica";
  c.reference =
      "pin-ended strut, thesis 5.4.1.2, end slope 80 deg: exact elastica; "
      "max of mid-span deflection and axial load errors";
  c.resolution = "segments of the strut";
  c.formulations = {"beam-3dof"};
  c.segments = {16, 32, 64, 128};
  c.quick_segments = {16, 64};
  c.defaults.formulation = "beam-3dof";
  c.defaults.segments = 64;
  c.tolerance = 0.01;
  c.run = run_elastica;
  return c;
}

}  // namespace tendril::validate
