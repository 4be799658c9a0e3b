// The step's lean bar copy is patched from the bars' edit list after a
// change (bar_chunks.hpp): the patched copy must hold exactly what a copy
// derived afresh holds - per chunk the same bars in the same order with
// the same constants, the same marks, particles and inboxes - so that the
// step sums every force in the same order, bit for bit.
#include <doctest/doctest.h>

#include <random>
#include <utility>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

// The first difference between two copies' contents (their room and their
// places aside), or "".
std::string first_difference(const BarChunks& a, const BarChunks& b) {
  if (a.shift != b.shift || a.chunks.size() != b.chunks.size()) return "chunking";
  if (a.particles != b.particles) return "particles";
  for (std::size_t c = 0; c < a.chunks.size(); ++c) {
    const BarChunks::Chunk &x = a.chunks[c], &y = b.chunks[c];
    const std::string at = " of chunk " + std::to_string(c);
    if (x.particles_begin != y.particles_begin || x.particles_end != y.particles_end) return "particle range" + at;
    if (x.bars_end - x.bars_begin != y.bars_end - y.bars_begin) return "bar count" + at;
    if (x.crossing_begin - x.bars_begin != y.crossing_begin - y.bars_begin) return "crossing bars" + at;
    if (x.cables != y.cables) return "cable flag" + at;
    if (x.inbox_end - x.inbox_begin != y.inbox_end - y.inbox_begin || x.first_source != y.first_source)
      return "inbox" + at;
    for (std::uint32_t n = 0; n < x.bars_end - x.bars_begin; ++n) {
      const std::uint32_t e = x.bars_begin + n, f = y.bars_begin + n;
      if (a.i[e] != b.i[f] || a.j[e] != b.j[f] || a.model_bar[e] != b.model_bar[f]) return "ends" + at;
      if (a.k[e] != b.k[f] || a.rest[e] != b.rest[f] || a.prestress[e] != b.prestress[f] || a.cable[e] != b.cable[f])
        return "constants" + at;
      if (n % BarChunks::kBlock == 0 && a.same_block(x, e) != b.same_block(y, f)) return "marks" + at;
    }
    // An inbox entry: its particle, and its slot as (source chunk, place
    // among that chunk's crossing bars).
    auto source = [](const BarChunks& B, std::uint32_t slot) {
      for (std::size_t s = 0; s < B.chunks.size(); ++s)
        if (slot >= B.chunks[s].slot_begin && slot < B.chunks[s].slot_limit)
          return std::pair<std::size_t, std::uint32_t>(s, slot - B.chunks[s].slot_begin);
      return std::pair<std::size_t, std::uint32_t>(~std::size_t(0), 0);
    };
    for (std::uint32_t n = 0; n < x.inbox_end - x.inbox_begin; ++n) {
      if (a.inbox_particle[x.inbox_begin + n] != b.inbox_particle[y.inbox_begin + n]) return "inbox particle" + at;
      if (source(a, a.inbox_slot[x.inbox_begin + n]) != source(b, b.inbox_slot[y.inbox_begin + n]))
        return "inbox slot" + at;
    }
  }
  for (std::size_t e = 0; e < a.place_of.size(); ++e)
    if (a.model_bar[a.place_of[e]] != e) return "place of model bar " + std::to_string(e);
  return a.place_of.size() == b.place_of.size() ? "" : "awake bars";
}

// A 64 x 64 net of bars 1 m apart (four chunks of 1024 particles), its
// border locked; ids row by row.
std::vector<ParticleId> net(Model& m) {
  std::vector<ParticleId> grid;
  for (int r = 0; r < 64; ++r)
    for (int c = 0; c < 64; ++c) {
      grid.push_back(m.add_particle(Vec3(c, r, 0.01 * ((r * 7 + c * 3) % 5))));
      if (r == 0 || c == 0 || r == 63 || c == 63) m.set_lock(grid.back(), kLockTranslation);
    }
  m.add_quad_grid(grid, 64, 64, Section{1e5, 0, 1e3, 0});
  return grid;
}

// One random change of the kinds rules make, each touching a few bars.
void change(Model& m, std::vector<ParticleId>& grid, std::vector<BlockId>& cables, std::mt19937& rng) {
  auto any = [&] { return grid[std::uniform_int_distribution<std::size_t>(0, grid.size() - 1)(rng)]; };
  auto live = [&] {
    ParticleId p = any();
    while (!m.particle_valid(p)) p = any();
    return p;
  };
  auto live_cable = [&]() -> BlockId {
    while (!cables.empty()) {
      const std::size_t n = std::uniform_int_distribution<std::size_t>(0, cables.size() - 1)(rng);
      if (m.block_valid(cables[n])) return cables[n];
      cables.erase(cables.begin() + std::ptrdiff_t(n));
    }
    return kNone;
  };
  switch (std::uniform_int_distribution<int>(0, 7)(rng)) {
    case 0:  // a cable across a cell, else across the net (crossing chunks)
    case 1: {
      const ParticleId a = live(), b = rng() % 2 ? live() : a + 65;
      if (a != b && m.particle_valid(b)) cables.push_back(m.add_cable(a, b, Section{2e4, 0, 50, 0}, 1.5));
      break;
    }
    case 2:
      if (const BlockId c = live_cable(); c != kNone) m.delete_cable(c);
      break;
    case 3:
      if (const BlockId c = live_cable(); c != kNone) {
        const std::vector<ParticleId> ends = m.particles_of(c);
        m.set_rest_length(ends[0], ends[1], 0.9 * m.edge_rest_length(ends[0], ends[1]));
      }
      break;
    case 4: {  // multi-resolution: a particle's bars go dormant or wake
      const ParticleId p = live();
      m.set_passive(p, !m.particles.passive[p]);
      break;
    }
    case 5: {  // a new particle hung on a cable
      const ParticleId a = live(), p = m.add_particle(m.particles.position[a] + Vec3(0, 0, -0.5));
      grid.push_back(p);
      cables.push_back(m.add_cable(a, p, Section{2e4, 0, 0, 0}, 0.5));
      break;
    }
    case 6:  // a hung particle and its cable deleted
      for (std::size_t n = grid.size(); n-- > 4096;)
        if (m.particle_valid(grid[n]) && m.blocks_of(grid[n]).size() == 1) {
          m.delete_cable(m.blocks_of(grid[n])[0]);  // may take the particle along
          if (m.particle_valid(grid[n])) m.delete_particle(grid[n]);
          break;
        }
      break;
    case 7: {  // a production that fails: rolled back
      m.begin_transaction();
      m.add_cable(live(), live(), Section{2e4, 0, 0, 0}, 1.0);
      m.rollback_transaction();
      break;
    }
  }
}

}  // namespace

TEST_CASE("bar chunks: a patched copy holds what a fresh one holds, after every kind of change") {
  Model m;
  std::vector<ParticleId> grid = net(m);
  std::vector<BlockId> cables;
  std::mt19937 rng(11);
  BarChunks patched;
  patched.update(m);
  REQUIRE(patched.chunks.size() == 5);  // 4096 particles: ids 0..4095, chunks of 1024 and the one after
  for (int n = 0; n < 400; ++n) {
    change(m, grid, cables, rng);
    if (n % 3 == 0) change(m, grid, cables, rng);  // two changes between updates
    patched.update(m);
    BarChunks fresh;
    fresh.derive(m);
    const std::string difference = first_difference(patched, fresh);
    INFO("after change " << n);
    REQUIRE(difference == "");
  }
  // No update derived (rolled back productions too: the list holds
  // every write the log undid).
  CHECK(patched.derivations == 1);
  CHECK(patched.patches >= 380);  // (a change may find nothing to change)
  // A chunk out of room (its bars and a sixteenth more): derived afresh.
  for (int n = 0; n < 200; ++n) m.add_cable(grid[65], grid[130 + n % 800], Section{2e4, 0, 0, 0}, 1.0);
  patched.update(m);
  CHECK(patched.derivations == 2);
  BarChunks fresh;
  fresh.derive(m);
  CHECK(first_difference(patched, fresh) == "");
}

TEST_CASE("bar chunks: a solver whose copy was patched steps as one whose copy was derived, bit for bit") {
  Model m;
  std::vector<ParticleId> grid = net(m);
  std::vector<BlockId> cables;
  std::mt19937 rng(5);
  Solver patched(m);
  for (int n = 0; n < 200; ++n) {
    change(m, grid, cables, rng);
    patched.step();
  }
  patched.compute_forces();
  const std::vector<Vec3> force = m.particles.force;
  const std::vector<double> stiffness = m.particles.stiffness;
  Solver fresh(m);
  fresh.compute_forces();
  int same = 0, differ = 0;
  for (ParticleId p = 0; p < m.particles.capacity(); ++p) {
    if (!m.particle_valid(p)) continue;
    (force[p] == m.particles.force[p] && stiffness[p] == m.particles.stiffness[p] ? same : differ)++;
  }
  CHECK(same > 4000);
  CHECK(differ == 0);
}
