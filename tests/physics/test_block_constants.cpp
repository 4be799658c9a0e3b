// The step takes a chunk's bars and hinges in blocks (forces.cpp), and a
// block whose elements share their constants bit for bit reads the first
// one's (BarChunks::same, HingeChunks::same). Only such blocks are marked,
// and the forces are those of every element's own constants, bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/hinge_chunks.hpp"
#include "physics/solver.hpp"

using namespace tendril;

// A chain of 300 bars: two blocks of equal bars and three blocks each with
// one bar unlike the others (its rest length, its EA, its being a cable),
// against eq. 3.32-3.35 evaluated bar by bar in the model's order.
TEST_CASE("bar blocks: a block of equal bars reads one bar's constants, the others each bar's, bit for bit") {
  Model m;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<ParticleId> ps;
  for (int k = 0; k <= 300; ++k) ps.push_back(m.add_particle(Vec3(k + u(rng), u(rng), u(rng))));
  const Section bar{1e4, 0, 10, 0};
  for (int k = 0; k < 300; ++k) {
    Section s = bar;
    double rest = 1.0;
    if (k == 150) rest = 1.1;           // block 2: one rest length
    if (k == 200) s.EA = 2e4;           // block 3: one EA
    if (k == 260) m.add_cable(ps[k], ps[k + 1], s, rest);  // block 4: one cable
    else m.add_elastic_bar(ps[k], ps[k + 1], s, rest);
  }
  BarChunks B;
  B.derive(m);
  REQUIRE(B.chunks.size() >= 1);
  REQUIRE(B.chunks[0].bars_end - B.chunks[0].bars_begin == 300);
  const auto marks = B.same.begin() + B.chunks[0].block_begin;  // the chunk's five blocks of bars
  CHECK(std::vector<std::uint8_t>(marks, marks + 5) == std::vector<std::uint8_t>{1, 1, 0, 0, 0});

  // Eq. 3.32-3.35 bar by bar, summed in the model's order from +0.
  const Vec3* x = m.particles.position.data();
  std::vector<Vec3> F(m.particles.capacity(), Vec3(0.0, 0.0, 0.0));
  std::vector<double> S(m.particles.capacity(), 0.0);
  for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) {
    REQUIRE(b->i < b->j);
    const Vec3 d = x[b->j] - x[b->i];
    const double L = std::sqrt(d.x() * d.x() + d.y() * d.y() + d.z() * d.z());
    const double k = b->EA / b->rest_length;
    const double T0 = b->prestress + k * (L - b->rest_length);
    const double T = b->tension_only && T0 < 0 ? 0.0 : T0;
    const double c = T / L;
    const Vec3 f(c * d.x(), c * d.y(), c * d.z());
    F[b->i] = Vec3(F[b->i].x() + f.x(), F[b->i].y() + f.y(), F[b->i].z() + f.z());
    F[b->j] = Vec3(F[b->j].x() - f.x(), F[b->j].y() - f.y(), F[b->j].z() - f.z());
    const double s = k + (T > 0 ? c : 0.0);
    S[b->i] += s;
    S[b->j] += s;
  }
  Solver solver(m);
  solver.compute_forces();
  int same_force = 0, same_stiffness = 0;
  for (ParticleId p : ps) {
    same_force += m.particles.force[p] == F[p];
    same_stiffness += m.particles.stiffness[p] == S[p];
  }
  CHECK(same_force == int(ps.size()));
  CHECK(same_stiffness == int(ps.size()));
}

// Two beams straight at rest and bent, of two sections (138 and 98
// hinges): blocks of one beam's hinges are marked, the block holding both
// is not; the fused step's forces (Leapfrog) equal the element pass's,
// which reads every hinge's own EI and rest curvature.
TEST_CASE("hinge blocks: a block of equal hinges reads one hinge's constants, the others each hinge's, bit for bit") {
  Model m;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  std::vector<ParticleId> a, b;
  for (int k = 0; k < 140; ++k) a.push_back(m.add_particle(Vec3(k, u(rng), u(rng))));
  for (int k = 0; k < 100; ++k) b.push_back(m.add_particle(Vec3(k, 5 + u(rng), u(rng))));
  m.add_beam(a, Section{1e4, 2.5, 0, 0});
  m.add_beam(b, Section{1e4, 5.0, 0, 0});
  Solver s(m);
  s.settings.integrator = Integrator::Leapfrog;
  REQUIRE(s.fused_step_bytes() > 0);  // the fused step takes this model
  const std::vector<Vec3> before = m.particles.position.raw();
  s.step();
  const std::vector<Vec3> fused = m.particles.force.raw();
  HingeChunks H;
  H.derive(m, BarChunks::chunk_shift_for(m.particles.capacity()), 1);
  REQUIRE(H.end[0] - H.begin[0] == 138 + 98);
  const auto marks = H.same.begin() + H.block_begin[0];  // the chunk's four blocks of hinges
  CHECK(std::vector<std::uint8_t>(marks, marks + 4) == std::vector<std::uint8_t>{1, 1, 0, 1});
  m.particles.position.raw() = before;
  s.compute_forces();
  double largest = 0;
  int same_force = 0;
  for (ParticleId p = 0; p < m.particles.capacity(); ++p) {
    largest = std::max(largest, fused[p].norm());
    same_force += m.particles.force[p] == fused[p];
  }
  CHECK(largest > 1);  // the hinges pull
  CHECK(same_force == int(m.particles.capacity()));
}
