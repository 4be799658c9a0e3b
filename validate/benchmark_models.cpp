#include "benchmark_models.hpp"

#include <algorithm>
#include <chrono>
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

StripCantilever::StripCantilever(int n, int across) {
  const double t = 0.01, nu = 0.3;
  const StripMaterial mat{(1 / kWidth) * 12 * (1 - nu * nu) / (t * t * t), t, nu, 0};
  std::vector<std::vector<Vec3>> grid(std::size_t(across) + 1);
  for (int r = 0; r <= across; ++r)
    for (int c = 0; c <= n; ++c) grid[std::size_t(r)].push_back(Vec3(double(c) / n, kWidth * r / across, 0));
  for (const auto& row : grid) {
    ps.emplace_back();
    for (const Vec3& x : row) ps.back().push_back(m.add_particle(x));
  }
  struct Direct : StripMaker {
    Model& m;
    explicit Direct(Model& m) : m(m) {}
    BlockId beam(const StripMember& s, const std::vector<ParticleId>& p) override {
      return m.add_beam(p, Section{s.EA, s.EI, 0, s.line_mass});
    }
    BlockId bar(ParticleId a, ParticleId b, double EA) override { return m.add_elastic_bar(a, b, Section{EA, 0, 0, 0}); }
    std::size_t planarity(double w, const std::vector<ParticleId>& c) override {
      Goal g;
      g.kind = Goal::Planar;
      g.i = c[0], g.j = c[1], g.k = c[2], g.l = c[3];
      g.weight = w;
      return m.add_goal(g);
    }
  } direct(m);
  members = make_strip(ps, strip_grillage(grid, mat), direct);
  for (std::size_t r = 0; r < ps.size(); ++r) {
    m.set_lock(ps[r].front(), kLockTranslation);
    m.set_clamp(ps[r].front(), members.rows[r], Vec3::UnitX());
  }
}

double StripCantilever::share(std::size_t row) const {
  const double across = double(ps.size() - 1);
  return (row == 0 || row + 1 == ps.size()) ? 0.5 / across : 1 / across;
}

void StripCantilever::set_tip_load(const Vec3& total) {
  for (std::size_t r = 0; r < ps.size(); ++r) m.set_load(ps[r].back(), share(r) * total);
}

void StripCantilever::set_tip_moment(const Vec3& total) {
  for (std::size_t r = 0; r < ps.size(); ++r) m.set_moment(ps[r].back(), share(r) * total);
}

double StripCantilever::error(int k) const {
  double e = 0;
  for (const auto& row : ps) {
    const Vec3& x = m.particles.position[row.back()];
    e = std::max({e, std::abs((1 - x.x()) / Mattiasson::kTable[k][0] - 1), std::abs(-x.z() / Mattiasson::kTable[k][1] - 1)});
  }
  return e;
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

LimitPoint find_limit(Solver& s, const std::function<void(double)>& set, const std::function<double()>& load,
                      double dv, double tolerance, std::uint64_t max_steps, int refinements) {
  LimitPoint out;
  auto at = [&](double v) {
    set(v);
    const std::uint64_t evaluations = s.force_evaluations();
    const auto start = std::chrono::steady_clock::now();
    const RunResult r = s.run(tolerance, max_steps);
    out.wall_ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    out.steps += r.steps;
    out.force_evaluations += s.force_evaluations() - evaluations;
    ++out.relaxations;
    out.converged = out.converged && r.converged;
    return load();
  };
  // Bracket: the first fall after a rise.
  double v = 0, p_prev = at(0), p = p_prev, p_fall = 0;
  for (int k = 1;; ++k) {
    const double p_next = at(k * dv);
    if (k > 1 && p_next < p) {
      v = (k - 1) * dv;
      p_fall = p_next;
      break;
    }
    p_prev = p;
    p = p_next;
    if (k > 10000) throw std::runtime_error("find_limit: no limit point within 10000 steps of dv");
  }
  // The parabola through (v - h, p0), (v, p1), (v + h, p2): its vertex.
  double h = dv, p0 = p_prev, p1 = p, p2 = p_fall;
  for (int r = 0;; ++r) {
    const double curv = p0 - 2 * p1 + p2;
    const double shift = curv < 0 ? 0.5 * h * (p0 - p2) / curv : 0.0;
    const double vertex = v + std::clamp(shift, -h, h);
    const double peak = p1 - 0.125 * (p0 - p2) * (p0 - p2) / curv;
    if (r == refinements || !(curv < 0)) {
      out.displacement = vertex;
      out.load = curv < 0 ? peak : p1;
      return out;
    }
    v = vertex;
    h *= 0.25;
    p0 = at(v - h);
    p1 = at(v);
    p2 = at(v + h);
  }
}

LeeFrame::LeeFrame(int n, int dofs, JointKind joint) {
  if (n % 5) throw std::invalid_argument("LeeFrame: n must be a multiple of 5");
  for (int i = 0; i <= n; ++i) column.push_back(m.add_particle(Vec3(0, L * i / n, 0)));
  corner = column.back();
  girder.push_back(corner);
  for (int i = 1; i <= n; ++i) girder.push_back(m.add_particle(Vec3(L * i / n, L, 0)));
  const Section s{EA, EI, 0, 0};
  column_beam = m.add_beam(column, s);
  girder_beam = m.add_beam(girder, s);
  loaded = girder[n / 5];
  const std::uint8_t plane = dofs == 6 ? kLockZ | kLockRX | kLockRY : kLockZ;
  if (dofs == 6) {
    m.set_beam_formulation(column_beam, 6);
    m.set_beam_formulation(girder_beam, 6);
  } else {
    m.set_joint(corner, column_beam, girder_beam, joint);
  }
  for (ParticleId p : column) m.set_lock(p, plane);
  for (ParticleId p : girder) m.set_lock(p, plane);
  m.set_lock(column.front(), plane | kLockTranslation);
  m.set_lock(girder.back(), plane | kLockTranslation);
  m.set_lock(loaded, plane | kLockY);
}

void LeeFrame::set_drop(double v) { m.particles.position[loaded].y() = L - v; }

double LeeFrame::load(const Solver& s) const { return -s.reaction(loaded).y(); }

LimitPoint LeeFrame::limit(Solver& s) {
  return find_limit(s, [&](double v) { set_drop(v); }, [&] { return load(s); }, 4.0, 1e-7, 2'000'000);
}

WilliamsToggle::WilliamsToggle(int n, int dofs, JointKind joint) : dofs(dofs) {
  for (int i = 0; i <= n; ++i) left.push_back(m.add_particle(Vec3(a * i / n, h * i / n, 0)));
  apex = left.back();
  right.push_back(apex);
  for (int i = 1; i <= n; ++i) right.push_back(m.add_particle(Vec3(a + a * i / n, h * (n - i) / n, 0)));
  const Section s{EA, EI, 0, 0};
  left_beam = m.add_beam(left, s);
  right_beam = m.add_beam(right, s);
  const std::uint8_t plane = dofs == 6 ? kLockZ | kLockRX | kLockRY : kLockZ;
  for (ParticleId p : left) m.set_lock(p, plane);
  for (ParticleId p : right) m.set_lock(p, plane);
  if (dofs == 6) {
    m.set_beam_formulation(left_beam, 6);
    m.set_beam_formulation(right_beam, 6);
    m.set_lock(left.front(), kFullLock);
    m.set_lock(right.back(), kFullLock);
  } else {
    m.set_joint(apex, left_beam, right_beam, joint);
    m.set_lock(left.front(), plane | kLockTranslation);
    m.set_lock(right.back(), plane | kLockTranslation);
    m.set_clamp(left.front(), left_beam);
    m.set_clamp(right.back(), right_beam);
  }
  m.set_lock(apex, plane | kLockY);
}

// Each step from the last drop moves both members as a tent (1 at the apex,
// 0 at the supports), not the apex alone: a predictor that keeps the end
// segments' slopes from jumping through the straight line (at 20 segments a
// 0.02 in jump of the apex alone flips them, and a 3-DOF joint cannot tell
// the mirror image of its kink from the kink). 6 DOF: the apex alone (the
// node frames would not follow the tent).
void WilliamsToggle::set_drop(double v) {
  const double step = v - (h - m.particles.position[apex].y());
  for (std::size_t k = 1; dofs == 3 && k + 1 < left.size(); ++k) {
    const double shape = double(k) / double(left.size() - 1);
    m.particles.position[left[k]].y() -= step * shape;
    m.particles.position[right[right.size() - 1 - k]].y() -= step * shape;
  }
  m.particles.position[apex].y() = h - v;
}

double WilliamsToggle::load(const Solver& s) const { return -s.reaction(apex).y(); }

LimitPoint WilliamsToggle::limit(Solver& s) {
  return find_limit(s, [&](double v) { set_drop(v); }, [&] { return load(s); }, 0.02, 1e-7, 2'000'000);
}

}  // namespace tendril::validate
