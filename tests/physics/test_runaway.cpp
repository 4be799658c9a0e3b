// Issue 13: a model that runs away to finite, absurd coordinates (1e62 ...
// 1e176 were seen) is stopped with an error naming the particle, measured
// against the model's own size; a healthy motion is not.
#include <doctest/doctest.h>

#include <string>

#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

// Two particles on a cable, true dynamics without damping: a = load / mass.
struct Pushed {
  Model m;
  Solver solver{m};
  ParticleId a, b;
  Pushed(double load_a, double load_b, bool lock_a) {
    a = m.add_particle(Vec3(0, 0, 0));
    b = m.add_particle(Vec3(1, 0, 0));
    m.add_cable(a, b, Section{1e-9, 0, 0, 0});
    for (ParticleId p : {a, b}) m.set_point_mass(p, 1);
    if (lock_a) m.set_lock(a, kLockTranslation);
    m.set_load(a, Vec3(load_a, 0, 0));
    m.set_load(b, Vec3(load_b, 0, 0));
    solver.settings.mass_mode = MassMode::Physical;
    solver.settings.damping = Damping::None;
  }
  std::string run(int steps) {
    try {
      for (int k = 0; k < steps; ++k) solver.step();
    } catch (const NumericalError& e) {
      return e.what();
    }
    return "";
  }
};

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("a particle that runs away from its model is stopped, named, at the next check") {
  // b accelerates at 1e6 m/s^2 away from the locked a: the 1 m model is
  // 1e6 times larger (5e5 t^2 > 1e6 m) after 2 s, found at step 64.
  Pushed p(0, 1e6, true);
  const std::string error = p.run(200);
  CAPTURE(error);
  CHECK(contains(error, "step 64: the model ran away: particle 1"));
  CHECK(contains(error, "the model's extent grew from 1 m at step 0 to"));
  CHECK(p.solver.steps() == 64);  // the check runs before the step: nothing moved after it
  CHECK(p.m.particles.position[p.b].allFinite());
}

TEST_CASE("a model that drifts away whole is stopped beyond 1e12 m") {
  // Both particles at 1e10 m/s^2: the extent stays 1 m, the coordinates pass
  // 1e12 m (5e9 t^2) by step 64.
  Pushed p(1e10, 1e10, false);
  const std::string error = p.run(200);
  CAPTURE(error);
  CHECK(contains(error, "step 64: the model ran away: particle"));
  CHECK(contains(error, "beyond 1e+12 m from the origin"));
}

TEST_CASE("a fast but bounded motion and a growing model are not runaways") {
  // 1e3 m/s^2 for 1000 steps: b ends 5e8 m away, 5e8 times the model's 1 m,
  // but every topology change measures the model again.
  Pushed p(0, 1e3, true);
  std::string error;
  for (int k = 0; k < 1000 && error.empty(); ++k) {
    if (k % 50 == 0) p.m.set_lock(p.b, 0);  // a change of the model (a production would do the same)
    error = p.run(1);
  }
  CHECK(error == "");
  CHECK(p.m.particles.position[p.b].x() > 1e5);
}

TEST_CASE("particles beyond 1e12 m are refused where they are made") {
  Model m;
  CHECK_THROWS_WITH_AS(m.add_particle(Vec3(0, 1e155, 0)),
                       "add_particle: position (0, 1e+155, 0) is beyond 1e+12 m from the origin", ModelError);
  CHECK(m.add_particle(Vec3(0, 1e12, -1e12)) == 0);
  CHECK(m.particle_count() == 1);
}
