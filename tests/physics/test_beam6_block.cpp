// The solver evaluates 6-DOF beams in vectorised blocks (forces.cpp,
// beam6_block), writing out the arithmetic of beam6_ends
// (element_forces.hpp) term for term; the projections still call
// beam6_ends. The two must stay the same function: on a crooked 6-DOF beam
// with its frames turned at random, more elements than one block, and a
// geometric factor other than 1, the solver's forces, torques and both
// stiffnesses equal beam6_ends summed in the model's order bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "model/model.hpp"
#include "model/frames.hpp"
#include "physics/beam6_plan.hpp"
#include "physics/element_forces.hpp"
#include "physics/frame_drift.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

// The solver's forces, torques and both stiffnesses against beam6_ends
// summed in the model's order, bit for bit; returns the largest torque.
double check_against_beam6_ends(Model& m, double gf) {
  const std::size_t n = m.particles.capacity();
  std::vector<Vec3> F(n, Vec3::Zero()), T(n, Vec3::Zero());
  std::vector<double> S(n, 0.0), K(n, 0.0);
  const Vec3* at = m.particles.position.data();
  const Quat* q = m.particles.orientation.data();
  for (const Beam6* b = m.beam6s.awake_begin(); b != m.beam6s.awake_end(); ++b) {
    const Beam6Ends e = beam6_ends(*b, at, q, gf);
    S[b->i] += e.k;
    S[b->j] += e.k;
    K[b->i] += e.kr;
    K[b->j] += e.kr;
    F[b->i] -= e.fj;
    F[b->j] += e.fj;
    T[b->i] += e.ta;
    T[b->j] += e.tb;
  }
  double largest = 0;
  for (const Vec3& t : T) largest = std::max(largest, t.norm());
  Solver solver(m);
  solver.settings.geometric_factor = gf;
  solver.compute_forces();
  int same_f = 0, same_t = 0, same_s = 0, same_k = 0;
  for (ParticleId p = 0; p < n; ++p) {
    same_f += m.particles.force[p] == F[p];
    same_t += m.particles.torque[p] == T[p];
    same_s += m.particles.stiffness[p] == S[p];
    same_k += m.particles.rot_stiffness[p] == K[p];
  }
  CHECK(same_f == int(n));
  CHECK(same_t == int(n));
  CHECK(same_s == int(n));
  CHECK(same_k == int(n));
  return largest;
}

// Frames turned away from the rest state and particles moved off their rest
// lengths: every term (axial, bending, twist) is at work.
void disturb(Model& m, const std::vector<ParticleId>& ps, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (ParticleId p : ps) {
    m.set_orientation(p, Quat(Eigen::AngleAxisd(0.3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized())) *
                             m.particles.orientation[p]);
    m.particles.position[p] += Vec3(0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng));
  }
}

}  // namespace

TEST_CASE("6-DOF beam blocks: the solver's beam forces are beam6_ends' bit for bit") {
  Model m;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<ParticleId> ps;
  Vec3 x(0, 0, 0);
  for (int k = 0; k < 150; ++k) {
    x += Vec3(0.5 + 0.3 * u(rng), 0.4 * u(rng), 0.4 * u(rng));
    ps.push_back(m.add_particle(x));
  }
  Section s{1e4, 2.5, 30, 0};
  s.EIy = 2.0, s.EIz = 3.5, s.GJ = 1.5;
  const BlockId beam = m.add_beam(ps, s);
  m.set_beam_formulation(beam, 6);
  REQUIRE(m.beam6s.awake > 64);
  disturb(m, ps, rng);
  CHECK(check_against_beam6_ends(m, 0.5) > 0.1);
}

// A member's elements of one length share their constants and, straight,
// their beam-end frames: the plan marks such runs and a block inside one
// reads its first entry's (forces.cpp). Runs that end inside a block, or
// span blocks, give beam6_ends' numbers all the same.
TEST_CASE("6-DOF beam blocks: runs of the same constants and ends, marked and read once, the same numbers") {
  Model m;
  Section s{1e4, 2.5, 30, 0};
  s.EIy = 2.0, s.EIz = 3.5, s.GJ = 1.5;
  // A straight beam of 150 elements, 0.5 m long up to element 100, then
  // 0.75 m (both exact in binary, and so are their sums).
  std::vector<ParticleId> straight;
  Vec3 x(0, 0, 0);
  for (int k = 0; k <= 150; ++k) {
    straight.push_back(m.add_particle(x));
    x += Vec3(k < 100 ? 0.5 : 0.75, 0, 0);
  }
  // A second straight beam of the first one's length, another section.
  std::vector<ParticleId> other;
  for (int k = 0; k <= 80; ++k) other.push_back(m.add_particle(Vec3(0.5 * k, 5, 0)));
  Section t = s;
  t.EIy = 4.0;
  m.set_beam_formulation(m.add_beam(straight, s), 6);
  m.set_beam_formulation(m.add_beam(other, t), 6);
  Beam6Plan plan;
  plan.derive(m);
  REQUIRE(plan.i.size() == 230);
  // The plan is in the model's order: the straight beam's elements, then the other's.
  CHECK(plan.same_constants_to[0] == 100);
  CHECK(plan.same_constants_to[37] == 100);
  CHECK(plan.same_constants_to[100] == 150);
  CHECK(plan.same_constants_to[150] == 230);
  CHECK(plan.same_ends_to[0] == 230);  // straight beams along their frames: the same ends throughout
  CHECK(plan.same_ends_to[229] == 230);
  std::mt19937 rng(11);
  disturb(m, straight, rng);
  disturb(m, other, rng);
  CHECK(check_against_beam6_ends(m, 0.5) > 0.1);
  CHECK(check_against_beam6_ends(m, 1.0) > 0.1);
}

// The frames' drift in blocks (frame_drift.cpp) writes out Eigen's
// quaternion product and normalization; kick_drift's other stages and the
// other integrators still turn frames with rotation_of. The same frames bit
// for bit, over more than one block, with rotations below rotation_of's
// small-angle bound, zero ones, inactive particles (left alone), half angles
// beyond the polynomials' bound (model/half_angle.hpp: libm's sine and
// cosine) and at it.
TEST_CASE("frame drift blocks: drift_frames turns frames as rotation_of and normalized do, bit for bit") {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  const int n = 2000;  // enough half angles of 0.1-0.5 that sines or cosines other than
                       // half_angle_sincos' would show (1-2 % of those differ from libm's)
  std::vector<ParticleId> ids;
  std::vector<Vec3> w(n);
  std::vector<Quat> R(n), expected(n);
  std::vector<std::uint8_t> active(n);
  const double dt = 0.7;
  for (int p = 0; p < n; ++p) {
    ids.push_back(ParticleId(p));
    const double scale = p % 17 == 3 ? 1e-14 : p % 23 == 5 ? 0.0 : p % 13 == 2 ? 4.0 : p % 5 == 1 ? 1.2 : 0.5;
    w[p] = scale * Vec3(u(rng), u(rng), u(rng));
    if (p % 29 == 11) w[p] = Vec3(std::nextafter(1.0, p % 3 - 1.0) / dt, 0, 0);  // |dt w| near 2 * 0.5
    if (p % 31 == 9) w[p] = Vec3(1e-12 * (1 + (p % 7 - 3) * 1e-15) / dt, 0, 0);  // |dt w|^2 about kSmallAngle2
    R[p] = Quat(Eigen::AngleAxisd(3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized()));
    active[p] = p % 11 != 7;
    expected[p] = active[p] ? Quat(Quat(rotation_of(dt * w[p]) * R[p]).normalized()) : R[p];
  }
  drift_frames(ids.data(), std::uint32_t(n), active.data(), dt, w.data(), R.data());
  int same = 0;
  for (int p = 0; p < n; ++p) same += R[p].coeffs() == expected[p].coeffs();
  CHECK(same == n);
}
