// The 6-DOF beam (thesis 3.2.8.4, Li's co-rotational Euler-Bernoulli element,
// eq. 3.44-3.50) against references: a cantilever rolled into a circle by an
// end moment, Bathe & Bolourchi's 45-degree bend, the pin-ended elastica,
// linear torsion and biaxial bending, twist imposed by locked frames; and
// switching formulations (thesis 5.5.2.1) and rule 13 while relaxing.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "benchmark_models.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

constexpr double kPi = std::numbers::pi;
constexpr std::uint8_t kFull = kLockTranslation | kLockRotation;

using validate::BentCantilever;
using validate::Cantilever;
// The pin-ended elastica of test_elastica.cpp, 64 segments unless told.
struct Strut : validate::Elastica {
  explicit Strut(double theta0_deg, int n = 64) : Elastica(theta0_deg, n) {}
};

// The rotation angle of a frame about the axis `axis` (unit), for frames
// turned about that axis only.
double angle_about(const Quat& q, const Vec3& axis) {
  const Eigen::AngleAxisd aa(Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z()));
  return aa.angle() * aa.axis().dot(axis);
}

}  // namespace

TEST_CASE("6-DOF beam: a cantilever under an end moment M = 2 pi EI / L rolls into a closed circle") {
  const double L = 1, EI = 1, M = 2 * kPi * EI / L;
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Cantilever c(20, L, Section{1e4, EI, 0, 0});
    c.m.set_moment(c.tip(), Vec3(0, 0, M));
    Solver solver(c.m);
    solver.settings.integrator = integrator;
    const RunResult r = solver.run(1e-7, 200'000);
    REQUIRE(r.converged);
    CHECK(c.m.check() == "");
    const double gap = (c.m.particles.position[c.tip()] - c.m.particles.position[c.ps.front()]).norm() / L;
    const Vec3 mid = c.m.particles.position[c.ps[10]];
    MESSAGE("end moment, " << name << ": |tip - root| / L = " << gap << ", mid-length point (" << mid.x() << ", "
                           << mid.y() << ") vs (0, " << L / kPi << "), steps " << r.steps);
    CHECK(gap < 0.01);
    CHECK(std::abs(mid.y() * kPi / L - 1) < 0.01);  // the diameter
    CHECK(std::abs(mid.x()) < 0.01 * L);
    // The tip turned once around; the root's support takes the moment.
    CHECK(solver.reaction_moment(c.ps.front()).z() == doctest::Approx(-M).epsilon(1e-6));
  }
}

TEST_CASE("6-DOF beam: Bathe & Bolourchi's 45-degree bend within 2% of Simo & Vu-Quoc") {
  // The model: validate/benchmark_models.hpp.
  const Vec3 reference = BentCantilever::kReference;
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::RK4}) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    BentCantilever bend(8);
    Solver solver(bend.m);
    solver.settings.integrator = integrator;
    const RunResult r = solver.run(1e-6, 200'000);
    REQUIRE(r.converged);
    CHECK(bend.m.check() == "");
    const Vec3 u = bend.displacement();
    MESSAGE("45-degree bend, " << name << ": tip displacement (" << u.x() << ", " << u.y() << ", " << u.z()
                               << ") in vs (-23.48, -13.50, 53.37); errors " << u.x() / reference.x() - 1 << ", "
                               << u.y() / reference.y() - 1 << ", " << u.z() / reference.z() - 1 << "; steps "
                               << r.steps);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(u[k] / reference[k] - 1) < 0.02);
  }
}

TEST_CASE("6-DOF beam: the pin-ended elastica within 1% (deflection and axial load)") {
  for (double theta0 : {40.0, 80.0, 120.0}) {
    CAPTURE(theta0);
    Strut strut(theta0);
    strut.m.set_beam_formulation(strut.beam, 6);
    Solver solver(strut.m);
    const RunResult r = solver.run(1e-3, 200'000);
    REQUIRE(r.converged);
    CHECK(strut.m.check() == "");
    MESSAGE("elastica 6 DOF, theta0=" << theta0 << ": deflection error " << strut.deflection_error()
                                      << ", load error " << strut.load_error(solver) << ", steps " << r.steps);
    CHECK(strut.deflection_error() < 0.01);
    CHECK(strut.load_error(solver) < 0.01);
  }
}

TEST_CASE("6-DOF beam: the elastica with every integrator, and with viscous damping") {
  for (Integrator integrator : kIntegrators) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Strut strut(80.0);
    strut.m.set_beam_formulation(strut.beam, 6);
    Solver solver(strut.m);
    solver.settings.integrator = integrator;
    const RunResult r = solver.run(1e-3, 200'000);
    REQUIRE(r.converged);
    MESSAGE("elastica 6 DOF, " << name << ": steps " << r.steps << ", deflection error "
                               << strut.deflection_error() << ", load error " << strut.load_error(solver));
    CHECK(strut.deflection_error() < 0.01);
    CHECK(strut.load_error(solver) < 0.01);
  }
  Strut strut(80.0);
  strut.m.set_beam_formulation(strut.beam, 6);
  Solver solver(strut.m);
  solver.settings.damping = Damping::Viscous;
  solver.settings.viscous = 0.02;
  const RunResult r = solver.run(1e-3, 200'000);
  REQUIRE(r.converged);
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}

TEST_CASE("6-DOF beam: switching 3 -> 6 -> 3 DOF mid-run converges to the same elastica") {
  Strut strut(80.0);
  Solver solver(strut.m);
  for (int i = 0; i < 300; ++i) solver.step();
  REQUIRE(solver.residual() > 1);  // far from equilibrium
  strut.m.set_beam_formulation(strut.beam, 6);
  REQUIRE(strut.m.check() == "");
  CHECK(strut.m.bars.size() == 0);
  CHECK(strut.m.hinges.size() == 0);
  CHECK(strut.m.beam6s.size() == 64);
  for (int i = 0; i < 600; ++i) solver.step();
  REQUIRE(solver.residual() > 1);  // still moving
  strut.m.set_beam_formulation(strut.beam, 3);
  REQUIRE(strut.m.check() == "");
  CHECK(strut.m.beam6s.size() == 0);
  CHECK(strut.m.particles.rotational.size() == 0);
  const RunResult r = solver.run(1e-3, 200'000);
  REQUIRE(r.converged);
  MESSAGE("3 -> 6 -> 3 DOF: deflection error " << strut.deflection_error() << ", load error "
                                               << strut.load_error(solver) << ", steps " << 900 + r.steps);
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);

  // And ending in 6 DOF: 3 -> 6 at equilibrium keeps the equilibrium.
  strut.m.set_beam_formulation(strut.beam, 6);
  solver.step();
  const double kept = solver.residual();
  const RunResult r6 = solver.run(1e-3, 200'000);
  REQUIRE(r6.converged);
  MESSAGE("3 -> 6 DOF at equilibrium: first residual " << kept << " N, " << r6.steps << " steps to 1e-3");
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}

TEST_CASE("6-DOF beam: rule 13 on a relaxed beam keeps check() and the solution") {
  Strut strut(80.0, 32);
  strut.m.set_beam_formulation(strut.beam, 6);
  Solver solver(strut.m);
  REQUIRE(solver.run(1e-3, 200'000).converged);
  const double before_deflection = strut.deflection_error(), before_load = strut.load_error(solver);
  const double load = -solver.reaction(strut.ps.back()).x();
  for (std::size_t i = 0; i + 1 < strut.ps.size(); i += 2) {
    const ParticleId q = strut.m.insert_particle(strut.ps[i], strut.ps[i + 1]);
    REQUIRE(strut.m.check() == "");
    CHECK(strut.m.particles.rot_degree[q] == 2);
  }
  CHECK(strut.m.beam6s.size() == 48);
  solver.reset_motion();
  solver.step();
  // The new nodes sit on the elements' cubic deflection curves: what is left
  // is the refinement, a fraction of the strut's load.
  MESSAGE("rule 13 x16 on a 6-DOF elastica: residual right after " << solver.residual() << " N (load " << load << " N)");
  CHECK(solver.residual() < 0.5 * load);
  const RunResult r = solver.run(1e-3, 200'000);
  REQUIRE(r.converged);
  CHECK(strut.m.check() == "");
  MESSAGE("rule 13 x16: deflection error " << strut.deflection_error() << " (before " << before_deflection
                                           << "), load error " << strut.load_error(solver) << " (before "
                                           << before_load << "), steps " << r.steps);
  CHECK(strut.deflection_error() < 0.01);
  CHECK(strut.load_error(solver) < 0.01);
}

TEST_CASE("6-DOF beam: linear torsion and biaxial bending of a cantilever") {
  const double L = 2, EA = 1e6, EIy = 2e3, EIz = 1e3, GJ = 500;
  Section s{EA, EIz, 0, 0};
  s.EIy = EIy;
  s.EIz = EIz;
  s.GJ = GJ;
  SUBCASE("a torque about the axis twists the tip by T L / GJ") {
    Cantilever c(8, L, s);
    const double T = 1;  // 4 mrad
    c.m.set_moment(c.tip(), Vec3(T, 0, 0));
    Solver solver(c.m);
    REQUIRE(solver.run(1e-9, 200'000).converged);
    const double twist = angle_about(c.m.particles.orientation[c.tip()], Vec3::UnitX());
    CHECK(twist == doctest::Approx(T * L / GJ).epsilon(1e-3));
    CHECK((c.m.particles.position[c.tip()] - Vec3(L, 0, 0)).norm() < 1e-9);
    CHECK(solver.reaction_moment(c.ps.front()).x() == doctest::Approx(-T).epsilon(1e-6));
  }
  SUBCASE("tip loads along y and z bend it by P L^3 / 3 EIz and P L^3 / 3 EIy") {
    Cantilever c(8, L, s);
    const double P = 0.5;  // deflections ~1e-3 L
    c.m.set_load(c.tip(), Vec3(0, P, P));
    Solver solver(c.m);
    REQUIRE(solver.run(1e-7, 200'000).converged);
    const Vec3 tip = c.m.particles.position[c.tip()];
    CHECK(tip.y() == doctest::Approx(P * L * L * L / (3 * EIz)).epsilon(2e-3));
    CHECK(tip.z() == doctest::Approx(P * L * L * L / (3 * EIy)).epsilon(2e-3));
    const Vec3 moment = solver.reaction_moment(c.ps.front());
    CHECK(moment.z() == doctest::Approx(-P * L).epsilon(2e-3));  // M = P L about z for the y load
    CHECK(moment.y() == doctest::Approx(P * L).epsilon(2e-3));   // and about -y for the z load
  }
}

TEST_CASE("6-DOF beam: twist between two fully locked ends comes from their frames (thesis 5.5.2.1)") {
  // Both ends clamped; the far end's frame turned by 0.3 rad about the beam's
  // axis before the switch: the beam takes that twist, linearly along it.
  const double L = 1, GJ = 20, twist = 0.3;
  Section s{1e5, 50, 0, 0};
  s.GJ = GJ;
  Model m;
  std::vector<ParticleId> ps;
  for (int i = 0; i <= 10; ++i) ps.push_back(m.add_particle(Vec3(L * i / 10, 0, 0)));
  const BlockId b = m.add_beam(ps, s);
  m.set_lock(ps.front(), kFull);
  m.set_lock(ps.back(), kFull);
  m.set_orientation(ps.back(), Quat(Eigen::AngleAxisd(twist, Vec3::UnitX())));
  m.set_beam_formulation(b, 6);
  REQUIRE(m.check() == "");
  // Free particles took the first locked particle's twist reference.
  CHECK(angle_about(m.particles.orientation[ps[5]], Vec3::UnitX()) == doctest::Approx(0).scale(1));
  Solver solver(m);
  REQUIRE(solver.run(1e-9, 200'000).converged);
  CHECK(angle_about(m.particles.orientation[ps[5]], Vec3::UnitX()) == doctest::Approx(twist / 2).epsilon(1e-6));
  CHECK(angle_about(m.particles.orientation[ps[2]], Vec3::UnitX()) == doctest::Approx(twist / 5).epsilon(1e-6));
  // The clamps hold the torque GJ * angle / L (the element's small-angle twist, sin).
  CHECK(solver.reaction_moment(ps.front()).x() == doctest::Approx(-GJ * std::sin(twist / 10) * 10 / L).epsilon(1e-3));
}

TEST_CASE("6-DOF beam: a rotation lock takes the moment, kinetic energy counts rotation (eq. 3.28)") {
  const double M = 2;
  Cantilever c(4, 1, Section{1e4, 1, 0, 0});
  c.m.set_moment(c.tip(), Vec3(0, 0, M));
  Solver solver(c.m);
  solver.step();
  // From rest, only the moment acts: the first step's energy is rotational.
  CHECK(solver.kinetic_energy() > 0);
  CHECK(c.m.particles.velocity[c.tip()].norm() == 0);
  CHECK(c.m.particles.angular_velocity[c.tip()].z() > 0);
  c.m.set_lock(c.tip(), kLockRZ);
  solver.reset_motion();
  c.m.set_orientation(c.tip(), Quat::Identity());
  REQUIRE(solver.run(1e-9, 100'000).converged);
  CHECK(c.m.particles.angular_velocity[c.tip()].z() == 0);
  CHECK(angle_about(c.m.particles.orientation[c.tip()], Vec3::UnitZ()) == doctest::Approx(0).scale(1));
  CHECK(solver.reaction_moment(c.tip()).z() == doctest::Approx(-M).epsilon(1e-6));
  CHECK(c.m.particles.position[c.tip()].y() == doctest::Approx(0).scale(1e-6));
}

TEST_CASE("6-DOF beam: particles off 6-DOF beams keep no rotational state and cost no rotational work") {
  Model m;
  std::vector<ParticleId> a, b;
  for (int i = 0; i <= 6; ++i) {
    a.push_back(m.add_particle(Vec3(i, 0, 0)));
    b.push_back(m.add_particle(Vec3(i, 2, 0)));
  }
  m.add_beam(a, Section{1e5, 10, 0, 0});  // 3 DOF, simply supported, loaded at mid-span
  const BlockId six = m.add_beam(b, Section{1e5, 10, 0, 0});
  m.set_lock(a.front(), kLockTranslation);
  m.set_lock(a.back(), kLockTranslation);
  m.set_lock(b.front(), kFull);
  m.set_load(a[3], Vec3(0, 0, -0.01));
  m.set_load(b.back(), Vec3(0, 0, -0.01));
  Solver solver(m);
  solver.step();
  CHECK(m.particles.rotational.size() == 0);
  m.set_beam_formulation(six, 6);
  CHECK(m.particles.rotational.size() == b.size());
  REQUIRE(solver.run(1e-9, 200'000).converged);
  for (ParticleId p : a) {
    CHECK(m.particles.rot_degree[p] == 0);
    CHECK(m.particles.orientation[p].coeffs() == Quat::Identity().coeffs());  // never integrated
    CHECK(m.particles.torque[p] == Vec3::Zero());                           // never accumulated
  }
  CHECK(angle_about(m.particles.orientation[b.back()], Vec3::UnitY()) > 0);  // the 6-DOF tip turned
  CHECK(m.particles.position[a[3]].z() < 0);
  // The 6-DOF cantilever's small tip deflection: P L^3 / 3 EI.
  CHECK(m.particles.position[b.back()].z() == doctest::Approx(-0.01 * 6 * 6 * 6 / 30).epsilon(2e-3));
}

TEST_CASE("6-DOF beam: physical masses need rotary inertia from a line mass") {
  Cantilever c(4, 1, Section{1e4, 1, 0, 0});
  Solver solver(c.m);
  solver.settings.mass_mode = MassMode::Physical;
  c.m.set_point_mass(c.tip(), 1);
  for (ParticleId p : c.ps) c.m.set_point_mass(p, 1);
  CHECK_THROWS_WITH_AS(solver.step(), doctest::Contains("rotary inertia"), ModelError);
  Cantilever d(4, 1, Section{1e4, 1, 0, 0.5});
  Solver s2(d.m);
  s2.settings.mass_mode = MassMode::Physical;
  s2.settings.dt = 1e-4;
  d.m.set_moment(d.tip(), Vec3(0, 0, 0.1));
  for (int i = 0; i < 10; ++i) s2.step();
  CHECK(d.m.particles.angular_velocity[d.tip()].z() > 0);
  CHECK(d.m.check() == "");
}
