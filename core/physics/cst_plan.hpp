#pragma once
// The CST step's lean copy of the awake triangles (DESIGN principle 1: a
// derived cache, like BarChunks): structure of arrays holding what the
// form-finding force reads, and the corners whose pull is projected onto
// their normal, each given a slot so that the element pass's sums sit
// together and in one compact array (the fused step sums a chunk's corners
// in rows by particle, cst_forces.cpp). It follows the triangles' own
// edit list (m.csts.edits): a change elsewhere in the model (a cable, a
// new particle) leaves it as it is, a triangle whose values changed but
// whose corners and projected corners did not is written again in place,
// and any other change of the awake triangles derives it again.
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
  // Triangle e's values but its slots; false when its corners or which of
  // them are projected differ from the entry's (the slots would move).
  bool put(const Cst& t, std::size_t e, bool check);
  bool patch(const Model& m);
  const Model* model_ = nullptr;
  std::uint64_t caught_up_ = ~std::uint64_t(0);  // the revision m.csts.edits was restarted at
  std::size_t awake_ = 0;
  std::uint64_t generation_ = 0;
  std::vector<std::uint32_t> touched_;
};

}  // namespace tendril
