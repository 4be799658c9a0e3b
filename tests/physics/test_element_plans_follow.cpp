// The CST and 6-DOF plans follow their own elements' edit lists
// (cst_plan.hpp, beam6_plan.hpp): a change elsewhere in the model leaves
// them as they are, an element whose values changed but whose ends did not
// is written again in place, anything else derives them again. After every
// update a plan (and a plan in a share's order, with its runs) must hold
// what one derived afresh holds, and a solver whose plans followed must
// step as one whose plans were derived at every step, bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/bar_chunks.hpp"
#include "physics/beam6_chunks.hpp"
#include "physics/beam6_plan.hpp"
#include "physics/cst_chunks.hpp"
#include "physics/cst_plan.hpp"
#include "physics/element_shares.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// A followed plan against a fresh one: the same entries bit for bit, and
// the same corner behind every slot an entry sums into. Slots are numbered
// as corners first came, so a followed plan's numbers differ, and it keeps
// the slots of corners no triangle projects onto any more (unused: their
// sums stay zero).
std::string first_difference(const CstPlan& a, const CstPlan& b) {
  if (!same_bits(a.i, b.i) || !same_bits(a.j, b.j) || !same_bits(a.k, b.k)) return "corners";
  if (!same_bits(a.sigma_warp, b.sigma_warp) || !same_bits(a.sigma_weft, b.sigma_weft) ||
      !same_bits(a.g_string, b.g_string))
    return "stresses";
  if (!same_bits(a.along_normal, b.along_normal) || !same_bits(a.analysis, b.analysis)) return "flags";
  if (a.slot.size() != b.slot.size()) return "slot count";
  for (std::size_t s = 0; s < a.slot.size(); ++s) {
    if ((a.slot[s] == CstPlan::kNoSlot) != (b.slot[s] == CstPlan::kNoSlot)) return "slots";
    if (a.slot[s] != CstPlan::kNoSlot && a.corner[a.slot[s]] != b.corner[b.slot[s]]) return "slots' corners";
  }
  std::vector<ParticleId> mine(a.corner), fresh(b.corner);
  std::sort(mine.begin(), mine.end());
  std::sort(fresh.begin(), fresh.end());
  if (std::adjacent_find(mine.begin(), mine.end()) != mine.end()) return "a corner with two slots";
  if (!std::includes(mine.begin(), mine.end(), fresh.begin(), fresh.end())) return "a corner without a slot";
  return "";
}

// The fused step's chunks against shares derived afresh: each chunk's
// triangles the same, in the model's order; its slots' corners those of
// the fresh shares, and besides them only unused slots' corners.
std::string first_difference(const CstChunks& a, const CstPlan& plan, const ElementShares& triangles,
                             const ElementShares& corners, const CstPlan& fresh) {
  const std::size_t chunks = triangles.begin.size() - 1;
  if (a.begin.size() < chunks) return "chunk count";
  std::vector<ParticleId> projected(fresh.corner);
  std::sort(projected.begin(), projected.end());
  for (std::size_t c = 0; c < a.begin.size(); ++c) {
    const std::vector<std::uint32_t> mine(a.triangles.begin() + a.begin[c], a.triangles.begin() + a.end[c]);
    const std::vector<std::uint32_t> theirs =
        c < chunks ? std::vector<std::uint32_t>(triangles.items.begin() + triangles.begin[c],
                                                triangles.items.begin() + triangles.begin[c + 1])
                   : std::vector<std::uint32_t>{};
    if (mine != theirs) return "triangles of chunk " + std::to_string(c);
    std::vector<ParticleId> mine_corners, their_corners;
    for (std::uint32_t k = a.corner_begin[c]; k < a.corner_end[c]; ++k) {
      const ParticleId p = plan.corner[a.corners[k]];
      if (std::binary_search(projected.begin(), projected.end(), p)) mine_corners.push_back(p);
    }
    if (c < chunks)
      for (std::uint32_t k = corners.begin[c]; k < corners.begin[c + 1]; ++k)
        their_corners.push_back(fresh.corner[corners.items[k]]);
    std::sort(mine_corners.begin(), mine_corners.end());
    std::sort(their_corners.begin(), their_corners.end());
    if (mine_corners != their_corners) return "corners of chunk " + std::to_string(c);
  }
  return "";
}

// Entries [a0, a0 + n) of a and [b0, b0 + n) of b: ends, frames, constants and runs (those ending at the range's end).
std::string first_difference(const Beam6Plan& a, const Beam6Plan& b, std::uint32_t a0, std::uint32_t b0,
                             std::uint32_t n) {
  auto differ = [&](const auto& x, const auto& y) {
    for (std::uint32_t e = 0; e < n; ++e)
      if (std::memcmp(&x[a0 + e], &y[b0 + e], sizeof(x[0])) != 0) return true;
    return false;
  };
  if (differ(a.elements, b.elements) || differ(a.i, b.i) || differ(a.j, b.j)) return "ends";
  for (int c = 0; c < 4; ++c)
    if (differ(a.end_i[c], b.end_i[c]) || differ(a.end_j[c], b.end_j[c])) return "beam-end frames";
  if (differ(a.L, b.L) || differ(a.EA, b.EA) || differ(a.prestress, b.prestress) || differ(a.k_static, b.k_static) ||
      differ(a.kr, b.kr) || differ(a.cz, b.cz) || differ(a.cy, b.cy) || differ(a.torsion, b.torsion))
    return "constants";
  for (std::uint32_t e = 0; e < n; ++e) {
    const std::uint32_t end_a = a0 + n, end_b = b0 + n;
    if (std::min(a.same_constants_to[a0 + e], end_a) - a0 != std::min(b.same_constants_to[b0 + e], end_b) - b0)
      return "runs of constants";
    if (std::min(a.same_ends_to[a0 + e], end_a) - a0 != std::min(b.same_ends_to[b0 + e], end_b) - b0)
      return "runs of ends";
  }
  return "";
}

std::string first_difference(const Beam6Chunks& a, const Beam6Chunks& b) {
  if (a.begin.size() != b.begin.size()) return "chunk count";
  for (std::size_t c = 0; c < a.begin.size(); ++c) {
    const std::uint32_t n = a.end[c] - a.begin[c];
    if (n != b.end[c] - b.begin[c]) return "entry count of chunk " + std::to_string(c);
    const std::string d = first_difference(a.plan, b.plan, a.begin[c], b.begin[c], n);
    if (!d.empty()) return d + " of chunk " + std::to_string(c);
  }
  return "";
}

std::string first_difference(const Beam6Plan& a, const Beam6Plan& b) {
  if (!same_bits(a.elements, b.elements) || !same_bits(a.i, b.i) || !same_bits(a.j, b.j)) return "ends";
  for (int c = 0; c < 4; ++c)
    if (!same_bits(a.end_i[c], b.end_i[c]) || !same_bits(a.end_j[c], b.end_j[c])) return "beam-end frames";
  if (!same_bits(a.L, b.L) || !same_bits(a.EA, b.EA) || !same_bits(a.prestress, b.prestress) ||
      !same_bits(a.k_static, b.k_static) || !same_bits(a.kr, b.kr) || !same_bits(a.cz, b.cz) ||
      !same_bits(a.cy, b.cy) || !same_bits(a.torsion, b.torsion))
    return "constants";
  if (!same_bits(a.same_constants_to, b.same_constants_to)) return "runs of constants";
  if (!same_bits(a.same_ends_to, b.same_ends_to)) return "runs of ends";
  return "";
}

// The fused step's split: one part per chunk of particles.
std::vector<ParticleId> chunk_split(const Model& m) {
  const std::uint32_t shift = BarChunks::chunk_shift_for(m.particles.capacity());
  std::vector<ParticleId> split;
  for (std::size_t c = 0; c <= (m.particles.capacity() >> shift) + 1; ++c) split.push_back(ParticleId(c) << shift);
  return split;
}

// s x s particles 1 m apart (chunks of 1024), the border locked: a CST
// membrane over the whole net, or a woven grid of 6-DOF beams with every
// third row's beam of another section (runs of constants that end).
struct Net {
  Model m;
  int s;
  std::vector<ParticleId> at;
  std::vector<BlockId> cables;
  Net(int side, bool membrane) : s(side) {
    for (int r = 0; r < s; ++r)
      for (int c = 0; c < s; ++c) {
        at.push_back(m.add_particle(Vec3(c, r, 0.01 * ((r * 5 + c * 3) % 7))));
        if (r == 0 || c == 0 || r == s - 1 || c == s - 1) m.set_lock(at.back(), kLockTranslation);
        else m.set_load(at.back(), Vec3(0, 0, -1));
      }
    if (membrane) {
      const BlockId patch = m.add_quad_grid(at, s, s, Section{1e5, 0, 1e3, 0});
      std::vector<Model::Triangle> triangles;
      for (int r = 0; r + 1 < s; ++r)
        for (int c = 0; c + 1 < s; ++c) {
          triangles.push_back({at[r * s + c], at[r * s + c + 1], at[(r + 1) * s + c + 1]});
          triangles.push_back({at[(r + 1) * s + c + 1], at[(r + 1) * s + c], at[r * s + c]});
        }
      Membrane film;
      film.mode = Membrane::FormFinding;
      film.sigma_warp = 1e3, film.sigma_weft = 2e3;
      m.set_patch_formulation(patch, film, triangles);
      return;
    }
    std::vector<ParticleId> line(std::size_t(s), 0);
    for (int r = 0; r < s; ++r) {
      for (int c = 0; c < s; ++c) line[c] = at[r * s + c];
      Section section{1e5, r % 3 ? 10.0 : 20.0, 0, 0};
      section.GJ = 5;
      m.set_beam_formulation(m.add_beam(line, section), 6);
    }
    for (int c = 0; c < s; ++c) {
      for (int r = 0; r < s; ++r) line[r] = at[r * s + c];
      Section section{1e5, 10, 0, 0};
      section.GJ = 5;
      m.set_beam_formulation(m.add_beam(line, section), 6);
    }
  }
  ParticleId interior(std::mt19937& rng) const {
    std::uniform_int_distribution<int> d(1, s - 3);
    return at[d(rng) * s + d(rng)];
  }
};

// Whether a and b are consecutive on a beam (rule 13 may have put a particle between them).
bool linked(const Model& m, ParticleId a, ParticleId b) {
  if (!m.particle_valid(a) || !m.particle_valid(b)) return false;
  try {
    return m.edge_rest_length(a, b) > 0;
  } catch (const ModelError&) {
    return false;
  }
}

// One random change: cables and particles (which no plan reads), a 6-DOF
// beam edge shortened (its element written again, its ends kept), rule 13
// on a beam, a particle made passive or active, a failed production.
// Stepping, only border particles go passive: a particle hung under a
// passive one would have nothing to hold it.
void change(Net& n, std::mt19937& rng, bool beams, bool stepping = false) {
  Model& m = n.m;
  const ParticleId p = n.interior(rng);
  switch (std::uniform_int_distribution<int>(0, 7)(rng)) {
    case 0:
    case 1:  // a cable across a cell
      if (m.particle_valid(p) && m.particle_valid(p + n.s + 1))
        n.cables.push_back(m.add_cable(p, p + n.s + 1, Section{1e5, 0, 0, 0}));
      break;
    case 2:  // one deleted
      if (!n.cables.empty()) {
        const std::size_t k = rng() % n.cables.size();
        if (m.block_valid(n.cables[k])) m.delete_cable(n.cables[k]);
        n.cables.erase(n.cables.begin() + std::ptrdiff_t(k));
      }
      break;
    case 3:  // a particle hung under another (new chunks appear past the net)
      if (m.particle_valid(p))
        m.add_cable(p, m.add_particle(m.particles.position[p] - Vec3(0, 0, 0.5)), Section{1e5, 0, 0, 0});
      break;
    case 4:
    case 5:  // a beam edge shortened, or a cable in the membrane
      if (beams && linked(m, p, p + 1)) m.set_rest_length(p, p + 1, 0.98 * m.edge_rest_length(p, p + 1));
      else if (!beams && !n.cables.empty() && m.block_valid(n.cables.back())) {
        const std::vector<ParticleId> ends = m.particles_of(n.cables.back());
        m.set_rest_length(ends[0], ends[1], 0.9 * m.edge_rest_length(ends[0], ends[1]));
      }
      break;
    case 6: {  // multi-resolution: elements go dormant or wake
      const ParticleId q = stepping ? n.at[1 + rng() % (n.s - 2)] : p;
      if (rng() % 3 == 0 && m.particle_valid(q)) m.set_passive(q, !m.particles.passive[q]);
      break;
    }
    case 7:  // a production that fails, or rule 13 on a beam
      if (beams && rng() % 2 && linked(m, p, p + 1)) {
        m.insert_particle(p, p + 1);
        break;
      }
      m.begin_transaction();
      m.add_cable(n.at[1], n.at[2], Section{1e5, 0, 0, 0});
      if (beams) m.set_rest_length(n.at[n.s + 1], n.at[n.s + 2], 0.5);
      m.rollback_transaction();
      break;
  }
}

}  // namespace

TEST_CASE("CST plan: follows its triangles, written, woken or put to sleep in place; the chunks' copy follows it") {
  Net n(45, true);  // 2025 particles: the hung ones open a third chunk
  std::mt19937 rng(5);
  CstPlan plan;
  CstChunks chunks;
  auto derive_shares = [](ElementShares& tri, ElementShares& cor, const CstPlan& p, const std::vector<ParticleId>& split) {
    tri.derive(p.generation(), split, std::uint32_t(p.i.size()), [&](std::uint32_t e, ParticleId* at) {
      at[0] = p.i[e], at[1] = p.j[e], at[2] = p.k[e];
      return 3;
    });
    cor.derive(p.generation(), split, std::uint32_t(p.corner.size()), [&](std::uint32_t s, ParticleId* at) {
      at[0] = p.corner[s];
      return 1;
    });
  };
  auto chunking = [&] {
    const std::uint32_t shift = BarChunks::chunk_shift_for(n.m.particles.capacity());
    return std::pair<std::uint32_t, std::size_t>(shift, (n.m.particles.capacity() >> shift) + 1);
  };
  // Three particles asleep from the start have no slot: woken (change
  // 150), they take new ones.
  const ParticleId sleepers[3] = {n.at[10 * 45 + 10], n.at[20 * 45 + 30], n.at[40 * 45 + 5]};
  for (ParticleId p : sleepers) n.m.set_passive(p, true);
  plan.update(n.m);
  REQUIRE(plan.i.size() == 2 * 44 * 44 - 3 * 6);
  chunks.update(plan, chunking().first, chunking().second);
  const std::size_t slots = plan.corner.size();
  int kept = 0, patched = 0, derived = 0, asleep = 0;
  for (int k = 0; k < 300; ++k) {
    const std::uint64_t before = plan.generation(), values = plan.values();
    const std::size_t awake = plan.i.size();
    if (k == 150)
      for (ParticleId p : sleepers) n.m.set_passive(p, false);
    else change(n, rng, false);
    plan.update(n.m);
    kept += plan.generation() == before;
    patched += plan.values() != values && plan.patched_from() == values;
    derived += plan.values() != values && plan.patched_from() != values;
    asleep += plan.i.size() < awake;
    chunks.update(plan, chunking().first, chunking().second);
    const std::vector<ParticleId> split = chunk_split(n.m);
    CstPlan fresh;
    fresh.derive(n.m);
    ElementShares fresh_triangles, fresh_corners;
    derive_shares(fresh_triangles, fresh_corners, fresh, split);
    INFO("after change " << k);
    REQUIRE(first_difference(plan, fresh) == "");
    REQUIRE(plan.current(n.m));
    REQUIRE(first_difference(chunks, plan, fresh_triangles, fresh_corners, fresh) == "");
  }
  // A particle made passive or active moves the awake triangles, each
  // time patched in place; nothing else writes them.
  CHECK(kept > 250);
  CHECK(asleep > 3);
  CHECK(patched == 300 - kept);
  CHECK(derived == 0);
  CHECK(plan.corner.size() >= slots + 3);  // the sleepers' new slots
  CHECK(chunks.derivations == 1);
}

TEST_CASE("6-DOF plan: written in place; the chunks' copy follows it, and plans in a share's order while ends stay") {
  Net n(45, false);
  std::mt19937 rng(7);
  Beam6Plan plan, in_chunks;
  Beam6Chunks chunks;
  ElementShares shares;
  auto chunking = [&] {
    const std::uint32_t shift = BarChunks::chunk_shift_for(n.m.particles.capacity());
    return std::pair<std::uint32_t, std::size_t>(shift, (n.m.particles.capacity() >> shift) + 1);
  };
  auto ends = [&](std::uint32_t e, ParticleId* at) {
    at[0] = plan.i[e], at[1] = plan.j[e];
    return 2;
  };
  plan.update(n.m);
  shares.derive(plan.generation(), chunk_split(n.m), std::uint32_t(plan.i.size()), ends);
  in_chunks.derive(plan, shares.items);
  chunks.update(plan, chunking().first, chunking().second);
  REQUIRE(shares.begin.size() > 2);  // more than one chunk: elements on two
  int followed = 0, patched = 0, derived = 0;
  for (int k = 0; k < 300; ++k) {
    const std::uint64_t before = plan.values();
    change(n, rng, true);
    plan.update(n.m);
    patched += plan.patched_from() == before;
    derived += plan.values() != before && plan.patched_from() != before;
    chunks.update(plan, chunking().first, chunking().second);
    const std::vector<ParticleId> split = chunk_split(n.m);
    const bool shares_follow = shares.follow(plan.generation(), split);
    if (!shares_follow) shares.derive(plan.generation(), split, std::uint32_t(plan.i.size()), ends);
    if (shares_follow && in_chunks.follow(plan)) ++followed;
    else in_chunks.derive(plan, shares.items);
    Beam6Plan fresh, fresh_in_chunks;
    fresh.derive(n.m);
    ElementShares fresh_shares;
    fresh_shares.derive(1, split, std::uint32_t(fresh.i.size()), [&](std::uint32_t e, ParticleId* at) {
      at[0] = fresh.i[e], at[1] = fresh.j[e];
      return 2;
    });
    fresh_in_chunks.derive(fresh, fresh_shares.items);
    Beam6Chunks fresh_chunks;
    fresh_chunks.derive(fresh, chunking().first, chunking().second);
    INFO("after change " << k);
    REQUIRE(first_difference(plan, fresh) == "");
    REQUIRE(first_difference(chunks, fresh_chunks) == "");
    REQUIRE(shares.begin == fresh_shares.begin);
    REQUIRE(shares.items == fresh_shares.items);
    REQUIRE(first_difference(in_chunks, fresh_in_chunks) == "");
  }
  CHECK(patched > 80);
  CHECK(derived == 0);  // every update patched the plan in the model's order
  CHECK(followed > 150);
  // The chunks' copy derived afresh only when a chunk ran out of room: rule
  // 13's particles all fall in the chunk after the grid's.
  CHECK(chunks.derivations <= 4);
  CHECK(chunks.patches > 100);
}

TEST_CASE("CST and 6-DOF plans: a solver whose plans followed steps as one whose plans were derived, bit for bit") {
  // The same changes and steps twice; the second time the triangles' and
  // the 6-DOF elements' edit lists are lost before every step. Leapfrog
  // (the fused step: the chunk shares and plan) and Velocity Verlet on two
  // threads (the element pass: the threads' shares and plan).
  for (const Integrator integrator : {Integrator::Leapfrog, Integrator::VelocityVerlet})
    for (const bool beams : {false, true}) {
      int moved = 0;  // net particles that moved, in the run whose plans followed
      auto run = [&](bool follow) {
        Net n(40, !beams);
        const std::vector<Vec3> start(n.m.particles.position.begin(), n.m.particles.position.end());
        std::mt19937 rng(9);
        Solver solver(n.m);
        solver.settings.integrator = integrator;
        solver.settings.threads = 2;
        solver.element_threads_from = 0;  // the element pass on threads
        if (integrator == Integrator::Leapfrog) REQUIRE(solver.fused_step_bytes() > 0);
        for (int k = 0; k < 120; ++k) {
          change(n, rng, beams, true);
          if (!follow) n.m.csts.edits.lose(), n.m.beam6s.edits.lose();
          solver.step();
        }
        std::vector<Vec3> x;
        for (ParticleId p = 0; p < n.m.particles.capacity(); ++p)
          if (n.m.particle_valid(p)) x.push_back(n.m.particles.position[p]);
        if (follow)
          for (ParticleId p : n.at) moved += (n.m.particles.position[p] - start[p]).norm() > 1e-6;
        return x;
      };
      INFO(integrator_name(integrator) << (beams ? ", 6-DOF grid" : ", membrane"));
      const std::vector<Vec3> followed = run(true), derived = run(false);
      REQUIRE(followed.size() == derived.size());
      int same = 0;
      for (std::size_t k = 0; k < followed.size(); ++k) same += followed[k] == derived[k];
      CHECK(same == int(followed.size()));
      CHECK(moved > 1000);
    }
}
