// The time integrators as true dynamics (physical masses, no damping) and
// their contracts: order of accuracy, locks, reactions, non-finite stages,
// mass modes, names, and no allocation in a step.
#include <doctest/doctest.h>

#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <numbers>
#include <sstream>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

// Counts heap allocations while `g_counting` is set (for the whole binary).
namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};
}  // namespace

// The whole family of replaceable operators, so that every new and delete
// pair goes through malloc and free (a partial replacement mixes its own
// blocks with the runtime's: AddressSanitizer reports a mismatch).
namespace {
void* counted_allocation(std::size_t size, std::size_t alignment) noexcept {
  if (g_counting) ++g_allocations;
  size = size ? size : 1;
  if (alignment <= alignof(std::max_align_t)) return std::malloc(size);
  return std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment);
}
void* counted_or_throw(std::size_t size, std::size_t alignment) {
  if (void* p = counted_allocation(size, alignment)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return counted_or_throw(n, 0); }
void* operator new[](std::size_t n) { return counted_or_throw(n, 0); }
void* operator new(std::size_t n, std::align_val_t a) { return counted_or_throw(n, std::size_t(a)); }
void* operator new[](std::size_t n, std::align_val_t a) { return counted_or_throw(n, std::size_t(a)); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept { return counted_allocation(n, 0); }
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept { return counted_allocation(n, 0); }
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_allocation(n, std::size_t(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_allocation(n, std::size_t(a));
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }

namespace {

// A point mass m on a linear spring: one bar of stiffness EA/L0 (a two-particle
// beam, which has no hinge and resists compression) from a locked particle, along x (the motion stays on the bar's line, so the force is
// exactly linear). x(t) = L0 + A cos(omega t), omega = sqrt(EA / (m L0)).
struct Spring {
  static constexpr double EA = 1e4, L0 = 1, mass = 2, A = 0.01;
  Model m;
  ParticleId anchor, bob;
  Spring() {
    anchor = m.add_particle(Vec3(0, 0, 0));
    bob = m.add_particle(Vec3(L0, 0, 0));
    m.add_beam({anchor, bob}, Section{EA, 1, 0, 0});  // one bar, no hinge; cables go slack
    m.particles.position[bob] = Vec3(L0 + A, 0, 0);
    m.set_lock(anchor, kLockTranslation);
    m.set_point_mass(bob, mass);
  }
  static double omega() { return std::sqrt(EA / (mass * L0)); }
  static double period() { return 2 * std::numbers::pi / omega(); }
};

struct Errors {
  double max_position = 0;  // max over the steps of |x_n - x(t_n)| on [0, T]
  double end_position = 0;  // |x_N - x(T)|
};

Errors oscillate(Integrator integrator, int steps_per_period) {
  Spring s;
  Solver solver(s.m);
  solver.settings.integrator = integrator;
  solver.settings.mass_mode = MassMode::Physical;
  solver.settings.damping = Damping::None;
  solver.settings.dt = Spring::period() / steps_per_period;
  Errors e;
  for (int n = 1; n <= steps_per_period; ++n) {
    solver.step();
    const double t = n * solver.settings.dt;
    const double exact = Spring::L0 + Spring::A * std::cos(Spring::omega() * t);
    const double err = std::abs(s.m.particles.position[s.bob].x() - exact);
    e.max_position = std::max(e.max_position, err);
    if (n == steps_per_period) e.end_position = err;
  }
  CHECK(s.m.particles.position[s.anchor] == Vec3(0, 0, 0));
  CHECK(s.m.particles.position[s.bob].y() == 0);
  return e;
}

int expected_order(Integrator i) {
  switch (i) {
    case Integrator::SymplecticEuler: return 1;
    case Integrator::RK4: return 4;
    default: return 2;
  }
}

}  // namespace

TEST_CASE("integrators: observed order of accuracy on a mass-spring oscillator") {
  // dt = T/50, T/100, T/200 over one period T; order = log2 of the ratio of
  // successive errors, within 0.3 of the method's order. The error measured
  // is the largest position error over the period (the global error). At
  // t = T exactly the leading error terms vanish (they go with sin(omega t)),
  // so the end-of-period error, reported too, shows one or two orders more
  // than the method has (Symplectic Euler's looks third order).
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    const Errors e50 = oscillate(integrator, 50), e100 = oscillate(integrator, 100), e200 = oscillate(integrator, 200);
    const double p1 = std::log2(e50.max_position / e100.max_position);
    const double p2 = std::log2(e100.max_position / e200.max_position);
    const double q2 = std::log2(e100.end_position / e200.end_position);
    std::ostringstream msg;
    msg << integrator_name(integrator) << ": max position error " << e50.max_position << ", " << e100.max_position
        << ", " << e200.max_position << " m at T/50, T/100, T/200 -> order " << p1 << ", " << p2
        << " (end-of-period error order " << q2 << ")";
    MESSAGE(msg.str());
    CHECK(std::abs(p1 - expected_order(integrator)) < 0.3);
    CHECK(std::abs(p2 - expected_order(integrator)) < 0.3);
  }
}

TEST_CASE("integrators: names round-trip and unknown names are refused") {
  for (Integrator i : kIntegrators) {
    CHECK(parse_integrator(integrator_name(i)) == i);
    CHECK(force_evaluations_per_step(i) >= 1);
    CHECK(fictitious_mass_scale(i) >= 1);
  }
  CHECK(!parse_integrator("euler").has_value());
  CHECK(!parse_integrator("RK4").has_value());
  CHECK(parse_mass_mode("physical") == MassMode::Physical);
  CHECK(parse_mass_mode(mass_mode_name(MassMode::Fictitious)) == MassMode::Fictitious);
  CHECK(!parse_mass_mode("real").has_value());
  const SolverSettings defaults;
  CHECK(defaults.integrator == Integrator::Auto);
  CHECK(defaults.mass_mode == MassMode::Fictitious);
}

TEST_CASE("integrators: a loaded bar stretches by F L / EA, supports react, locked axes stay") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(2, 0, 0));
    m.add_cable(a, b, Section{1e6, 0, 0, 0});
    m.set_lock(a, kLockTranslation);
    m.set_lock(b, kLockY | kLockZ);
    m.set_load(b, Vec3(500, 300, -200));  // the locked axes take the rest
    Solver s(m);
    s.settings.integrator = integrator;
    RunResult r = s.run(1e-8, 100000);
    REQUIRE(r.converged);
    CHECK(s.force_evaluations() == r.steps * force_evaluations_per_step(integrator));
    CHECK(m.particles.position[a] == Vec3(0, 0, 0));
    CHECK(m.particles.position[b].y() == 0);
    CHECK(m.particles.position[b].z() == 0);
    CHECK(m.particles.position[b].x() == doctest::Approx(2 + 500 * 2 / 1e6).epsilon(1e-12));
    CHECK(s.reaction(a).x() == doctest::Approx(-500).epsilon(1e-9));
    CHECK(s.reaction(b).x() == 0);
    CHECK(s.reaction(b).y() == doctest::Approx(-300).epsilon(1e-9));
    CHECK(s.reaction(b).z() == doctest::Approx(200).epsilon(1e-9));
  }
}

TEST_CASE("integrators: a lock set on a moving particle stops it along the locked axis") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    std::vector<ParticleId> ps;
    for (int i = 0; i <= 4; ++i) ps.push_back(m.add_particle(Vec3(i, 0, 0)));
    m.add_beam(ps, Section{1e7, 1e3, 0, 0});
    m.set_lock(ps[0], kLockTranslation);
    m.set_lock(ps[4], kLockTranslation);
    m.set_load(ps[2], Vec3(0, 0, -100));
    Solver s(m);
    s.settings.integrator = integrator;
    s.settings.damping = Damping::None;
    for (int i = 0; i < 20; ++i) s.step();
    REQUIRE(m.particles.velocity[ps[2]].z() != 0);
    const double z = m.particles.position[ps[2]].z();
    m.set_lock(ps[2], kLockZ);
    for (int i = 0; i < 20; ++i) s.step();
    CHECK(m.particles.position[ps[2]].z() == z);
  }
}

TEST_CASE("integrators: a non-finite stage stops the step with nothing moved") {
  // Finite at the step's start, but the first stage (at x + dt v or
  // x + dt/2 v) is so far away that the bar's force overflows.
  for (Integrator integrator : {Integrator::VelocityVerlet, Integrator::Midpoint, Integrator::RK4}) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)), c = m.add_particle(Vec3(2, 0, 0));
    m.add_beam({a, b, c}, Section{1e6, 10, 0, 0});
    m.set_lock(a, kLockTranslation);
    Solver s(m);
    s.settings.integrator = integrator;
    s.step();
    m.particles.velocity[c] = Vec3(0, 1e300, 0);
    const auto positions = m.particles.position.raw();
    const auto velocities = m.particles.velocity.raw();
    const std::uint64_t steps = s.steps();
    try {
      s.step();
      FAIL("expected a NumericalError");
    } catch (const NumericalError& e) {
      CHECK(std::string(e.what()).find("stage") != std::string::npos);
    }
    CHECK(m.particles.position.raw() == positions);
    CHECK(m.particles.velocity.raw() == velocities);
    CHECK(s.steps() == steps);
    CHECK(m.check() == "");
  }
}

TEST_CASE("physical masses: a free particle without mass is refused, a fully locked one is fine") {
  Model m;
  ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0));
  m.add_cable(a, b, Section{1e4, 0, 0, 0});
  m.set_lock(a, kLockTranslation);
  m.set_load(b, Vec3(1, 0, 0));
  Solver s(m);
  s.settings.mass_mode = MassMode::Physical;
  try {
    s.step();
    FAIL("expected a ModelError");
  } catch (const ModelError& e) {
    CHECK(std::string(e.what()).find("particle " + std::to_string(b) + " has no physical mass") != std::string::npos);
  }
  CHECK(m.particles.position[b] == Vec3(1, 0, 0));
  m.set_point_mass(b, 3);
  s.settings.dt = 1e-3;
  s.step();  // leapfrog's half kick: v = dt/2 F/m, x += dt v
  CHECK(m.particles.position[b].x() == doctest::Approx(1 + 0.5e-6 / 3).epsilon(1e-12));
}

TEST_CASE("a step allocates nothing once the scratch buffers fit the model") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    std::vector<ParticleId> ps;
    for (int i = 0; i <= 10; ++i) ps.push_back(m.add_particle(Vec3(i, 0, 0.01 * i * (10 - i))));
    m.add_beam(ps, Section{1e6, 1e2, 0, 1});
    m.gravity = Vec3(0, 0, -9.81);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
    Solver s(m);
    s.settings.integrator = integrator;
    s.step();  // sizes the scratch buffers
    g_allocations = 0;
    g_counting = true;
    for (int i = 0; i < 200; ++i) s.step();
    g_counting = false;
    CHECK(g_allocations == 0);
  }
}

TEST_CASE("integrators: viscous damping reaches the same equilibrium with every integrator") {
  auto solve = [](Integrator integrator, Damping damping) {
    Model m;
    std::vector<ParticleId> ps;
    for (int i = 0; i <= 8; ++i) ps.push_back(m.add_particle(Vec3(0.5 * i, 0, 0)));
    m.add_beam(ps, Section{1e7, 1e3, 0, 1});
    m.gravity = Vec3(0, 0, -9.81);
    m.set_lock(ps.front(), kLockTranslation);
    m.set_lock(ps.back(), kLockTranslation);
    m.set_load(ps[3], Vec3(0, 50, -100));
    Solver s(m);
    s.settings.integrator = integrator;
    s.settings.damping = damping;
    s.settings.viscous = 0.05;
    RunResult r = s.run(1e-7, 1'000'000);
    REQUIRE(r.converged);
    MESSAGE(std::string(integrator_name(integrator)) << " + " << std::string(damping_name(damping)) << ": steps=" << r.steps);
    // Vec3 named: deduced, the sum would be an Eigen expression over the two
    // reactions, temporaries gone by the time it is read (clang ASan read 5e-310).
    return std::pair<Vec3, Vec3>{m.particles.position[ps[3]], s.reaction(ps.front()) + s.reaction(ps.back())};
  };
  const auto [reference, support] = solve(Integrator::Leapfrog, Damping::Kinetic);
  CHECK(support.y() == doctest::Approx(-50).epsilon(1e-6));
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    const auto [x, reaction] = solve(integrator, Damping::Viscous);
    CHECK((x - reference).norm() < 1e-6 * reference.norm());
    CHECK((reaction - support).norm() < 1e-5);
  }
}

TEST_CASE("a step with 6-DOF beams allocates nothing once the scratch buffers fit the model") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    std::vector<ParticleId> ps;
    for (int i = 0; i <= 10; ++i) ps.push_back(m.add_particle(Vec3(i, 0, 0.01 * i * (10 - i))));
    const BlockId b = m.add_beam(ps, Section{1e6, 1e2, 0, 1});
    m.set_beam_formulation(b, 6);
    m.gravity = Vec3(0, 0, -9.81);
    m.set_lock(ps.front(), kLockTranslation | kLockRotation);
    m.set_moment(ps.back(), Vec3(1, 2, 3));
    Solver s(m);
    s.settings.integrator = integrator;
    s.step();
    g_allocations = 0;
    g_counting = true;
    for (int i = 0; i < 200; ++i) s.step();
    g_counting = false;
    CHECK(g_allocations == 0);
  }
}

namespace {

// A rotational oscillator: one 6-DOF beam element, clamped at the root, its
// tip held in place but free to turn about z. The tip's angle follows
// I theta'' = -(4 EI / L) sin(theta) (eq. 3.46 with the other end clamped),
// I = mu L^3 / 24 (physical rotary inertia of the half element); at this
// amplitude theta0 cos(omega t) to 1e-12.
struct Rocker {
  static constexpr double EI = 3, L = 1, mu = 2, theta0 = 1e-4;
  Model m;
  ParticleId root, tip;
  Rocker() {
    root = m.add_particle(Vec3(0, 0, 0));
    tip = m.add_particle(Vec3(L, 0, 0));
    const BlockId b = m.add_beam({root, tip}, Section{1e4, EI, 0, mu});
    m.set_lock(root, kLockTranslation | kLockRotation);
    m.set_lock(tip, kLockTranslation | kLockRX | kLockRY);
    m.set_beam_formulation(b, 6);
    m.set_orientation(tip, Quat(Eigen::AngleAxisd(theta0, Vec3::UnitZ())));
  }
  static double omega() { return std::sqrt(4 * EI / L / (mu * L * L * L / 24)); }
  double angle() const { return 2 * std::atan2(m.particles.orientation[tip].z(), m.particles.orientation[tip].w()); }
};

// The largest error of the tip angle over one period, n steps per period.
double rock(Integrator integrator, int n) {
  Rocker r;
  Solver s(r.m);
  s.settings.integrator = integrator;
  s.settings.mass_mode = MassMode::Physical;
  s.settings.damping = Damping::None;
  s.settings.dt = 2 * std::numbers::pi / Rocker::omega() / n;
  double worst = 0;
  for (int k = 1; k <= n; ++k) {
    s.step();
    const double exact = Rocker::theta0 * std::cos(Rocker::omega() * k * s.settings.dt);
    worst = std::max(worst, std::abs(r.angle() - exact));
  }
  return worst;
}

}  // namespace

TEST_CASE("integrators: rotation (eq. 3.16-3.25) converges at each integrator's order") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    const double coarse = rock(integrator, 100), fine = rock(integrator, 200);
    const double order = std::log2(coarse / fine);
    MESSAGE("rotation, " << name << ": largest angle error " << coarse / Rocker::theta0 << " theta0 at 100 steps per period, "
                         << fine / Rocker::theta0 << " at 200, observed order " << order);
    CHECK(order > expected_order(integrator) - 0.2);
    CHECK(coarse < 0.1 * Rocker::theta0);
  }
}
