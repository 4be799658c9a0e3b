// The static Newton solver (integrator "newton", newton.hpp): its tangent
// is the derivative of the forces, it reaches the equilibrium the explicit
// and projective solvers reach (prestressed net, a net with a slack cable,
// locked axes, anchor, plane, line and length goals), follows topology
// changes between steps, keeps its symbolic analysis while the pattern
// holds, refuses elements it has no tangent for, says so when it cannot
// converge, and gives the same numbers on any thread count.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/newton.hpp"
#include "physics/solver.hpp"
#include "prestressed_net.hpp"

using namespace tendril;

namespace {

std::vector<ParticleId> net(Model& m, int s, double load = 1.0) { return test::prestressed_net(m, s, load); }

double largest_distance(const Model& a, const Model& b) {
  double d = 0;
  for (ParticleId p : a.particles.integrated.raw())
    d = std::max(d, (a.particles.position[p] - b.particles.position[p]).norm());
  return d;
}

RunResult relax(Solver& s, Integrator i, double tolerance, std::uint64_t steps = 2'000'000) {
  s.settings.integrator = i;
  return s.run(tolerance, steps);
}

}  // namespace

TEST_CASE("newton: the tangent equals the central differences of the forces (bars, a slack cable, goals, locked axes)") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1.1, 0.2, 0.3)),
                   c = m.add_particle(Vec3(0.1, 0.9, -0.2)), d = m.add_particle(Vec3(1.2, 1.1, 0.4));
  m.set_lock(a, kLockTranslation);
  m.set_lock(c, kLockZ);  // c moves in its plane only
  m.add_elastic_bar(a, b, Section{2e3, 0, 50, 0}, 1.0);
  m.add_elastic_bar(b, d, Section{1e3, 0, -30, 0}, 1.2);  // compressed: a negative geometric term
  m.add_cable(a, c, Section{5e2, 0, 10, 0}, 0.8);         // taut
  m.add_cable(c, d, Section{5e2, 0, 0, 0}, 2.0);          // slack: no stiffness
  m.add_elastic_bar(c, b, Section{8e2, 0, 0, 0}, 1.0);
  const ParticleId e = m.add_particle(Vec3(0.7, 1.6, 0.9));
  m.add_cable(d, e, Section{3e2, 0, 20, 0}, 0.9);
  auto goal = [&](Goal::Kind k, ParticleId i, ParticleId j, Vec3 point, Vec3 direction, double length, double w) {
    Goal g;
    g.kind = k, g.i = i, g.j = j, g.point = point, g.direction = direction, g.length = length, g.weight = w;
    m.add_goal(g);
  };
  goal(Goal::Anchor, b, kNone, Vec3(1, 0.1, 0.2), Vec3::Zero(), 0, 300);
  goal(Goal::Plane, d, kNone, Vec3(1, 1, 0), Vec3(0.2, -0.3, 1.5), 0, 400);
  goal(Goal::Line, e, kNone, Vec3(0, 1.5, 1), Vec3(1, 0.5, -0.2), 0, 250);
  goal(Goal::Length, b, e, Vec3::Zero(), Vec3::Zero(), 1.3, 500);  // stretched
  Solver s(m);
  NewtonSystem K;
  K.assemble(m, m.particles.position.data(), 0);
  const Eigen::SparseMatrix<double> lower = K.tangent();
  const Eigen::MatrixXd full = Eigen::MatrixXd(lower).selfadjointView<Eigen::Lower>();
  CHECK(K.rows() == 3 + 3 + 2 + 3);  // b, d and e free, c in x and y
  const double h = 1e-6;
  double worst = 0, scale = 0;
  for (ParticleId q : {b, c, d, e})
    for (int axis = 0; axis < 3; ++axis) {
      const int col = K.row(q, axis);
      if (col < 0) continue;
      std::vector<Vec3> plus, minus;
      Vec3& x = m.particles.position[q];
      x[axis] += h;
      s.compute_forces();
      plus.assign(m.particles.force.begin(), m.particles.force.end());
      x[axis] -= 2 * h;
      s.compute_forces();
      minus.assign(m.particles.force.begin(), m.particles.force.end());
      x[axis] += h;
      for (ParticleId p : {b, c, d, e})
        for (int r = 0; r < 3; ++r) {
          const int row = K.row(p, r);
          if (row < 0) continue;
          const double fd = -(plus[p][r] - minus[p][r]) / (2 * h);  // K = -dF/dx
          worst = std::max(worst, std::abs(full(row, col) - fd));
          scale = std::max(scale, std::abs(fd));
        }
    }
  MESSAGE("tangent against central differences: largest difference " << worst << " of " << scale << " N/m");
  CHECK(scale > 1e3);
  CHECK(worst < 1e-6 * scale);
  CHECK(NewtonSystem::unsupported(m) == nullptr);
}

TEST_CASE("newton: the prestressed net's equilibrium equals Leapfrog's and projective dynamics'") {
  Model mn, ml, mp;
  net(mn, 16), net(ml, 16), net(mp, 16);
  Solver sn(mn), sl(ml), sp(mp);
  const RunResult rn = relax(sn, Integrator::Newton, 1e-9, 50);
  // Kinetic damping gets no further than about 1e-7 N in reasonable time.
  const RunResult rl = relax(sl, Integrator::Leapfrog, 1e-7);
  const RunResult rp = relax(sp, Integrator::ProjectiveDynamics, 1e-9);
  REQUIRE(rn.converged);
  REQUIRE(rl.converged);
  REQUIRE(rp.converged);
  MESSAGE("newton " << rn.steps << " steps, leapfrog " << rl.steps << ", projective " << rp.steps << "; "
                    << sn.newton_work().iterations << " CG iterations, " << sn.newton_work().factorizations
                    << " factorisations");
  CHECK(rn.steps <= 8);
  // The softest mode (the net's first sag mode) is about 90 N/m per
  // particle: a residual of 1e-7 N leaves at most about 1e-9 m.
  MESSAGE("newton - leapfrog " << largest_distance(mn, ml) << " m, newton - projective " << largest_distance(mn, mp)
                               << " m");
  CHECK(largest_distance(mn, ml) < 1e-9);
  CHECK(largest_distance(mn, mp) < 1e-10);
  const double sag = -mn.particles.position[8 * 16 + 8].z();
  CHECK(sag > 0.01);
  CHECK(mn.check() == "");
  for (ParticleId p : mn.particles.integrated.raw()) CHECK(mn.particles.velocity[p] == Vec3::Zero());
}

TEST_CASE("newton: a cable net with a slack cable and a particle locked along z reaches Leapfrog's equilibrium") {
  auto build = [](Model& m) {
    const std::vector<ParticleId> g = net(m, 8, 2.0);
    // A cable across the net, too long to carry tension: slack at equilibrium.
    m.add_cable(g[1 * 8 + 1], g[6 * 8 + 6], Section{1e4, 0, 0, 0}, 20.0);
    // A short one that pulls (prestressed below its length): taut.
    m.add_cable(g[2 * 8 + 5], g[5 * 8 + 2], Section{1e4, 0, 500, 0}, 0);
    m.set_lock(g[3 * 8 + 3], kLockZ);  // stays in the plane, free in x and y
    return g;
  };
  Model mn, ml;
  const std::vector<ParticleId> g = build(mn);
  build(ml);
  Solver sn(mn), sl(ml);
  REQUIRE(relax(sn, Integrator::Newton, 1e-9, 50).converged);
  REQUIRE(relax(sl, Integrator::Leapfrog, 1e-7).converged);
  MESSAGE("newton - leapfrog " << largest_distance(mn, ml) << " m");
  CHECK(largest_distance(mn, ml) < 1e-9);
  CHECK(mn.particles.position[g[3 * 8 + 3]].z() == 0);
  CHECK((mn.particles.position[g[3 * 8 + 3]] - Vec3(3, 3, 0)).norm() > 1e-4);  // it moved in its plane
  const double slack = (mn.particles.position[g[6 * 8 + 6]] - mn.particles.position[g[1 * 8 + 1]]).norm();
  CHECK(slack < 20.0);  // shorter than its rest length: no force, no stiffness
  CHECK(sn.residual() < 1e-9);
}

TEST_CASE("newton: topology changes between steps, the symbolic analysis kept while the pattern holds") {
  Model m;
  const std::vector<ParticleId> g = net(m, 10);
  Solver s(m);
  REQUIRE(relax(s, Integrator::Newton, 1e-8, 50).converged);
  CHECK(s.newton_work().analyses == 1);
  // A new cable across two cells changes the pattern.
  m.add_cable(g[3 * 10 + 3], g[5 * 10 + 5], Section{1e4, 0, 2e3, 0}, 0);
  REQUIRE(relax(s, Integrator::Newton, 1e-8, 50).converged);
  CHECK(s.newton_work().analyses == 2);
  // Its rest length moves the revision, not the pattern: no new analysis.
  const std::uint64_t revision = m.revision;
  m.set_rest_length(g[3 * 10 + 3], g[5 * 10 + 5], 2.5);
  CHECK(m.revision != revision);
  REQUIRE(relax(s, Integrator::Newton, 1e-8, 50).converged);
  CHECK(s.newton_work().analyses == 2);
  // The same equilibrium as Leapfrog's on the changed model.
  Model l;
  const std::vector<ParticleId> h = net(l, 10);
  l.add_cable(h[3 * 10 + 3], h[5 * 10 + 5], Section{1e4, 0, 2e3, 0}, 0);
  l.set_rest_length(h[3 * 10 + 3], h[5 * 10 + 5], 2.5);
  Solver sl(l);
  REQUIRE(relax(sl, Integrator::Leapfrog, 1e-7).converged);
  CHECK(largest_distance(m, l) < 1e-8);
}

TEST_CASE("newton: a net held by anchor, plane, line and length goals reaches Leapfrog's equilibrium") {
  auto build = [](Model& m) {
    const std::vector<ParticleId> g = net(m, 8, 2.0);
    auto goal = [&](Goal::Kind k, ParticleId i, ParticleId j, Vec3 point, Vec3 direction, double length) {
      Goal x;
      x.kind = k, x.i = i, x.j = j, x.point = point, x.direction = direction, x.length = length, x.weight = 2e3;
      m.add_goal(x);
    };
    goal(Goal::Anchor, g[2 * 8 + 2], kNone, Vec3(2, 2, 0.5), Vec3::Zero(), 0);
    goal(Goal::Plane, g[5 * 8 + 5], kNone, Vec3(0, 0, -1), Vec3(0.1, 0, 1), 0);
    goal(Goal::Line, g[2 * 8 + 5], kNone, Vec3(5, 2, 0), Vec3(1, 1, 0.3), 0);
    goal(Goal::Length, g[4 * 8 + 1], g[4 * 8 + 6], Vec3::Zero(), Vec3::Zero(), 4.5);
  };
  Model mn, ml;
  build(mn), build(ml);
  Solver sn(mn), sl(ml);
  const RunResult rn = relax(sn, Integrator::Newton, 1e-9, 50);
  REQUIRE(rn.converged);
  REQUIRE(relax(sl, Integrator::Leapfrog, 1e-7).converged);
  MESSAGE("newton " << rn.steps << " steps; newton - leapfrog " << largest_distance(mn, ml) << " m");
  CHECK(largest_distance(mn, ml) < 1e-9);
}

TEST_CASE("newton: elements without a tangent are refused by name, nothing moved") {
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(1, 0, 0)),
                   c = m.add_particle(Vec3(2, 0, 0));
  m.set_lock(a, kLockTranslation);
  m.set_lock(c, kLockTranslation);
  m.set_load(b, Vec3(0, 0, -1));
  m.add_beam({a, b, c}, Section{1e4, 10, 0, 0});
  Solver s(m);
  s.settings.integrator = Integrator::Newton;
  std::string error;
  try {
    s.step();
  } catch (const ModelError& e) {
    error = e.what();
  }
  CHECK(error.find("newton") != std::string::npos);
  CHECK(error.find("hinges") != std::string::npos);
  CHECK(m.particles.position[b] == Vec3(1, 0, 0));
}

TEST_CASE("newton: a mechanism does not converge and the run says so") {
  // A free particle held by a slack cable only: no stiffness along the load.
  Model m;
  const ParticleId a = m.add_particle(Vec3(0, 0, 0)), b = m.add_particle(Vec3(0.5, 0, 0));
  m.set_lock(a, kLockTranslation);
  m.add_cable(a, b, Section{1e3, 0, 0, 0}, 1.0);
  m.set_load(b, Vec3(0, 0, -1));
  Solver s(m);
  s.settings.integrator = Integrator::Newton;
  const RunResult r = s.run(RunLimits{1e-6, 0, 500});
  CHECK_FALSE(r.converged);
  CHECK(r.verdict != Verdict::Converged);
  MESSAGE("verdict " << std::string(verdict_name(r.verdict)) << ": " << r.detail);
  CHECK(m.particles.position[b] == Vec3(0.5, 0, 0));  // no step lowered the residual: nothing moved
  CHECK(s.residual() == doctest::Approx(1.0));
}

TEST_CASE("newton: the same numbers on 1, 2 and 8 threads") {
  std::vector<std::vector<Vec3>> runs;
  for (int threads : {1, 2, 8}) {
    Model m;
    net(m, 24);
    Solver s(m);
    s.settings.threads = threads;
    s.settings.integrator = Integrator::Newton;
    for (int k = 0; k < 4; ++k) s.step();
    runs.emplace_back(m.particles.position.begin(), m.particles.position.end());
  }
  CHECK(runs[0] == runs[1]);
  CHECK(runs[0] == runs[2]);
}

TEST_CASE("newton: the multigrid preconditioner of large axis blocks reaches the factors' equilibrium") {
  // Below multigrid_rows the axis blocks are factored; this net is made
  // to take the multigrid cycle by lowering it, then compared with the
  // factors' run, also after a new cable changes the pattern.
  Model mf, mg;
  const std::vector<ParticleId> gf = net(mf, 40), gg = net(mg, 40);
  Solver sf(mf), sg(mg);
  const int rows = NewtonSystem::multigrid_rows;
  REQUIRE(rows > 38 * 38);
  const RunResult rf = relax(sf, Integrator::Newton, 1e-8, 50);
  NewtonSystem::multigrid_rows = 500;
  const RunResult rg = relax(sg, Integrator::Newton, 1e-8, 50);
  NewtonSystem::multigrid_rows = rows;
  REQUIRE(rf.converged);
  REQUIRE(rg.converged);
  std::fprintf(stderr, "factors: %llu steps, %llu CG iterations; multigrid: %llu steps, %llu CG iterations\n",
               (unsigned long long)rf.steps, (unsigned long long)sf.newton_work().iterations,
               (unsigned long long)rg.steps, (unsigned long long)sg.newton_work().iterations);
  CHECK(rg.steps <= rf.steps + 1);
  CHECK(largest_distance(mf, mg) < 1e-10);
  for (auto [m, g] : {std::pair{&mf, &gf}, std::pair{&mg, &gg}})
    m->add_cable((*g)[10 * 40 + 10], (*g)[20 * 40 + 25], Section{1e4, 0, 2e3, 0}, 0);
  REQUIRE(relax(sf, Integrator::Newton, 1e-8, 50).converged);
  NewtonSystem::multigrid_rows = 500;
  const bool converged = relax(sg, Integrator::Newton, 1e-8, 50).converged;
  NewtonSystem::multigrid_rows = rows;
  REQUIRE(converged);
  CHECK(sg.newton_work().analyses == 2);
  CHECK(largest_distance(mf, mg) < 1e-10);
  CHECK(mg.check() == "");
}
