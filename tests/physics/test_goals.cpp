// Anchors and geometric goals (elements.hpp: Goal): every integrator,
// explicit and constraint-based, reaches their analytic equilibria; they are
// journaled, saved and removed with their particles.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "io/model_xml.hpp"
#include "command/replay.hpp"
#include "io/trace.hpp"
#include "every_integrator.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using test::every_integrator;

TEST_CASE("goals: a particle between a spring and an anchor settles at their weighted average") {
  // A cable (k = EA/L = 1000 N/m, rest 1 m) from a support at the origin and
  // an anchor at x = 3 with weight w: k (x - 1) = w (3 - x), so
  // x = (k * 1 + w * 3) / (k + w).
  for (Integrator integrator : every_integrator()) {
    for (double w : {250.0, 4000.0}) {
      const std::string name = integrator_name(integrator);
      CAPTURE(name);
      CAPTURE(w);
      Model m;
      const ParticleId a = m.add_particle(Vec3(0, 0, 0)), p = m.add_particle(Vec3(1.5, 0, 0));
      m.add_cable(a, p, Section{1000, 0, 0, 0}, 1.0);
      m.set_lock(a, kLockTranslation);
      m.set_lock(p, kLockY | kLockZ);
      Goal g;
      g.kind = Goal::Anchor;
      g.i = p;
      g.point = Vec3(3, 0, 0);
      g.weight = w;
      m.add_goal(g);
      Solver s(m);
      s.settings.integrator = integrator;
      REQUIRE(s.run(1e-9, 1'000'000).converged);
      CHECK(m.particles.position[p].x() == doctest::Approx((1000 * 1 + w * 3) / (1000 + w)).epsilon(1e-9));
    }
  }
}

TEST_CASE("goals: plane, line and length goals reach their targets; weights trade them off") {
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::VariationalImplicitEuler,
                                Integrator::ProjectiveDynamics, Integrator::Mixed}) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    const ParticleId p = m.add_particle(Vec3(1, 2, 3)), q = m.add_particle(Vec3(4, 2, 3));
    const ParticleId r = m.add_particle(Vec3(0, 5, 0)), t = m.add_particle(Vec3(3, 5, 1));
    m.add_cable(p, q, Section{1, 0, 0, 0}, 3.0);  // slack-free, nearly no stiffness: gives the particles a block
    m.add_cable(r, t, Section{1, 0, 0, 0}, 1.2);
    Goal plane;  // p onto z = 0 (normal given unnormalised)
    plane.kind = Goal::Plane;
    plane.i = p;
    plane.point = Vec3(7, -1, 0);
    plane.direction = Vec3(0, 0, 2);
    plane.weight = 1e4;
    Goal line = plane;  // q onto the line x = 4, z = 0 along y
    line.kind = Goal::Line;
    line.i = q;
    line.point = Vec3(4, 0, 0);
    line.direction = Vec3(0, 3, 0);
    Goal anchor_r;  // r held, t pulled to length 2 from it
    anchor_r.kind = Goal::Anchor;
    anchor_r.i = r;
    anchor_r.point = Vec3(0, 5, 0);
    anchor_r.weight = 1e6;
    Goal length;
    length.kind = Goal::Length;
    length.i = r;
    length.j = t;
    length.length = 2;
    length.weight = 1e4;
    for (const Goal& g : {plane, line, anchor_r, length}) m.add_goal(g);
    Solver s(m);
    s.settings.integrator = integrator;
    REQUIRE(s.run(1e-7, 1'000'000).converged);
    const Vec3 xp = m.particles.position[p], xq = m.particles.position[q];
    CHECK(std::abs(xp.z()) < 1e-7);
    CHECK(std::abs(xq.x() - 4) < 1e-7);
    CHECK(std::abs(xq.z()) < 1e-7);
    // The cable r-t (k = EA / L = 1 / 1.2, rest 1.2 m) against the length
    // goal (2 m, w = 1e4 N/m): at their weighted average.
    const double k = 1 / 1.2, expected = (k * 1.2 + 1e4 * 2) / (k + 1e4);
    CHECK((m.particles.position[t] - m.particles.position[r]).norm() == doctest::Approx(expected).epsilon(1e-7));
  }
}

TEST_CASE("goals: bad input is refused naming the argument; a goal goes with its particle") {
  Model m;
  const ParticleId p = m.add_particle(Vec3(0, 0, 0)), q = m.add_particle(Vec3(1, 0, 0));
  const ParticleId r = m.add_particle(Vec3(0, 1, 0));
  const BlockId pq = m.add_cable(p, q, Section{1, 0, 0, 0});
  m.add_cable(p, r, Section{1, 0, 0, 0});
  Goal g;
  g.kind = Goal::Plane;
  g.i = p;
  g.weight = 1;
  CHECK_THROWS_WITH_AS(m.add_goal(g), doctest::Contains("normal"), ModelError);  // zero normal
  g.direction = Vec3(0, 0, 1);
  g.weight = -1;
  CHECK_THROWS_WITH_AS(m.add_goal(g), doctest::Contains("weight"), ModelError);
  g.weight = 1;
  g.i = 77;
  CHECK_THROWS_AS(m.add_goal(g), ModelError);
  CHECK(m.goals.empty());
  g.i = q;
  m.add_goal(g);
  g.kind = Goal::Anchor;
  g.i = p;
  m.add_goal(g);
  CHECK(m.goals.size() == 2);
  m.delete_cable(pq);
  if (m.particle_valid(q)) m.delete_particle(q);  // isolated now
  REQUIRE(m.goals.size() == 1);
  CHECK(m.goals[0].i == p);
  CHECK(m.check() == "");
}

TEST_CASE("goals: the model database stores them exactly; the journal replays them") {
  Model m;
  const ParticleId p = m.add_particle(Vec3(0, 0, 0)), q = m.add_particle(Vec3(1, 0.1, 0));
  m.add_cable(p, q, Section{10, 0, 0, 0});
  Goal a;
  a.kind = Goal::Line;
  a.i = q;
  a.point = Vec3(0.1, 0.2, 0.3);
  a.direction = Vec3(1, 1.0 / 3, 0);
  a.weight = 12.5;
  Goal b;
  b.kind = Goal::Length;
  b.i = p;
  b.j = q;
  b.length = 0.7;
  b.weight = 3;
  m.add_goal(a);
  m.add_goal(b);
  SolverSettings settings;
  const std::string xml = model_xml_string(m, settings);
  Model copy;
  SolverSettings read;
  load_model_xml_string(xml, copy, read);
  CHECK(model_xml_string(copy, read) == xml);  // exact round trip
  REQUIRE(copy.goals.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const Goal &x = m.goals[k], &y = copy.goals[k];
    CHECK(x.kind == y.kind);
    CHECK(x.point == y.point);
    CHECK(x.direction == y.direction);
    CHECK(x.length == y.length);
    CHECK(x.weight == y.weight);
  }
  CHECK(copy.goals[1].j != kNone);
  std::istringstream journal(
      "particle 0 0 0\nparticle 1 0.1 0\ncable 0 1 10 0 0 0 0\ngoal line 1 0.1 0.2 0.3 1 0.333 0 12.5\n"
      "goal length 0 1 0.7 3\ngoal anchor 0 0 0 0 5\ngoal_weight 2 6\nremove_goal 0\n");
  Model replayed;
  Solver s(replayed);
  replay_trace(journal, "journal", replayed, s);
  REQUIRE(replayed.goals.size() == 2);
  CHECK(replayed.goals[0].kind == Goal::Length);
  CHECK(replayed.goals[1].kind == Goal::Anchor);
  CHECK(replayed.goals[1].weight == 6);
}
