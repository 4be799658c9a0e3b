#pragma once
// The fused bar step's copy of the awake spline-beam hinges (eq. 3.41-3.43),
// chunk by chunk of the bar chunks (bar_chunks.hpp), so that a model of
// bars and 3-DOF beams is kicked chunk by chunk while its forces are still
// in the cache, as bars alone are:
// - a chunk lists, in the model's order, every hinge with an end among its
//   particles; the chunk adds a hinge's forces into those ends only, so a
//   hinge with ends in two chunks is evaluated by both (a few along each
//   chunk boundary) and every particle's hinges are summed in the model's
//   order, after its bars, as the element pass sums them;
// - only what the force reads: ends, EI and rest curvature, and the hinge's
//   index among the awake ones to name it when it cannot be evaluated.
// Derived again when the chunk size moved; else patched from the hinges'
// edit list as the bar copy is (bar_chunks.hpp): each chunk keeps room
// after its items, and a chunk a change touched is written again from the
// model in model order, the sequences a fresh copy would hold.
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace tendril {

struct HingeChunks {
  // Up to date: nothing moved or was written since the last update.
  bool current(const Model& m, std::uint32_t shift) const;
  void derive(const Model& m, std::uint32_t shift, std::size_t n_chunks);
  // Patched from m.hinges.edits where it can, else derived; restarts the
  // edit list either way.
  void update(Model& m, std::uint32_t shift, std::size_t n_chunks);
  std::size_t item_count() const;
  std::uint64_t derivations = 0, patches = 0;  // how it was brought up to date

  // Chunk c's items are [begin[c], end[c]); its room ends at limit[c].
  std::vector<std::uint32_t> begin, end, limit;
  std::vector<std::uint32_t> hinge;  // per item: its index among the awake hinges (kNone in the room)
  std::vector<ParticleId> i, j, k;
  std::vector<double> EI, rest;
  std::vector<std::uint32_t> place_of;  // per awake hinge: the place of one of its items
  // The step takes a chunk's hinges in blocks of this many (forces.cpp);
  // per block, 1 where its hinges share EI and rest curvature bit for bit
  // (a beam of one section, straight at rest), so that the step reads the
  // first hinge's (stop 45). Chunk c's first block is block_begin[c].
  static constexpr std::uint32_t kBlock = 64;
  std::vector<std::uint32_t> block_begin;
  std::vector<std::uint8_t> same;
  bool same_block(std::uint32_t chunk, std::uint32_t e0) const {
    return same[block_begin[chunk] + (e0 - begin[chunk]) / kBlock];
  }

 private:
  bool patch(const Model& m, std::size_t n_chunks);
  void put(const Hinge& h, std::uint32_t e, std::uint32_t at);
  void mark_blocks(std::uint32_t c);
  void append_empty_chunk();
  std::vector<std::uint32_t> touched_, affected_, items_;  // patch's scratch
  const Model* model_ = nullptr;
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::size_t capacity_ = 0;
  std::uint32_t shift_ = 0;
};

}  // namespace tendril
