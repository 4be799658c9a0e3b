// The solver evaluates spline-beam hinges in vectorised blocks
// (forces.cpp, hinge_block), writing out the arithmetic of hinge_forces
// (element_forces.hpp) term for term; the projections still call
// hinge_forces. The two must stay the same function: on a crooked beam,
// straight at rest, with straight runs (hinges without a plane) and more
// hinges than one block, the solver's forces equal hinge_forces summed in
// the model's order bit for bit, and its stiffnesses, beside the bars'
// own, to rounding.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "model/model.hpp"
#include "physics/element_forces.hpp"
#include "physics/solver.hpp"

using namespace tendril;

TEST_CASE("hinge blocks: the solver's hinge forces are hinge_forces' bit for bit") {
  Model m;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<ParticleId> ps;
  Vec3 x(0, 0, 0);
  for (int k = 0; k < 150; ++k) {
    // Every tenth run of five links straight: hinges with no plane.
    const Vec3 step = (k / 5) % 10 == 3 ? Vec3(0.7, 0, 0) : Vec3(0.5 + 0.3 * u(rng), 0.4 * u(rng), 0.4 * u(rng));
    x += step;
    ps.push_back(m.add_particle(x));
  }
  // The beam is straight at rest and bent here, so its hinges pull; its
  // bars are at their rest lengths (taken from these positions), so they
  // add exact zeros and the forces are the hinges' alone.
  m.add_beam(ps, Section{1e4, 2.5, 0, 0});
  REQUIRE(m.hinges.awake > 64);
  const Vec3* at = m.particles.position.data();
  std::vector<Vec3> F(m.particles.capacity(), Vec3::Zero());
  std::vector<double> S(m.particles.capacity(), 0.0);
  int straight = 0;
  for (const Hinge* h = m.hinges.awake_begin(); h != m.hinges.awake_end(); ++h) {
    const HingeForces f = hinge_forces(*h, at);
    straight += f.fi == Vec3::Zero();
    S[h->j] += f.ka + f.kb;
    F[h->i] += f.fi;
    F[h->k] += f.fk;
    F[h->j] -= f.fi + f.fk;
  }
  CHECK(straight > 0);
  double largest = 0;
  for (const Vec3& f : F) largest = std::max(largest, f.norm());
  CHECK(largest > 1);
  Solver s(m);
  s.compute_forces();
  // The bars add their EA / L to the stiffnesses (and, at rest length, an
  // exact zero to the forces).
  std::vector<double> bar_stiffness(m.particles.capacity(), 0.0);
  for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) {
    bar_stiffness[b->i] += b->EA / b->rest_length;
    bar_stiffness[b->j] += b->EA / b->rest_length;
  }
  int same = 0;
  double worst = 0;
  for (ParticleId p : ps) {
    same += m.particles.force[p] == F[p];
    worst = std::max(worst, std::abs(m.particles.stiffness[p] - bar_stiffness[p] - S[p]) / m.particles.stiffness[p]);
  }
  CHECK(same == int(ps.size()));
  CHECK(worst < 1e-12);
}
