// The fused bar step (issue 18): when every particle slot is integrated,
// Leapfrog and Symplectic Euler drift in the kick's pass (into a second
// position buffer swapped in at the end); otherwise in a second pass. Both
// forms must give the same numbers, bit for bit, through kinetic peaks,
// with and without gravity, on 1 and 2 threads.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "cst_scenes.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

// A 60 x 60 prestressed net (3600 particles, 4 chunks), boundary locked,
// loaded out of plane; `passive_extra` adds one unconnected passive
// particle, which makes the step take its two-pass form and changes
// nothing else (the same chunks, the same sums).
std::unique_ptr<Model> net(bool passive_extra, bool gravity) {
  constexpr int s = 60;
  auto m = std::make_unique<Model>();
  std::vector<ParticleId> g;
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m->add_particle(Vec3(c, r, 0.01 * ((r * 7 + c * 3) % 5)));
      g.push_back(p);
      if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m->set_lock(p, kLockTranslation);
      else m->set_load(p, Vec3(0.1 * (c % 3), 0, -1));
    }
  m->add_quad_grid(g, s, s, Section{1e5, 0, 1e3, 0.5});
  m->add_cable(g[s + 1], g[(s - 2) * s + s - 2], Section{2e4, 0, 50, 0});
  if (gravity) m->gravity = Vec3(0, 0, -9.81);
  if (passive_extra) m->set_passive(m->add_particle(Vec3(100, 100, 100)), true);
  return m;
}

struct Run {
  std::vector<Vec3> x, v, F;
  std::vector<double> residuals;
  std::uint64_t resets;
};

Run run(Integrator integrator, bool passive_extra, bool gravity, int threads, double& bytes) {
  auto m = net(passive_extra, gravity);
  Solver s(*m);
  s.settings.integrator = integrator;
  s.settings.threads = threads;
  Run r;
  for (int k = 0; k < 300; ++k) {
    s.step();
    r.residuals.push_back(s.residual());
  }
  bytes = s.fused_step_bytes();
  const std::size_t n = 60 * 60;
  r.x.assign(m->particles.position.raw().begin(), m->particles.position.raw().begin() + n);
  r.v.assign(m->particles.velocity.raw().begin(), m->particles.velocity.raw().begin() + n);
  r.F.assign(m->particles.force.raw().begin(), m->particles.force.raw().begin() + n);
  r.resets = s.kinetic_resets();
  return r;
}

}  // namespace

TEST_CASE("fused step: drifting in the kick's pass gives the two-pass numbers, bit for bit") {
  for (Integrator integrator : {Integrator::Leapfrog, Integrator::SymplecticEuler})
    for (bool gravity : {false, true})
      for (int threads : {1, 2}) {
        const std::string name = std::string(integrator_name(integrator)) + (gravity ? " + gravity" : "");
        CAPTURE(name);
        CAPTURE(threads);
        double one_pass_bytes = 0, two_pass_bytes = 0;
        const Run one = run(integrator, false, gravity, threads, one_pass_bytes);
        const Run two = run(integrator, true, gravity, threads, two_pass_bytes);
        REQUIRE(one.resets > 0);  // the kinetic peaks' move back was exercised
        CHECK(one.x == two.x);
        CHECK(one.v == two.v);
        CHECK(one.F == two.F);
        CHECK(one.residuals == two.residuals);
        CHECK(one.resets == two.resets);
        // The one-pass form saves the drift pass: it reads the id, position
        // and velocity and writes the position again, 52 bytes a particle
        // more than writing the new position in the kick's pass.
        CHECK(one_pass_bytes > 0);
        CHECK(two_pass_bytes - one_pass_bytes == doctest::Approx(52.0 * 3600).epsilon(1e-12));
      }
}

TEST_CASE("fused step: its kick, four particles in lanes, gives kick_drift's velocities and positions, bit for bit") {
  // A stiff anchor on a locked corner at its own position adds +0 to the
  // corner's force and only moves its mass: nothing else changes, but the
  // step is no longer the fused one (goals take the element pass and
  // kick_drift's scalar loop over the particles). Until the first kinetic
  // peak (the kinetic energy is summed in another order there, chunk by
  // chunk) every particle must move alike. The net's locked boundary sends
  // some groups of four through the fused kick's scalar loop, the interior
  // through its lanes.
  for (bool gravity : {false, true}) {
    CAPTURE(gravity);
    auto fused = net(false, gravity), plain = net(false, gravity);
    Goal anchor;
    anchor.kind = Goal::Anchor;
    anchor.i = 0;
    anchor.point = plain->particles.position[0];
    anchor.weight = 1e3;
    plain->add_goal(anchor);
    Solver a(*fused), b(*plain);
    REQUIRE(a.fused_step_bytes() > 0);
    REQUIRE(b.fused_step_bytes() == 0);
    int compared = 0;
    for (int k = 0; k < 40 && a.kinetic_resets() == 0 && b.kinetic_resets() == 0; ++k) {
      a.step();
      b.step();
      if (a.kinetic_resets() != 0 || b.kinetic_resets() != 0) break;
      CHECK(fused->particles.position.raw() == plain->particles.position.raw());
      CHECK(fused->particles.velocity.raw() == plain->particles.velocity.raw());
      ++compared;
    }
    CHECK(compared >= 5);
  }
}

namespace {

// A 40 x 40 grid of 3-DOF spline beams along its rows and columns (1600
// particles, two chunks of 1024 ids: the columns' hinges at rows 25 and 26
// have ends in both), one more beam across the grid with its ids falling,
// two edges locked, loaded out of plane and along x; with `membrane` 1 or 2
// a CST patch over the grid too, in form-finding or in analysis (its
// triangles and projected corners on both sides of the chunks' boundary);
// with `six_dof` every fourth column a 6-DOF beam (ids 1024 and 1028 on
// them).
std::unique_ptr<Model> beam_grid(int membrane, bool six_dof = false) {
  constexpr int s = 40;
  auto m = std::make_unique<Model>();
  std::vector<ParticleId> g;
  for (int r = 0; r < s; ++r)
    for (int c = 0; c < s; ++c) {
      const ParticleId p = m->add_particle(Vec3(0.1 * c, 0.1 * r, 0.002 * ((r * 7 + c * 3) % 5)));
      g.push_back(p);
      if (r == 0 || r == s - 1) m->set_lock(p, kLockTranslation);
      else m->set_load(p, Vec3(0.05 * (c % 3), 0, -1));
    }
  if (membrane > 0) {
    const BlockId patch = m->add_quad_grid(g, s, s, Section{1e4, 0, 1e2, 0});
    m->set_patch_formulation(patch, test::test_film(membrane == 2), test::grid_triangles(g, s));
  }
  const Section section{1e5, 20, 0, 0};
  for (int r = 0; r < s; ++r) m->add_beam(std::vector<ParticleId>(g.begin() + r * s, g.begin() + (r + 1) * s), section);
  for (int c = 0; c < s; ++c) {
    std::vector<ParticleId> column;
    for (int r = 0; r < s; ++r) column.push_back(g[r * s + c]);
    const BlockId beam = m->add_beam(column, section);
    if (six_dof && c % 4 == 0) m->set_beam_formulation(beam, 6);
  }
  std::vector<ParticleId> falling;
  for (int r = s - 2; r >= 1; r -= 3) falling.push_back(m->add_particle(Vec3(0.1 * r, 0.1 * r, 0.3)));
  m->add_beam(falling, section);
  m->set_lock(falling.front(), kLockTranslation);
  m->set_lock(falling.back(), kLockTranslation);
  return m;
}

}  // namespace

TEST_CASE("fused step: hinges, 6-DOF beams and CST triangles are summed as the element pass sums them, on any thread count") {
  for (int membrane : {0, 1, 2})
    for (bool six_dof : {false, true})
    for (Integrator integrator : {Integrator::Leapfrog, Integrator::SymplecticEuler}) {
      const std::string name = std::string(integrator_name(integrator)) + (six_dof ? ", 6-DOF columns" : "") +
                               (membrane == 0 ? "" : membrane == 1 ? ", CST form-finding" : ", CST analysis");
      CAPTURE(name);
      std::vector<Vec3> x1, v1, w1;
      std::vector<Quat> R1;
      std::uint64_t resets1 = 0;
      for (int threads : {1, 2, 3}) {
        CAPTURE(threads);
        auto m = beam_grid(membrane, six_dof);
        Particles& P = m->particles;
        Solver s(*m);
        s.settings.integrator = integrator;
        s.settings.threads = threads;
        REQUIRE(s.fused_step_bytes() > 0);  // the fused step takes this model
        for (int k = 0; k < 200; ++k) {
          const std::vector<Vec3> before = P.position.raw();
          const std::vector<Quat> frames = P.orientation.raw();
          s.step();
          if (k % 50 != 0) continue;
          // The forces and stiffnesses the fused step kicked with are those
          // of the element pass (bars, hinges, then triangles) at the
          // step's positions.
          const std::vector<Vec3> after = P.position.raw(), fused_F = P.force.raw(), fused_T = P.torque.raw();
          const std::vector<double> fused_S = P.stiffness.raw(), fused_K = P.rot_stiffness.raw();
          const std::vector<Quat> turned = P.orientation.raw();
          P.position.raw() = before;
          P.orientation.raw() = frames;
          s.compute_forces();
          CHECK(P.force.raw() == fused_F);
          CHECK(P.stiffness.raw() == fused_S);
          CHECK(P.torque.raw() == fused_T);
          CHECK(P.rot_stiffness.raw() == fused_K);
          P.position.raw() = after;
          P.orientation.raw() = turned;
        }
        CHECK(m->check() == "");
        if (threads == 1) {
          x1 = P.position.raw(), v1 = P.velocity.raw(), w1 = P.angular_velocity.raw(), R1 = P.orientation.raw();
          resets1 = s.kinetic_resets();
          REQUIRE(resets1 > 0);  // the kinetic peaks' move back was exercised
          if (six_dof) REQUIRE(s.torque_residual() > 0);  // the frames turned
        } else {
          CHECK(P.position.raw() == x1);
          CHECK(P.velocity.raw() == v1);
          CHECK(P.angular_velocity.raw() == w1);
          CHECK(P.orientation.raw() == R1);
          CHECK(s.kinetic_resets() == resets1);
        }
      }
    }
}

TEST_CASE("fused step: another integrator takes over after it (its scratch sized, though the drift used one buffer)") {
  // The one-pass drift sizes the buffer of new positions alone; RK4 and
  // the midpoint rule need their other stage buffers too (a crash before).
  for (Integrator next : {Integrator::RK4, Integrator::Midpoint, Integrator::VelocityVerlet}) {
    CAPTURE(integrator_name(next));
    auto m = net(false, false);
    Solver s(*m);
    for (int k = 0; k < 100; ++k) s.step();
    s.settings.integrator = next;
    const RunResult r = s.run(1e-3, 300);
    CHECK(r.steps == 300);
    CHECK(std::isfinite(s.residual()));
    for (const Vec3& x : m->particles.position.raw()) CHECK(x.allFinite());
    CHECK(m->check() == "");
  }
}

TEST_CASE("fused step: a zero-length link across two chunks stops the step naming its first hinge, nothing moved") {
  // Particles 1023 and 1024 (row 25 of the grid) lie in two chunks: both
  // chunks find the hinges through that link; the first in the model's
  // order, at particle 1023, is named.
  auto m = beam_grid(0);
  Particles& P = m->particles;
  Solver s(*m);
  for (int k = 0; k < 20; ++k) s.step();
  P.position[1024] = P.position[1023];
  const std::vector<Vec3> positions = P.position.raw();
  const std::string what = [&] {
    try {
      s.step();
      return std::string("no error");
    } catch (const NumericalError& e) {
      return std::string(e.what());
    }
  }();
  CHECK(what.find("at particle 1023") != std::string::npos);
  CHECK(what.find("particles 1023 and 1024 coincide") != std::string::npos);
  CHECK(what.find("velocities were reset, no particle was moved") != std::string::npos);
  CHECK(P.position.raw() == positions);
  for (std::size_t p = 0; p < P.capacity(); ++p) {
    CHECK(P.velocity[p] == Vec3::Zero());
    CHECK(P.force[p].allFinite());
    CHECK(std::isfinite(P.stiffness[p]));
  }
  CHECK(m->check() == "");
}
