// Deterministic threads (DESIGN "Parallel and still deterministic"): the
// same model gives the same numbers, bit for bit, on 1, 2 and 8 threads, for
// every integrator, bars and the element loops (hinges, 6-DOF beams, CST
// triangles, each thread adding into the particles it owns); within one
// chunk the bar forces are summed exactly in the model's order.
#include <doctest/doctest.h>

#include <memory>
#include <string>
#include <vector>

#include "cst_scenes.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

// An s x s prestressed net, boundary locked, loaded out of plane, with a
// cable from a corner region to the far side (its force crosses many
// chunks: an inbox filled from another thread's range) and, optionally, a
// 3-DOF beam along the middle row (hinges: the general force path).
std::unique_ptr<Model> net(int s, bool beam) {
  auto m = std::make_unique<Model>();
  std::vector<ParticleId> g;
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m->add_particle(Vec3(c, r, 0.01 * ((r * 7 + c * 3) % 5)));
      g.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m->set_lock(p, kLockTranslation);
      else m->set_load(p, Vec3(0.1 * (c % 3), 0, -1));
    }
  m->add_quad_grid(g, s, s, Section{1e5, 0, 1e3, 0});
  m->add_cable(g[s + 1], g[(s - 2) * s + s - 2], Section{2e4, 0, 50, 0});
  if (beam) {
    std::vector<ParticleId> row(g.begin() + (s / 2) * s, g.begin() + (s / 2 + 1) * s);
    m->add_beam(row, Section{1e5, 50, 0, 0});
  }
  return m;
}

struct Snapshot {
  std::vector<Vec3> x, v, F;
  double residual;
  std::uint64_t resets;
};

Snapshot run(Integrator integrator, bool beam, int threads, int steps) {
  auto m = net(80, beam);  // 6400 particles: 7 chunks of 1024
  Solver s(*m);
  s.settings.integrator = integrator;
  s.settings.threads = threads;
  s.element_threads_from = 0;  // the force pass on the threads, however small the model
  for (int k = 0; k < steps; ++k) s.step();
  return {m->particles.position.raw(), m->particles.velocity.raw(), m->particles.force.raw(), s.residual(),
          s.kinetic_resets()};
}

// An s x s CST patch (form-finding, or analysis) with a 3-DOF beam along
// every inner row and a 6-DOF beam along every fourth column: every element
// kind whose loop runs on threads, at the particles where one thread's
// range ends and the next begins (ids 1024, 2048, ... lie on the 6-DOF
// columns) and crossing the ranges everywhere.
std::unique_ptr<Model> elements(int s, bool analysis) {
  auto m = std::make_unique<Model>();
  std::vector<ParticleId> g;
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m->add_particle(Vec3(c, r, 0.02 * ((r * 5 + c * 3) % 7)));
      g.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m->set_lock(p, kLockTranslation);
      else m->set_load(p, Vec3(0.05 * (c % 3), 0, -1));
    }
  const BlockId patch = m->add_quad_grid(g, s, s, Section{1e4, 0, 1e2, 0});
  m->set_patch_formulation(patch, test::test_film(analysis), test::grid_triangles(g, s));
  for (int r = 1; r < s - 1; ++r)
    m->add_beam(std::vector<ParticleId>(g.begin() + r * s, g.begin() + (r + 1) * s), Section{1e5, 20, 0, 0});
  for (int c = 4; c < s - 1; c += 4) {
    std::vector<ParticleId> column;
    for (int r = 0; r < s; ++r) column.push_back(g[r * s + c]);
    m->set_beam_formulation(m->add_beam(column, Section{1e5, 20, 0, 0}), 6);
  }
  return m;
}

}  // namespace

TEST_CASE("threads: hinges, 6-DOF beams and CST triangles on threads give the same numbers, bit for bit") {
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::RK4, Integrator::VariationalImplicitEuler}) {
    for (bool analysis : {false, true}) {
      const std::string name = std::string(integrator_name(integrator)) + (analysis ? ", analysis" : ", form-finding");
      CAPTURE(name);
      auto run = [&](int threads) {
        auto m = elements(72, analysis);  // 5184 particles: 6 chunks of 1024
        Solver s(*m);
        s.settings.integrator = integrator;
        s.settings.threads = threads;
        s.element_threads_from = 0;  // every element loop on the threads, however small
        for (int k = 0; k < 40; ++k) s.step();
        return std::make_pair(Snapshot{m->particles.position.raw(), m->particles.velocity.raw(),
                                       m->particles.force.raw(), s.residual(), s.kinetic_resets()},
                              m->particles.orientation.raw());
      };
      const auto one = run(1);
      REQUIRE(one.first.residual > 0);
      for (int threads : {2, 3, 8}) {
        CAPTURE(threads);
        const auto many = run(threads);
        CHECK(many.first.x == one.first.x);
        CHECK(many.first.v == one.first.v);
        CHECK(many.first.F == one.first.F);
        CHECK(many.first.residual == one.first.residual);
        CHECK(many.second == one.second);
      }
    }
  }
}

TEST_CASE("threads: 1, 2 and 8 threads give the same numbers, bit for bit, with every integrator") {
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::SymplecticEuler, Integrator::VelocityVerlet,
                                Integrator::RK4, Integrator::VariationalImplicitEuler, Integrator::ProjectiveDynamics}) {
    for (bool beam : {false, true}) {
      const std::string name = std::string(integrator_name(integrator)) + (beam ? " + beam" : "");
      CAPTURE(name);
      const int steps = integrator == Integrator::ProjectiveDynamics ? 20 : 60;
      const Snapshot one = run(integrator, beam, 1, steps);
      REQUIRE(one.residual > 0);
      for (int threads : {2, 8}) {
        CAPTURE(threads);
        const Snapshot many = run(integrator, beam, threads, steps);
        CHECK(many.x == one.x);
        CHECK(many.v == one.v);
        CHECK(many.F == one.F);
        CHECK(many.residual == one.residual);
        CHECK(many.resets == one.resets);
      }
    }
  }
}

TEST_CASE("threads: within one chunk, bar forces are summed in the model's bar order") {
  // 30 x 30 = 900 particles fit one chunk: the forces must equal, exactly,
  // the plain loop over the model's bars (eq. 3.32-3.33) in its order.
  auto m = net(30, false);
  REQUIRE(m->particles.capacity() <= 1024);
  const Particles& P = m->particles;
  for (int k = 0; k < 3; ++k) Solver(*m).step();  // off the grid's symmetry
  Solver s(*m);
  s.compute_forces();
  std::vector<Vec3> F(P.capacity(), Vec3::Zero());
  std::vector<double> S(P.capacity(), 0.0);
  for (ParticleId p : P.integrated.raw()) F[p] = P.load[p] + (P.point_mass[p] + P.lumped_mass[p]) * m->gravity;
  for (const Bar* b = m->bars.awake_begin(); b != m->bars.awake_end(); ++b) {
    const Vec3 d = P.position[b->j] - P.position[b->i];
    const double L = d.norm(), k = b->EA / b->rest_length;
    double T = b->prestress + k * (L - b->rest_length);
    if (b->tension_only && T < 0) T = 0;
    const Vec3 f = (T / L) * d;
    F[b->i] += f;
    F[b->j] -= f;
    const double st = k + (T > 0 ? T / L : 0.0);
    S[b->i] += st;
    S[b->j] += st;
  }
  for (ParticleId p : P.integrated.raw()) {
    CAPTURE(p);
    CHECK(P.force[p] == F[p]);
    CHECK(P.stiffness[p] == S[p]);
  }
}

TEST_CASE("threads: a model that grows into more chunks keeps its forces") {
  // Adding particles moves the capacity past a chunk boundary: the lean
  // bars are derived again, and the forces match a fresh solver's.
  auto m = net(40, false);  // 1600 particles: 2 chunks
  Solver s(*m);
  s.settings.threads = 2;
  for (int k = 0; k < 10; ++k) s.step();
  const ParticleId far = m->add_particle(Vec3(20, 20, 5));
  m->add_cable(0, far, Section{1e4, 0, 10, 0});
  for (int k = 0; k < 10; ++k) s.step();
  s.compute_forces();
  const std::vector<Vec3> before = m->particles.force.raw();
  Solver fresh(*m);
  fresh.compute_forces();
  CHECK(m->particles.force.raw() == before);
}
