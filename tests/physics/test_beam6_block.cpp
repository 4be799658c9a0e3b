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
#include "physics/element_forces.hpp"
#include "physics/frame_drift.hpp"
#include "physics/solver.hpp"

using namespace tendril;

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
  // Frames turned away from the rest state and particles moved off their
  // rest lengths: every term (axial, bending, twist) is at work.
  for (ParticleId p : ps) {
    m.set_orientation(p, Quat(Eigen::AngleAxisd(0.3 * u(rng), Vec3(u(rng), u(rng), u(rng)).normalized())) *
                             m.particles.orientation[p]);
    m.particles.position[p] += Vec3(0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng));
  }
  const double gf = 0.5;
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
  CHECK(largest > 0.1);
  Solver solver(m);
  solver.settings.geometric_factor = gf;
  solver.compute_forces();
  int same_f = 0, same_t = 0, same_s = 0, same_k = 0;
  for (ParticleId p : ps) {
    same_f += m.particles.force[p] == F[p];
    same_t += m.particles.torque[p] == T[p];
    same_s += m.particles.stiffness[p] == S[p];
    same_k += m.particles.rot_stiffness[p] == K[p];
  }
  CHECK(same_f == int(ps.size()));
  CHECK(same_t == int(ps.size()));
  CHECK(same_s == int(ps.size()));
  CHECK(same_k == int(ps.size()));
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
