// The default integrator "auto" (solver.hpp, Solver::RunScope): a run() to
// equilibrium of a model the Newton solver takes, with fictitious masses
// and kinetic damping, is Newton's and ends where Newton alone ends; a step
// in time, a run of a model Newton refuses and a run of dynamics are
// Leapfrog's, bit for bit; a run Newton stalls on goes on with Leapfrog
// from where it stopped and ends where Leapfrog alone ends.
#include <doctest/doctest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/solver.hpp"
#include "prestressed_net.hpp"

using namespace tendril;

namespace {

std::vector<ParticleId> net(Model& m, int s) { return test::prestressed_net(m, s); }

// A straight chain of cables at their rest length, ends locked, 10 N in -z
// on its inner particles: no tension, so no transverse stiffness, and the
// tangent is singular along z whatever its shift.
void slack_chain(Model& m) {
  std::vector<ParticleId> ps;
  for (int k = 0; k <= 6; ++k) ps.push_back(m.add_particle(Vec3(k, 0, 0)));
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  for (std::size_t k = 1; k + 1 < ps.size(); ++k) m.set_load(ps[k], Vec3(0, 0, -10));
  for (std::size_t k = 0; k + 1 < ps.size(); ++k) m.add_cable(ps[k], ps[k + 1], Section{1e4, 0, 0, 0});
}

double largest_distance(const Model& a, const Model& b) {
  double d = 0;
  for (ParticleId p : a.particles.integrated.raw())
    d = std::max(d, (a.particles.position[p] - b.particles.position[p]).norm());
  return d;
}

}  // namespace

TEST_CASE("auto: the default; a run of bars and cables is Newton's, a step Leapfrog's") {
  Model ma, mn, ml;
  net(ma, 14), net(mn, 14), net(ml, 14);
  Solver sa(ma), sn(mn), sl(ml);
  CHECK(sa.settings.integrator == Integrator::Auto);
  CHECK(parse_integrator("auto") == Integrator::Auto);
  CHECK(std::string(integrator_name(Integrator::Auto)) == "auto");
  sn.settings.integrator = Integrator::Newton;
  sl.settings.integrator = Integrator::Leapfrog;

  const RunResult ra = sa.run(1e-8, 100000), rn = sn.run(1e-8, 100000), rl = sl.run(1e-7, 1000000);
  REQUIRE(ra.converged);
  REQUIRE(rl.converged);
  CHECK(std::string(sa.phase()) == "newton");
  CHECK(sa.settings.integrator == Integrator::Auto);  // the setting stays
  CHECK(ra.steps == rn.steps);
  CHECK(ra.steps < 10);
  CHECK(rl.steps > 500);
  CHECK(largest_distance(ma, mn) == 0);     // Newton's steps, bit for bit
  CHECK(largest_distance(ma, ml) < 1e-7);   // Leapfrog's equilibrium

  // A step after the run, and steps from the start, are Leapfrog's.
  sa.step();
  CHECK(std::string(sa.phase()) == "leapfrog");
  Model ms, mt;
  net(ms, 14), net(mt, 14);
  Solver ss(ms), st(mt);
  st.settings.integrator = Integrator::Leapfrog;
  for (int k = 0; k < 40; ++k) ss.step(), st.step();
  CHECK(std::string(ss.phase()) == "leapfrog");
  CHECK(largest_distance(ms, mt) == 0);
  CHECK(ss.residual() == st.residual());
  CHECK(ss.fused_step_bytes() > 0);  // the fused bar step, as Leapfrog's
  CHECK(ss.fused_step_bytes() == st.fused_step_bytes());
}

TEST_CASE("auto: Leapfrog for a model Newton refuses and for dynamics, bit for bit") {
  auto with = [](auto change) {
    Model ma, ml;
    net(ma, 8), net(ml, 8);
    Solver sa(ma), sl(ml);
    change(ma, sa), change(ml, sl);
    sl.settings.integrator = Integrator::Leapfrog;
    const RunResult ra = sa.run(1e-6, 200000), rl = sl.run(1e-6, 200000);
    CHECK(std::string(sa.phase()) == "leapfrog");
    CHECK(ra.steps == rl.steps);
    CHECK(ra.verdict == rl.verdict);
    CHECK(largest_distance(ma, ml) == 0);
  };
  SUBCASE("a spline beam") {
    with([](Model& m, Solver&) {
      const ParticleId a = m.add_particle(Vec3(0, -2, 0)), b = m.add_particle(Vec3(1, -2, 0)),
                       c = m.add_particle(Vec3(2, -2, 0));
      m.set_lock(a, kLockTranslation);
      m.set_lock(c, kLockTranslation);
      m.add_beam({a, b, c}, Section{1e4, 10, 0, 0});
    });
  }
  SUBCASE("physical masses") {
    with([](Model& m, Solver& s) {
      for (ParticleId p : m.particles.integrated.raw()) m.set_point_mass(p, 0.1);
      s.settings.mass_mode = MassMode::Physical;
      s.settings.dt = 1e-3;
    });
  }
  SUBCASE("viscous damping") {
    with([](Model&, Solver& s) { s.settings.damping = Damping::Viscous; });
  }
}

TEST_CASE("auto: a run Newton stalls on goes on with Leapfrog from where it stopped") {
  Model ma, ml;
  slack_chain(ma), slack_chain(ml);
  Solver sa(ma), sl(ml);
  sl.settings.integrator = Integrator::Leapfrog;
  const RunResult ra = sa.run(1e-6, 200000), rl = sl.run(1e-6, 200000);
  REQUIRE(rl.converged);
  CHECK(ra.converged);
  CHECK(std::string(sa.phase()) == "leapfrog");
  CHECK(ra.steps == rl.steps + 1);  // Newton's step moved nothing
  CHECK(largest_distance(ma, ml) == 0);
  // The chain hangs: every inner particle went down.
  for (ParticleId p : ma.particles.integrated.raw())
    if (ma.particles.lock[p] == 0) CHECK(ma.particles.position[p].z() < -0.01);
}
