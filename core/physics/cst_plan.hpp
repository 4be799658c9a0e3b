#pragma once
// The CST step's lean copy of the awake triangles (DESIGN principle 1: a
// derived cache, like BarChunks): structure of arrays holding what the
// form-finding force reads, and the corners whose pull is projected onto
// their normal, each given a slot so that the element pass's sums sit
// together and in one compact array (the fused step sums a chunk's corners
// in rows by particle, cst_forces.cpp). It follows the triangles' own
// edit list (m.csts.edits): a change elsewhere in the model (a cable, a
// new particle) leaves it as it is, and each triangle written, woken or
// put to sleep is written again in place. A corner keeps its slot while no
// triangle projects onto it (its sums stay zero, so it adds nothing), so
// that it finds it again when one does; the plan is derived again once
// such slots are more than half.
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace tendril {

// A projected corner's sums while its triangles are added: the pull, the
// normal (each triangle's oriented to the sum so far) and the G-strings.
struct CstCornerSums {
  Vec3 pull = Vec3::Zero(), normal = Vec3::Zero(), smooth = Vec3::Zero();
};

struct CstPlan {
  static constexpr std::uint32_t kNoSlot = ~std::uint32_t(0);

  // Up to date: no triangle written, woken or put to sleep since the last update.
  bool current(const Model& m) const;
  // Brings the plan up to date and restarts m.csts.edits.
  void update(Model& m);
  void derive(const Model& m);
  // Moves whenever the triangles' corners or slots may have (what the
  // shares of the triangles and corners are derived from), not when a
  // triangle's stresses alone were written again.
  std::uint64_t generation() const { return generation_; }
  // Moves at every update; patched() lists the entries the last one wrote
  // (ascending; past the plan's end: triangles gone to sleep or removed)
  // and patched_ends() their corners before it (3 each, kNone for an entry
  // that is new), when it moved from patched_from(), else patched_from()
  // matches no stamp.
  std::uint64_t values() const { return values_; }
  std::uint64_t patched_from() const { return patched_from_; }
  const std::vector<std::uint32_t>& patched() const { return touched_; }
  const std::vector<ParticleId>& patched_ends() const { return old_ends_; }

  // Per awake triangle, in the model's order.
  std::vector<ParticleId> i, j, k;
  std::vector<double> sigma_warp, sigma_weft;
  std::vector<double> g_string;  // the G-strings' force density, 0.5 (warp + weft)
  // Bit c: corner c (i, j, k) takes only its pull along its normal and
  // follows the G-strings (an interior vertex in form-finding).
  std::vector<std::uint8_t> along_normal;
  static constexpr std::uint8_t kAllCorners = 7;  // along_normal of a triangle with every corner interior
  std::vector<std::uint32_t> slot;  // 3 per triangle: its corners' slots, kNoSlot where none
  std::vector<std::uint8_t> analysis;  // 1: in analysis (eq. 3.37-3.39), else form-finding
  std::vector<ParticleId> corner;  // per slot: the corner

 private:
  void put(const Cst& t, std::size_t e);  // triangle e's values but its slots
  void add_slots(std::size_t e, int way);  // entry e's corners join (+1) or leave (-1) their slots
  bool patch(const Model& m);
  const Model* model_ = nullptr;
  std::uint64_t caught_up_ = ~std::uint64_t(0);  // the revision m.csts.edits was restarted at
  std::uint64_t generation_ = 0, values_ = 0, patched_from_ = ~std::uint64_t(0);
  std::vector<std::uint32_t> touched_;
  std::vector<ParticleId> old_ends_;
  std::vector<std::uint32_t> slot_of_;  // per particle: its slot, or kNoSlot
  std::vector<std::uint32_t> users_;    // per slot: the corners of projected triangles on it
  std::size_t unused_ = 0;              // slots without users
};

}  // namespace tendril
