// The planarity goal of a quad face (thesis fig. 6.6): a twisted quad, its
// corners anchored where they start, is pulled flat against the anchors to
// the analytic balance under every integrator; it is saved, replayed, and
// goes with its particles.
#include <doctest/doctest.h>

#include <sstream>
#include <string>

#include "command/replay.hpp"
#include "io/model_xml.hpp"
#include "physics/planarity.hpp"
#include "every_integrator.hpp"
#include "physics/solver.hpp"

using namespace tendril;
using test::every_integrator;

namespace {

// The unit square twisted by +-h: corners at z = h, -h, h, -h round it. Its
// best-fit plane is z = 0 (by symmetry, before and after), each corner h
// from it. Slack cables round the edges give the particles blocks and carry
// nothing.
struct TwistedQuad {
  Model m;
  ParticleId c[4];
  explicit TwistedQuad(double h) {
    const double xy[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int a = 0; a < 4; ++a) c[a] = m.add_particle(Vec3(xy[a][0], xy[a][1], a % 2 ? -h : h));
    for (int a = 0; a < 4; ++a) m.add_cable(c[a], c[(a + 1) % 4], Section{1, 0, 0, 0}, 3.0);
  }
  std::size_t planarity(double w) {
    Goal g;
    g.kind = Goal::Planar;
    g.i = c[0], g.j = c[1], g.k = c[2], g.l = c[3];
    g.weight = w;
    return m.add_goal(g);
  }
  double gap() const {
    const Vec3 x[4] = {m.particles.position[c[0]], m.particles.position[c[1]], m.particles.position[c[2]],
                       m.particles.position[c[3]]};
    return planarity_gap(x);
  }
};

}  // namespace

TEST_CASE("planarity: a twisted quad goes flat against its anchors, w d = k (h - d), under every integrator") {
  // Each corner is anchored (weight k) where it starts, h off the plane, and
  // pulled towards the plane with weight w: it settles d = k h / (k + w) off
  // it. w = 1e4 k leaves 1e-4 h: flat to 1e-5 m.
  const double h = 0.1, k = 100;
  for (Integrator integrator : every_integrator()) {
    for (double w : {100.0, 1e6}) {
      const std::string name = integrator_name(integrator);
      CAPTURE(name);
      CAPTURE(w);
      TwistedQuad q(h);
      CHECK(q.gap() == doctest::Approx(h).epsilon(1e-12));
      for (ParticleId p : q.c) {
        Goal a;
        a.kind = Goal::Anchor;
        a.i = p;
        a.point = q.m.particles.position[p];
        a.weight = k;
        q.m.add_goal(a);
      }
      q.planarity(w);
      Solver s(q.m);
      s.settings.integrator = integrator;
      REQUIRE(s.run(1e-9, 2'000'000).converged);
      const double d = k * h / (k + w);
      CHECK(q.gap() == doctest::Approx(d).epsilon(1e-6));
      CHECK(q.m.particles.position[q.c[0]].z() == doctest::Approx(d).epsilon(1e-6));
      CHECK(q.m.particles.position[q.c[1]].z() == doctest::Approx(-d).epsilon(1e-6));
      CHECK(q.m.particles.position[q.c[0]].x() == doctest::Approx(0).scale(1).epsilon(1e-9));  // moved across only
      if (w > 1e5) CHECK(q.gap() < 1e-5);
    }
  }
}

TEST_CASE("planarity: a general non-planar quad alone becomes planar under every integrator") {
  for (Integrator integrator : every_integrator()) {
    const std::string name = integrator_name(integrator);
    CAPTURE(name);
    Model m;
    const Vec3 at[4] = {Vec3(0, 0, 0.3), Vec3(2, 0.1, -0.2), Vec3(1.7, 1.2, 0.5), Vec3(-0.2, 0.9, -0.1)};
    ParticleId c[4];
    for (int a = 0; a < 4; ++a) c[a] = m.add_particle(at[a]);
    for (int a = 0; a < 4; ++a) m.add_cable(c[a], c[(a + 1) % 4], Section{1e3, 0, 0, 0});  // in-plane shape
    m.set_lock(c[0], kLockTranslation);  // one corner held: the face must not drift
    Goal g;
    g.kind = Goal::Planar;
    g.i = c[0], g.j = c[1], g.k = c[2], g.l = c[3];
    g.weight = 1e3;
    m.add_goal(g);
    Solver s(m);
    s.settings.integrator = integrator;
    REQUIRE(s.run(1e-9, 2'000'000).converged);
    const Vec3 x[4] = {m.particles.position[c[0]], m.particles.position[c[1]], m.particles.position[c[2]],
                       m.particles.position[c[3]]};
    CHECK(planarity_gap(at) > 0.1);
    CHECK(planarity_gap(x) < 1e-9);
  }
}

TEST_CASE("planarity: refused with a repeated or dead corner; saved exactly; replayed; goes with its corners") {
  TwistedQuad q(0.05);
  Goal g;
  g.kind = Goal::Planar;
  g.i = q.c[0], g.j = q.c[1], g.k = q.c[1], g.l = q.c[3];
  g.weight = 1;
  CHECK_THROWS_WITH_AS(q.m.add_goal(g), doctest::Contains("corner 2 and corner 3"), ModelError);
  g.k = 99;
  CHECK_THROWS_AS(q.m.add_goal(g), ModelError);
  CHECK(q.m.goals.empty());
  q.planarity(7.5);
  SolverSettings settings;
  const std::string xml = model_xml_string(q.m, settings);
  CHECK(xml.find("kind=\"planar\"") != std::string::npos);
  Model copy;
  SolverSettings read;
  load_model_xml_string(xml, copy, read);
  CHECK(model_xml_string(copy, read) == xml);
  REQUIRE(copy.goals.size() == 1);
  CHECK(copy.goals[0].kind == Goal::Planar);
  CHECK(copy.goals[0].l != kNone);
  std::istringstream journal(
      "particle 0 0 0\nparticle 1 0 0.1\nparticle 1 1 0\nparticle 0 1 0.1\ncable 0 1 10 0 0 0 0\n"
      "cable 2 3 10 0 0 0 0\nplanarity 50 0 1 2 3\nsteps 10\n");
  Model replayed;
  Solver s(replayed);
  replay_trace(journal, "journal", replayed, s);
  REQUIRE(replayed.goals.size() == 1);
  CHECK(replayed.goals[0].kind == Goal::Planar);
  CHECK(replayed.goals[0].weight == 50);
  // Corner 3 goes (its cables, then the particle if still there): so does the goal.
  while (q.m.particle_valid(q.c[2]) && !q.m.blocks_of(q.c[2]).empty()) q.m.delete_cable(q.m.blocks_of(q.c[2])[0]);
  if (q.m.particle_valid(q.c[2])) q.m.delete_particle(q.c[2]);
  CHECK(q.m.goals.empty());
  CHECK(q.m.check() == "");
}
