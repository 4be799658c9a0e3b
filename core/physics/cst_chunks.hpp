#pragma once
// The fused step's share of the CST plan (cst_plan.hpp) chunk by chunk of
// the bar chunks: a chunk lists, in the model's order, every triangle with
// a corner among its particles (a triangle with corners in two chunks is
// evaluated by both, each adding into its own corners), and the slots of
// its projected corners, so that every particle's triangles are summed in
// the model's order, as the element pass sums them. A slot's place among
// its chunk's changes no number: each is its particle's only one.
// It follows the plan as the 6-DOF copy does (beam6_chunks.hpp): after an
// update that wrote a few entries (plan.patched()), each chunk of a written
// triangle's old or new corners is written again in model order, in the
// room kept after its entries, and new slots join their chunk's room.
// Derived again when a chunk outgrew its room, the chunk size moved, or it
// missed one of the plan's updates.
#include <cstdint>
#include <vector>

#include "physics/cst_plan.hpp"

namespace tendril {

struct CstChunks {
  void update(const CstPlan& plan, std::uint32_t shift, std::size_t n_chunks);
  void derive(const CstPlan& plan, std::uint32_t shift, std::size_t n_chunks);
  std::size_t triangle_count() const;  // entries of every chunk, the room left out
  std::size_t corner_count() const;
  std::uint64_t derivations = 0, patches = 0;  // how it was brought up to date

  // Chunk c's triangles (the plan's entries) are triangles[begin[c], end[c]),
  // its room up to limit[c] (kNone there); its slots corners[corner_begin[c],
  // corner_end[c]), room to corner_limit[c].
  std::vector<std::uint32_t> begin, end, limit, triangles;
  std::vector<std::uint32_t> corner_begin, corner_end, corner_limit, corners;

 private:
  bool patch(const CstPlan& plan, std::size_t n_chunks);
  void append_empty_chunk();
  std::vector<std::uint32_t> affected_, items_;  // patch's scratch
  std::uint64_t from_values_ = 0;
  std::uint32_t shift_ = 0, slots_ = 0;  // the plan's slots placed
};

}  // namespace tendril
