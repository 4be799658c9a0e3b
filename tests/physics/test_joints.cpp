// Joints between members (Model::set_joint): a rigid joint of two 3-DOF
// beams at a shared particle keeps its built angle and carries moment
// (physics/element_forces.hpp: rigid_joint_forces); a pinned one carries
// none. Lee's frame and Williams' toggle against their published limit
// loads (validate/benchmark_models.hpp), and the joint's bookkeeping.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include "benchmark_models.hpp"
#include "model/model.hpp"
#include "physics/element_forces.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

constexpr double kPi = std::numbers::pi;

}  // namespace

TEST_CASE("rigid joint kernel: the moment k (theta - theta0) at any angle, a couple only") {
  // Segments of 2 m and 0.5 m at a right angle, rest angle 80 degrees: the
  // joint closes them by 10 degrees with M = k * 10 degrees; shears M / L.
  const double k = 3.0, theta0 = 80 * kPi / 180;
  const Vec3 p(1, 1, 0), a = p + Vec3(2, 0, 0), b = p + Vec3(0, 0.5, 0);
  const RigidJointForces f = rigid_joint_forces(k, theta0, p, a, b);
  const double M = k * 10 * kPi / 180;
  CHECK(f.fa.isApprox(Vec3(0, M / 2, 0), 1e-14));     // a pulled towards b
  CHECK(f.fb.isApprox(Vec3(M / 0.5, 0, 0), 1e-14));   // b pulled towards a
  // A couple: the forces (p takes -(fa + fb)) sum to zero, their moment
  // about p is M on a and -M on b.
  CHECK((a - p).cross(f.fa).z() == doctest::Approx(M));
  CHECK((b - p).cross(f.fb).z() == doctest::Approx(-M));
  CHECK(f.ka == doctest::Approx(4 * k / 4));
  CHECK(f.kb == doctest::Approx(4 * k / 0.25));
  // At its rest angle: no force; the hinge measure 2 sin(alpha) / Lc would
  // have no stiffness here, the angle has k.
  const RigidJointForces rest = rigid_joint_forces(k, kPi / 2, p, a, b);
  CHECK(rest.fa.norm() == 0);
  CHECK(rest.fb.norm() == 0);
}

TEST_CASE("Lee's frame with 3-DOF beams: a rigid corner reaches the limit load PL^2/EI = 18.56 within 1 %") {
  // Lee, Manuel & Rossow (1968): L = 120 in, EI = 1440 kip in^2, EA = 4320
  // kip, load at 24 in from the corner; limit PL^2/EI = 18.56. 20 segments
  // per member, displacement control (validate::find_limit).
  validate::LeeFrame f(20, 3);
  CHECK(f.m.joint_kind(f.corner, f.column_beam, f.girder_beam) == JointKind::Rigid);
  Solver solver(f.m);
  const validate::LimitPoint p = f.limit(solver);
  CHECK(p.converged);
  CHECK(f.m.check() == "");
  const double PL2_EI = p.load * f.L * f.L / f.EI;
  MESSAGE("Lee 3 DOF rigid: PL^2/EI = " << PL2_EI << " at a drop of " << p.displacement << " in");
  CHECK(std::abs(PL2_EI / 18.56 - 1) < 0.01);
}

TEST_CASE("Lee's frame with a pinned corner is a mechanism-like frame far below 18.56 (what 3-DOF beams were)") {
  validate::LeeFrame f(10, 3, JointKind::Pinned);
  CHECK(f.m.joint_kind(f.corner, f.column_beam, f.girder_beam) == JointKind::Pinned);
  Solver solver(f.m);
  const validate::LimitPoint p = f.limit(solver);
  MESSAGE("Lee 3 DOF pinned: PL^2/EI = " << p.load * f.L * f.L / f.EI);
  CHECK(p.load * f.L * f.L / f.EI < 0.8 * 18.56);
}

TEST_CASE("Williams' toggle with 3-DOF beams: a rigid apex reaches the limit load 33.86 lb within 1 %") {
  // Williams (1964): half span 12.943 in, rise 0.386 in, E = 10.3e6 psi,
  // section 0.753 x 0.243 in, supports clamped (clamp hinges); limit 33.86
  // lb. 20 segments per member, displacement control.
  validate::WilliamsToggle t(20, 3);
  Solver solver(t.m);
  const validate::LimitPoint p = t.limit(solver);
  CHECK(p.converged);
  CHECK(t.m.check() == "");
  MESSAGE("Williams 3 DOF rigid: P = " << p.load << " lb at a drop of " << p.displacement << " in");
  CHECK(std::abs(p.load / 33.86 - 1) < 0.01);
}
