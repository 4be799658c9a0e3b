#pragma once
// The 6-DOF step's lean copy of the awake Beam6 elements (DESIGN principle
// 1: a derived cache, like BarChunks): structure of arrays holding what the
// force reads, with the quotients of constants that eq. 3.46-3.49 divide
// every step stored once (the same expressions, so the same numbers).
// A plan is in the model's order, or in the order a share of the elements
// is evaluated in (the fused step's chunks, the threads of the element
// pass: ElementShares::items), so that the element loop reads its
// constants in place instead of copying them element by element.
// The elements of a member usually share their section and length, and
// often their beam-end frames: runs of entries with the same constants, or
// the same ends, are marked, so that a block of the step inside such a run
// reads one entry's instead of streaming a column each.
// The plan in the model's order follows the elements' own edit list
// (m.beam6s.edits): a change elsewhere in the model leaves it as it is,
// and each element written, woken or put to sleep is written again in
// place (its runs marked again); the chunks' copy (beam6_chunks.hpp)
// follows the same list. A plan in a share's order follows it while no
// element's ends move.
#include <array>
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace tendril {

// The step evaluates a plan's entries in blocks of this many (forces.cpp).
inline constexpr std::uint32_t kBeam6Block = 64;

struct Beam6Plan {
  // Up to date: no element written, woken or put to sleep since the last update.
  bool current(const Model& m) const;
  // Brings the plan in the model's order up to date and restarts m.beam6s.edits.
  void update(Model& m);
  void derive(const Model& m);
  // The entries items[0 .. n) of `from` (in the model's order), in that order.
  void derive(const Beam6Plan& from, const std::vector<std::uint32_t>& items);
  // A plan derived from `from` brought up to date with it: the entries of
  // the elements `from` wrote again in its last update written again too.
  // False when that is not enough (`from` was derived again, or updated
  // twice since): derive it again from the share's items.
  bool follow(const Beam6Plan& from);
  // Moves whenever the elements' ends or number may have (what the shares
  // are derived from), not when an element's values alone were written.
  std::uint64_t generation() const { return generation_; }
  // Moves at every update; patched() lists the entries the last one wrote
  // (ascending; past the plan's end: elements gone), when it moved from
  // patched_from(), else patched_from() matches no stamp.
  std::uint64_t values() const { return values_; }
  std::uint64_t patched_from() const { return patched_from_; }
  const std::vector<std::uint32_t>& patched() const { return patched_; }
  // For a copy with room (beam6_chunks.hpp): n entries, those of the room
  // alone in their runs; entry e of `from` (in the model's order) at `at`;
  // the runs of [first, last) marked afresh, ending at last.
  void resize(std::size_t n);
  void copy_entry(const Beam6Plan& from, std::uint32_t e, std::uint32_t at);
  void find_runs(std::uint32_t first, std::uint32_t last);
  // The index among the awake elements of entry e.
  std::uint32_t element(std::uint32_t e) const { return elements.empty() ? e : elements[e]; }

  // Per entry.
  std::vector<std::uint32_t> elements;  // its awake element (empty: in the model's order)
  std::vector<ParticleId> i, j;
  std::vector<double> end_i[4], end_j[4];  // x, y, z, w of the beam-end orientations
  std::vector<double> L, EA, prestress;
  std::vector<double> k_static;  // max(EA / L, 7/4 12 EI / L^3), eq. 3.47 without the geometric term
  std::vector<double> kr;        // max(GJ / L, 7/4 4 EI / L), eq. 3.49
  std::vector<double> cz, cy;    // 2 EIz / L, 2 EIy / L (eq. 3.46)
  std::vector<double> torsion;   // GJ / L
  // The end of the run from entry e on whose entries hold e's constants
  // (L .. torsion) or e's ends (end_i, end_j), bit for bit: entries e ..
  // same_constants_to[e] - 1 read alike.
  std::vector<std::uint32_t> same_constants_to, same_ends_to;
  // The columns a run groups: the beam-end frames (end_i x, y, z, w, then
  // end_j's) and the constants (L .. torsion).
  std::array<const double*, 8> end_columns() const {
    return {end_i[0].data(), end_i[1].data(), end_i[2].data(), end_i[3].data(),
            end_j[0].data(), end_j[1].data(), end_j[2].data(), end_j[3].data()};
  }
  std::array<const double*, 8> constant_columns() const {
    return {L.data(), EA.data(), prestress.data(), k_static.data(), kr.data(), cz.data(), cy.data(), torsion.data()};
  }
  // Whether the step's block of entries [first, first + n) reads one entry's constants, or ends.
  bool same_constants(std::uint32_t first, std::uint32_t n) const { return same_constants_to[first] >= first + n; }
  bool same_ends(std::uint32_t first, std::uint32_t n) const { return same_ends_to[first] >= first + n; }
  // The bytes of the plan the step reads for entries [first, first + count),
  // taken in blocks from `first` on: ends, beam-end frames and constants.
  double step_bytes(std::uint32_t first, std::uint32_t count) const;

 private:
  // each(out's column, in's column) for every per-entry column but elements
  // and the runs (find_runs derives them).
  template <class Each>
  static void columns(Beam6Plan& out, const Beam6Plan& in, Each each);
  void find_runs();
  void mark_runs_at(std::uint32_t e);  // entry e's runs again, those after it marked already
  void put(const Beam6& b, std::uint32_t e);
  bool patch(const Model& m);
  const Model* model_ = nullptr;
  std::uint64_t caught_up_ = ~std::uint64_t(0);  // the revision m.beam6s.edits was restarted at
  std::size_t awake_ = 0;
  std::uint64_t generation_ = 0;
  // Moves at every update; `patched` lists the entries the last one wrote
  // in place, when it moved from `patched_from`.
  std::uint64_t values_ = 0, patched_from_ = ~std::uint64_t(0);
  std::vector<std::uint32_t> patched_, marked_;
  // A plan in a share's order: what it was derived or followed from, and
  // the places of each element of `from` (two at most: one per owner).
  std::uint64_t from_generation_ = 0, from_values_ = 0;
  std::vector<std::uint32_t> places_;
};

}  // namespace tendril
