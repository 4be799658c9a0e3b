#pragma once
// The fused step's copy of the 6-DOF plan (beam6_plan.hpp) chunk by chunk
// of the bar chunks, as HingeChunks is for the spline-beam hinges: a chunk
// lists, in the model's order, every element with an end among its
// particles (an element with ends in two chunks is evaluated by both, each
// adding into its own ends), so that every particle's elements are summed
// in the model's order, as the element pass sums them.
// It follows the plan in the model's order: after an update that wrote a
// few entries there (plan.patched()), each written element leaves the
// chunks of its old ends and joins those of its ends now, and each chunk
// touched is written again in model order, in the room kept after its
// entries. Derived again when a chunk outgrew its room, the chunk size
// moved, or it missed one of the plan's updates.
#include <cstdint>
#include <vector>

#include "physics/beam6_plan.hpp"

namespace tendril {

struct Beam6Chunks {
  void update(const Beam6Plan& from, std::uint32_t shift, std::size_t n_chunks);
  void derive(const Beam6Plan& from, std::uint32_t shift, std::size_t n_chunks);
  std::size_t entry_count() const;
  std::uint64_t derivations = 0, patches = 0;  // how it was brought up to date

  // Chunk c's entries are plan's [begin[c], end[c]), each chunk's runs
  // ending at end[c]; its room ends at limit[c] (elements: kNone there).
  std::vector<std::uint32_t> begin, end, limit;
  Beam6Plan plan;

 private:
  bool patch(const Beam6Plan& from, std::size_t n_chunks);
  void put(const Beam6Plan& from, std::uint32_t e, std::uint32_t at);
  void append_empty_chunk();
  std::vector<std::uint32_t> place_of_;  // per element of `from`: the place of one of its entries
  std::vector<std::uint32_t> affected_, items_;  // patch's scratch
  std::uint64_t from_values_ = 0;
  std::uint32_t shift_ = 0;
};

}  // namespace tendril
