// Projective dynamics chooses its local-global iterations when
// vie_iterations = 0, the default (projective.cpp, solver.hpp): one per step
// in form-finding, where it reaches the equilibrium a fixed count reaches;
// in dynamics as many as bring the last correction below 1e-3 of the step's
// motion, which on a falling chain follows converged steps (200 iterations)
// more closely than four fixed iterations do, with fewer of them. A number
// fixes the count, as before.
#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include "model/model.hpp"
#include "physics/solver.hpp"
#include "prestressed_net.hpp"

using namespace tendril;

namespace {

// 12 x 12 particles 1 m apart, bars on the grid edges (EA = 1e5 N,
// prestress 1e3 N), the boundary fixed, 1 N down on every other particle.
std::vector<Vec3> net_equilibrium(int iterations, std::uint64_t& steps, std::uint64_t& evaluations) {
  Model m;
  const std::vector<ParticleId> grid = test::prestressed_net(m, 12);
  Solver s(m);
  s.settings.integrator = Integrator::ProjectiveDynamics;
  s.settings.vie_iterations = iterations;
  const RunResult r = s.run(1e-9, 100000);
  CHECK(r.converged);
  steps = s.steps(), evaluations = s.force_evaluations();
  std::vector<Vec3> x;
  for (ParticleId p : grid) x.push_back(m.particles.position[p]);
  return x;
}

// A cable chain of 40 links, 12 m between supports 10 m apart, 2 kg/m,
// EA = 100 kN, released straight under gravity: positions after `steps`
// steps of dt with physical masses and no damping.
std::vector<Vec3> falling_chain(int iterations, double dt, int steps, double& evaluations_per_step) {
  Model m;
  m.gravity = Vec3(0, 0, -9.81);
  std::vector<ParticleId> ps;
  const int n = 40;
  for (int i = 0; i <= n; ++i) ps.push_back(m.add_particle(Vec3(10.0 * i / n, 0, 0)));
  for (int i = 0; i < n; ++i) m.add_cable(ps[i], ps[i + 1], Section{1e5, 0, 0, 2}, 12.0 / n);
  m.set_lock(ps.front(), kLockTranslation);
  m.set_lock(ps.back(), kLockTranslation);
  Solver s(m);
  s.settings.integrator = Integrator::ProjectiveDynamics;
  s.settings.mass_mode = MassMode::Physical;
  s.settings.damping = Damping::None;
  s.settings.dt = dt;
  s.settings.vie_iterations = iterations;
  for (int k = 0; k < steps; ++k) s.step();
  evaluations_per_step = double(s.force_evaluations()) / steps;
  std::vector<Vec3> x;
  for (ParticleId p : ps) x.push_back(m.particles.position[p]);
  return x;
}

double largest_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double d = 0;
  for (std::size_t k = 0; k < a.size(); ++k) d = std::max(d, (a[k] - b[k]).norm());
  return d;
}

}  // namespace

TEST_CASE("projective dynamics takes one iteration a step in form-finding and reaches the same equilibrium") {
  CHECK(SolverSettings{}.vie_iterations == 0);
  std::uint64_t steps1 = 0, evaluations1 = 0, steps4 = 0, evaluations4 = 0;
  const std::vector<Vec3> chosen = net_equilibrium(0, steps1, evaluations1);
  const std::vector<Vec3> four = net_equilibrium(4, steps4, evaluations4);
  // A step evaluates the residual once, then one local step per iteration.
  CHECK(evaluations1 == 2 * steps1);
  CHECK(evaluations4 == 5 * steps4);
  // Both at rest to 1e-9 N with bars of k = 1e5 N/m: the same shape to 1e-10 m.
  CHECK(largest_distance(chosen, four) < 1e-10);
  // And in fewer global solves.
  CHECK(steps1 < 4 * steps4);
}

TEST_CASE("projective dynamics iterates a dynamic step until its correction is small") {
  double per_step_ref = 0, per_step = 0, per_step4 = 0, per_step_coarse = 0;
  const std::vector<Vec3> converged = falling_chain(200, 1e-3, 500, per_step_ref);
  const std::vector<Vec3> chosen = falling_chain(0, 1e-3, 500, per_step);
  const std::vector<Vec3> four = falling_chain(4, 1e-3, 500, per_step4);
  CHECK(per_step4 == 5);
  // Measured: 3.5 iterations a step on average, 4.8 mm from the converged
  // steps after 0.5 s (the chain sags 1.23 m), four fixed iterations 7.4 mm.
  CHECK(per_step > 2);
  CHECK(per_step < 5);
  CHECK(largest_distance(chosen, converged) < 0.8 * largest_distance(four, converged));
  // A time step ten times longer needs more iterations: measured 14.2, 9 cm
  // from the converged steps, four fixed iterations 32 cm.
  const std::vector<Vec3> converged_coarse = falling_chain(200, 1e-2, 100, per_step_ref);
  const std::vector<Vec3> chosen_coarse = falling_chain(0, 1e-2, 100, per_step_coarse);
  const std::vector<Vec3> four_coarse = falling_chain(4, 1e-2, 100, per_step4);
  CHECK(per_step_coarse > per_step + 5);
  CHECK(per_step_coarse <= 1 + kAdaptiveIterations);
  CHECK(largest_distance(chosen_coarse, converged_coarse) < 0.5 * largest_distance(four_coarse, converged_coarse));
}
