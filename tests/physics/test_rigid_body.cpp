// The rigid-body goal (Goal::Rigid, physics/rigid_body.hpp): shape matching
// leaves the six rigid motions free (no pull on a moved and turned body),
// its pulls on a deformed body sum to zero with no moment about the
// centroid, and an L-shaped body pinned at one corner under a load at
// another swings until the load hangs below the pin, keeping its shape,
// under every integrator; saved and loaded, replayed, it goes with a deleted
// particle; bad bodies are refused.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <string>

#include "physics/rigid_body.hpp"
#include "every_integrator.hpp"
#include "physics/solver.hpp"
#include "reload.hpp"

using namespace tendril;
using test::every_integrator;

namespace {

// An L of three particles, A (0, 0, 0), B (1, 0, 0), C (1, 0, -1), and D
// off its plane, (0.5, 0.5, -0.5): a body with a volume. Slack cables give
// the particles blocks (a particle in no block is isolated and never moves)
// and carry nothing.
struct Body {
  Model m;
  ParticleId p[4];
  std::size_t goal;
  explicit Body(double w) {
    const Vec3 x[4] = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0, -1), Vec3(0.5, 0.5, -0.5)};
    for (int a = 0; a < 4; ++a) p[a] = m.add_particle(x[a]);
    for (int a = 0; a < 4; ++a) m.add_cable(p[a], p[(a + 1) % 4], Section{1, 0, 0, 0}, 5.0);
    Goal g;
    g.kind = Goal::Rigid;
    g.members = {p[0], p[1], p[2], p[3]};
    g.weight = w;
    goal = m.add_goal(g);
  }
  double distance(int a, int b) const { return (m.particles.position[p[a]] - m.particles.position[p[b]]).norm(); }
};

}  // namespace

TEST_CASE("rigid body: rigid motions pull nothing; a deformed body's pulls sum to zero with no moment") {
  Body b(1e3);
  const Goal& g = std::as_const(b.m.goals)[b.goal];
  const Mat3 R = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> x(4), pulls;
  for (int a = 0; a < 4; ++a) x[std::size_t(b.p[a])] = R * b.m.particles.position[b.p[a]] + Vec3(3, -2, 5);
  rigid_pulls(g, x.data(), pulls);
  for (const Vec3& f : pulls) CHECK(f.norm() < 1e-10);
  x[std::size_t(b.p[2])] += Vec3(0.1, -0.05, 0.2);  // deformed
  rigid_pulls(g, x.data(), pulls);
  Vec3 sum = Vec3::Zero(), moment = Vec3::Zero(), c = Vec3::Zero();
  for (int a = 0; a < 4; ++a) c += x[std::size_t(b.p[a])] / 4;
  for (int a = 0; a < 4; ++a) {
    sum += pulls[std::size_t(a)];
    moment += (x[std::size_t(b.p[a])] - c).cross(pulls[std::size_t(a)]);
  }
  CHECK(pulls[2].norm() > 10);
  CHECK(sum.norm() < 1e-10);
  CHECK(moment.norm() < 1e-10);
}

TEST_CASE("rigid body: an L pinned at A with a load at C swings until C hangs below A, under every integrator") {
  // Statics of a rigid body on one pin: the load's line passes through it,
  // so C ends at (0, 0, -|AC|) = (0, 0, -sqrt 2) (by symmetry C stays in
  // the xz plane); the shape holds to P / w.
  for (Integrator integrator : every_integrator()) {
    CAPTURE(integrator_name(integrator));
    Body b(1e6);
    b.m.set_lock(b.p[0], kLockTranslation);
    b.m.set_load(b.p[2], Vec3(0, 0, -10));
    Solver s(b.m);
    s.settings.integrator = integrator;
    const RunResult r = s.run(RunLimits{1e-7, 0, 2000000});
    CHECK(r.converged);
    const Vec3 c = b.m.particles.position[b.p[2]];
    CHECK(std::abs(c.x()) < 1e-4);
    CHECK(std::abs(c.y()) < 1e-4);
    CHECK(c.z() == doctest::Approx(-std::sqrt(2.0)).epsilon(1e-4));
    CHECK(b.distance(0, 1) == doctest::Approx(1).epsilon(1e-4));
    CHECK(b.distance(1, 2) == doctest::Approx(1).epsilon(1e-4));
    CHECK(b.distance(1, 3) == doctest::Approx(std::sqrt(0.75)).epsilon(1e-4));
    CHECK(b.distance(2, 3) == doctest::Approx(std::sqrt(0.75)).epsilon(1e-4));
    // the pin carries the load
    CHECK(s.reaction(b.p[0]).z() == doctest::Approx(10).epsilon(1e-4));
  }
}

TEST_CASE("rigid body: the model database keeps it; it goes with a deleted particle; bad bodies are refused") {
  Body b(1e4);
  b.m.particles.position[b.p[2]] = Vec3(1.1, 0, -1);  // the rest shape stays the one it was made with
  Model loaded;
  CHECK(test::reload(b.m, loaded, "rigid.xml").find("kind=\"rigid\"") != std::string::npos);
  REQUIRE(loaded.goals.size() == 1);
  const Goal& g = std::as_const(loaded.goals)[0];
  CHECK(g.kind == Goal::Rigid);
  REQUIRE(g.rest.size() == 4);
  CHECK((g.rest[2] - std::as_const(b.m.goals)[0].rest[2]).norm() == 0);

  for (BlockId blk : b.m.blocks_of(b.p[3])) b.m.delete_cable(blk);  // rule 7 takes the particle left isolated
  CHECK(!b.m.particles.valid(b.p[3]));
  CHECK(b.m.goals.empty());

  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), c = m.add_particle(Vec3(1, 0, 0)), d = m.add_particle(Vec3(2, 0, 0));
  Goal line;
  line.kind = Goal::Rigid;
  line.weight = 1;
  line.members = {a, c, d};
  CHECK_THROWS_WITH(m.add_goal(line), "goal (rigid): its particles are on one line; a rigid body needs three not on a line");
  line.members = {a, c};
  CHECK_THROWS_WITH(m.add_goal(line), "goal (rigid): needs three or more particles, got 2");
  line.members = {a, c, a};
  CHECK_THROWS_WITH(m.add_goal(line), "goal (rigid): particle 0 is given twice");
  CHECK(m.goals.empty());
}
