#include "benchmark_models.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace tendril::validate {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::uint8_t kFullLock = kLockTranslation | kLockRotation;

}  // namespace

Elastica::Elastica(double theta0_deg, int n, int dofs) {
  const double L = 10, EI = 1e5, EA = 1e8;
  const double k = std::sin(theta0_deg * kPi / 360);
  const double K = std::comp_ellint_1(k), E = std::comp_ellint_2(k);
  const double chord = L * (2 * E / K - 1);
  exact_deflection = k * L / K;
  exact_load = EI * std::pow(2 * K / L, 2);
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(L * i / n, 0, 0)));
  beam = m.add_beam(ps, Section{EA, EI, 0, 0});
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    m.particles.position[ps[i]] = Vec3(chord * s, exact_deflection * std::sin(kPi * s), 0);
  }
  for (ParticleId p : ps) m.set_lock(p, kLockZ);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  if (dofs == 6) m.set_beam_formulation(beam, 6);
}

double Elastica::deflection_error() const {
  return std::abs(std::abs(m.particles.position[ps[ps.size() / 2]].y()) / exact_deflection - 1);
}

double Elastica::load_error(const Solver& s) const { return std::abs(-s.reaction(ps.back()).x() / exact_load - 1); }

HangingChain::HangingChain(int n) {
  m.gravity = Vec3(0, 0, -g);
  for (int i = 0; i <= n; ++i) {
    const double s = double(i) / n;
    ps.push_back(m.add_particle(Vec3(span * s, 0, -2 * s * (1 - s))));
  }
  for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{EA, 0, 0, rho}, length / n);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
}

double HangingChain::sag() const { return -m.particles.position[ps[ps.size() / 2]].z(); }

double HangingChain::exact_sag() {
  const double W = rho * g * length;
  auto span_of = [&](double H) { return 2 * H * length / W * std::asinh(W / (2 * H)) + H * length / EA; };
  double lo = 1e-6 * W, hi = 1e6 * W;  // the span grows with H
  for (int i = 0; i < 300; ++i) {
    const double H = std::sqrt(lo * hi);
    (span_of(H) < span ? lo : hi) = H;
  }
  const double H = std::sqrt(lo * hi);
  return H * length / W * (std::sqrt(1 + std::pow(W / (2 * H), 2)) - 1) + W * length / (8 * EA);
}

double HangingChain::sag_error() const { return std::abs(sag() / exact_sag() - 1); }

Cantilever::Cantilever(int n, double L, const Section& s) {
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(L * i / n, 0, 0)));
  beam = m.add_beam(ps, s);
  m.set_lock(ps.front(), kFullLock);
  m.set_beam_formulation(beam, 6);
}

Cantilever3::Cantilever3(int n, double L, const Section& s) {
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(L * i / n, 0, 0)));
  beam = m.add_beam(ps, s);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_clamp(ps.front(), beam, Vec3::UnitX());
}

Mattiasson::Mattiasson(int n, int dofs) {
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(double(i) / n, 0, 0)));
  beam = m.add_beam(ps, Section{1e5, 1, 0, 0});
  for (ParticleId p : ps) m.set_lock(p, kLockZ);
  if (dofs == 6) {
    m.set_beam_formulation(beam, 6);
    m.set_lock(ps.front(), kFullLock);
  } else {
    m.set_lock(ps.front(), kLockTranslation);
    m.set_clamp(ps.front(), beam, Vec3::UnitX());
  }
}

void Mattiasson::set_load(double PL2_EI) { m.set_load(ps.back(), Vec3(0, -PL2_EI, 0)); }
double Mattiasson::u() const { return 1 - m.particles.position[ps.back()].x(); }
double Mattiasson::w() const { return -m.particles.position[ps.back()].y(); }

double Mattiasson::error(int k) const {
  return std::max(std::abs(u() / kTable[k][0] - 1), std::abs(w() / kTable[k][1] - 1));
}

BentCantilever::BentCantilever(int n, double load) {
  const double R = 100;
  for (int i = 0; i <= n; ++i) {
    const double a = kPi / 4 * i / n;
    ps.push_back(m.add_particle(Vec3(R * std::sin(a), R * (1 - std::cos(a)), 0)));
  }
  Section s{1e7, 1e7 / 12, 0, 0};
  s.GJ = 0.5e7 / 6;
  beam = m.add_beam(ps, s);
  m.set_lock(ps.front(), kFullLock);
  m.set_beam_formulation(beam, 6);
  m.set_rest_shape(beam, RestShape::Current);
  start = m.particles.position[tip()];
  m.set_load(tip(), Vec3(0, 0, load));
}

Vec3 BentCantilever::tip_reference(double load) {
  if (load == 300) return Vec3(58.84, 22.33, 40.08);
  if (load == 600) return Vec3(47.23, 15.79, 53.37);
  throw std::logic_error("BentCantilever: Simo & Vu-Quoc's tip is known under 300 and 600 lb only");
}

double BentCantilever::tip_error(double load) const {
  const Vec3 ref = tip_reference(load);
  return (m.particles.position[tip()] - ref).norm() / (ref - start).norm();
}

SqueezedRing::SqueezedRing(int n, double load) : P(load) {
  if (n < 8 || n % 4) throw std::logic_error("SqueezedRing: n must be a multiple of 4, at least 8");
  for (int i = 0; i < n; ++i) {
    const double a = 2 * kPi * i / n;  // node 0 on +x, n/4 at the top
    ps.push_back(m.add_particle(Vec3(R * std::cos(a), R * std::sin(a), 0)));
  }
  beam = m.add_beam(ps, Section{EA, EI, 0, 0}, true);
  m.set_rest_shape(beam, RestShape::Current);
  top = ps[n / 4];
  bottom = ps[3 * n / 4];
  for (ParticleId p : ps) m.set_lock(p, kLockZ);
  m.set_lock(top, kLockZ | kLockX);
  m.set_lock(bottom, kLockZ | kLockX);
  m.set_lock(ps[0], kLockZ | kLockY);
  m.set_lock(ps[n / 2], kLockZ | kLockY);
  m.set_load(top, Vec3(0, -P, 0));
  m.set_load(bottom, Vec3(0, P, 0));
}

double SqueezedRing::shortening() const {
  return 2 * R - (m.particles.position[top] - m.particles.position[bottom]).norm();
}

double SqueezedRing::error() const { return std::abs(shortening() / exact_shortening(P) - 1); }

double BentCantilever::error() const {
  const Vec3 u = displacement();
  double e = 0;
  for (int k = 0; k < 3; ++k) e = std::max(e, std::abs(u[k] / kReference[k] - 1));
  return e;
}

PrestressedRing::PrestressedRing(int n, int dofs) {
  const double radius = 5, load = 1e4;
  const int quadrant[4] = {n, 2 * n, 4 * n, 8 * n};
  for (int q = 0; q < 4; ++q) {
    node[q] = ParticleId(ps.size());  // an index into ps for now
    for (int i = 0; i < quadrant[q]; ++i) {
      const double a = kPi / 2 * (q + double(i) / quadrant[q]);
      ps.push_back(m.add_particle(Vec3(radius * std::cos(a), radius * std::sin(a), 0)));
    }
  }
  for (ParticleId& p : node) p = ps[p];
  beam = m.add_beam(ps, Section{1e8, 1e5, 0, 0}, true);  // rest lengths: the chords, straight joints
  if (dofs == 6) m.set_beam_formulation(beam, 6);
  m.set_load(node[0], Vec3(0, 0, -load));
  m.set_load(node[2], Vec3(0, 0, -load));
  m.set_lock(node[1], kLockZ | kLockX | (dofs == 6 ? kLockRX : 0));
  m.set_lock(node[3], kLockZ | kLockX);
  m.set_lock(node[0], kLockY);
}

double PrestressedRing::drop(int node_number) const { return -m.particles.position[node[node_number - 1]].z(); }

double PrestressedRing::error() const {
  return std::max(std::abs(drop(1) / kReference - 1), std::abs(drop(3) / kReference - 1));
}

}  // namespace tendril::validate
