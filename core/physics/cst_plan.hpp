#pragma once
// The CST step's lean copy of the awake triangles (DESIGN principle 1: a
// derived cache, like BarChunks): structure of arrays holding what the
// form-finding force reads, and the corners whose pull is projected onto
// their normal, each given a slot so that the element pass's sums sit
// together and in one compact array (the fused step sums a chunk's corners
// in rows by particle, cst_forces.cpp). Derived again whenever the
// model's revision or capacity moved (every change of a triangle, its
// membrane or a particle's passivity moves the revision).
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

  bool current(const Model& m) const {
    return model_ == &m && revision_ == m.revision && capacity_ == m.particles.capacity();
  }
  void derive(const Model& m);

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
  const Model* model_ = nullptr;
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::size_t capacity_ = 0;
};

}  // namespace tendril
