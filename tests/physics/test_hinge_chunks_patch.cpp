// The fused step's hinge copy is patched from the hinges' edit list after a
// change, as the bar copy is (hinge_chunks.hpp): the patched copy must hold
// what a copy derived afresh holds - per chunk the same hinges in the same
// order with the same constants and marks - so that every particle's
// hinges are summed in the same order, bit for bit.
#include <doctest/doctest.h>

#include <random>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/hinge_chunks.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

std::string first_difference(const HingeChunks& a, const HingeChunks& b) {
  if (a.begin.size() != b.begin.size()) return "chunk count";
  for (std::size_t c = 0; c < a.begin.size(); ++c) {
    const std::string at = " of chunk " + std::to_string(c);
    if (a.end[c] - a.begin[c] != b.end[c] - b.begin[c]) return "hinge count" + at;
    for (std::uint32_t n = 0; n < a.end[c] - a.begin[c]; ++n) {
      const std::uint32_t e = a.begin[c] + n, f = b.begin[c] + n;
      if (a.hinge[e] != b.hinge[f] || a.i[e] != b.i[f] || a.j[e] != b.j[f] || a.k[e] != b.k[f]) return "ends" + at;
      if (a.EI[e] != b.EI[f] || a.rest[e] != b.rest[f]) return "constants" + at;
      if (n % HingeChunks::kBlock == 0 && a.same_block(std::uint32_t(c), e) != b.same_block(std::uint32_t(c), f))
        return "marks" + at;
    }
  }
  for (std::size_t e = 0; e < a.place_of.size(); ++e)
    if (a.hinge[a.place_of[e]] != e) return "place of hinge " + std::to_string(e);
  return a.place_of.size() == b.place_of.size() ? "" : "awake hinges";
}

// A woven grid of 64 beams each way through 64 x 64 particles (four
// chunks of 1024), its border locked, two sections.
struct Grid {
  Model m;
  std::vector<ParticleId> at;
  std::vector<BlockId> beams;
  Grid() {
    for (int r = 0; r < 64; ++r)
      for (int c = 0; c < 64; ++c) {
        at.push_back(m.add_particle(Vec3(c, r, 0.02 * ((r * 5 + c * 3) % 7))));
        if (r == 0 || c == 0 || r == 63 || c == 63) m.set_lock(at.back(), kLockTranslation);
      }
    std::vector<ParticleId> line(64);
    for (int r = 0; r < 64; ++r) {
      for (int c = 0; c < 64; ++c) line[c] = at[r * 64 + c];
      beams.push_back(m.add_beam(line, Section{1e5, r % 2 ? 10.0 : 20.0, 0, 0}));
    }
    for (int c = 0; c < 64; ++c) {
      for (int r = 0; r < 64; ++r) line[r] = at[r * 64 + c];
      beams.push_back(m.add_beam(line, Section{1e5, 10, 0, 0}));
    }
  }
};

// One random change of the kinds beam rules make.
void change(Grid& g, std::mt19937& rng) {
  Model& m = g.m;
  auto beam = [&]() -> BlockId {
    for (;;) {
      const BlockId b = g.beams[std::uniform_int_distribution<std::size_t>(0, g.beams.size() - 1)(rng)];
      if (m.block_valid(b) && m.particles_of(b).size() >= 4) return b;
    }
  };
  switch (std::uniform_int_distribution<int>(0, 6)(rng)) {
    case 0: {  // rule 13: a particle inserted on a beam edge
      const std::vector<ParticleId> ps = m.particles_of(beam());
      const std::size_t n = std::uniform_int_distribution<std::size_t>(0, ps.size() - 2)(rng);
      m.insert_particle(ps[n], ps[n + 1]);
      break;
    }
    case 1: {  // a beam edge shortened
      const std::vector<ParticleId> ps = m.particles_of(beam());
      const std::size_t n = std::uniform_int_distribution<std::size_t>(0, ps.size() - 2)(rng);
      m.set_rest_length(ps[n], ps[n + 1], 0.97 * m.edge_rest_length(ps[n], ps[n + 1]));
      break;
    }
    case 2: {  // rule 16: a beam split at an interior particle of its own (one rule 13 inserted)
      const BlockId b = beam();
      const std::vector<ParticleId> ps = m.particles_of(b);
      for (std::size_t n = 1; n + 1 < ps.size(); ++n)
        if (m.references_of(ps[n]).size() == 1 && !m.particles.passive[ps[n]]) {
          g.beams.push_back(m.split_beam(b, ps[n]).second);
          break;
        }
      break;
    }
    case 3: {  // multi-resolution: a particle's hinges go dormant or wake
      const ParticleId p = g.at[std::uniform_int_distribution<std::size_t>(0, g.at.size() - 1)(rng)];
      if (m.particle_valid(p)) m.set_passive(p, !m.particles.passive[p]);
      break;
    }
    case 4:  // rule 18
      if (rng() % 4 == 0) m.delete_beam(beam());
      break;
    case 5: {  // a new beam across the grid through existing particles
      std::vector<ParticleId> ps;
      for (int n = 0; n < 6; ++n) {
        const ParticleId p = g.at[std::uniform_int_distribution<std::size_t>(0, g.at.size() - 1)(rng)];
        if (m.particle_valid(p) && std::find(ps.begin(), ps.end(), p) == ps.end()) ps.push_back(p);
      }
      if (ps.size() >= 3) g.beams.push_back(m.add_beam(ps, Section{1e5, 5, 0, 0}));
      break;
    }
    case 6: {  // a production that fails: rolled back
      m.begin_transaction();
      const std::vector<ParticleId> ps = m.particles_of(beam());
      m.insert_particle(ps[0], ps[1]);
      m.rollback_transaction();
      break;
    }
  }
}

}  // namespace

TEST_CASE("hinge chunks: a patched copy holds what a fresh one holds, after every kind of beam change") {
  Grid g;
  std::mt19937 rng(3);
  auto chunking = [&] {
    const std::uint32_t shift = BarChunks::chunk_shift_for(g.m.particles.capacity());
    return std::pair<std::uint32_t, std::size_t>(shift, (g.m.particles.capacity() >> shift) + 1);
  };
  HingeChunks patched;
  patched.update(g.m, chunking().first, chunking().second);
  REQUIRE(patched.begin.size() == 5);
  for (int n = 0; n < 300; ++n) {
    change(g, rng);
    if (n % 3 == 0) change(g, rng);
    patched.update(g.m, chunking().first, chunking().second);
    HingeChunks fresh;
    fresh.derive(g.m, chunking().first, chunking().second);
    INFO("after change " << n);
    REQUIRE(first_difference(patched, fresh) == "");
  }
  // Derived afresh only when a chunk ran out of room: the particles rule
  // 13 inserts all fall in the chunk after the grid's, whose room is 32
  // hinges, then a sixteenth of its hinges more.
  CHECK(patched.derivations <= 4);
  CHECK(patched.patches >= 260);
}

TEST_CASE("hinge chunks: a solver whose copies were patched steps as one whose copies were derived, bit for bit") {
  // The same changes and steps twice; the second time every copy is
  // derived afresh (its edit lists lost before each step).
  auto run = [](bool patch) {
    Grid g;
    std::mt19937 rng(8);
    Solver solver(g.m);
    solver.settings.integrator = Integrator::Leapfrog;
    REQUIRE(solver.fused_step_bytes() > 0);  // the fused step, which reads the hinge copy
    for (int n = 0; n < 150; ++n) {
      change(g, rng);
      if (!patch) g.m.hinges.edits.lose(), g.m.bars.edits.lose();
      solver.step();
    }
    std::vector<Vec3> x;
    for (ParticleId p = 0; p < g.m.particles.capacity(); ++p)
      if (g.m.particle_valid(p)) x.push_back(g.m.particles.position[p]);
    return x;
  };
  const std::vector<Vec3> patched = run(true), derived = run(false);
  REQUIRE(patched.size() == derived.size());
  int same = 0;
  for (std::size_t n = 0; n < patched.size(); ++n) same += patched[n] == derived[n];
  CHECK(same == int(patched.size()));
  CHECK(patched.size() > 4000);
}
