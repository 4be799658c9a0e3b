#pragma once
// The step's lean copy of the awake bars (DESIGN principle 1: a derived
// cache), laid out for one streaming pass and for threads:
// - structure of arrays holding only what the force reads, with k = EA / L
//   stored (eq. 3.32), no dart, line mass or block;
// - the integrated particles split by id into chunks of a fixed size that
//   depends on the model, never on the thread count; a bar belongs to the
//   chunk of its smaller particle (stored as i, the other as j: swapping the
//   ends negates the force exactly, so no sum changes);
// - a bar whose j lies in another chunk is "crossing": its owner writes the
//   force on j into a slot, and j's chunk adds its slots (its inbox) after
//   its own bars. Every particle's force is thus summed in one fixed order:
//   its initial load, its own chunk's bars in model order, then its inbox in
//   slot order, whatever thread ran which chunk. A model within one chunk
//   (up to 1024 particles) sums exactly as the model's bar order says.
// Derived again when the chunk size moved with the model's capacity. Else
// patched from the bars' edit list (edit_list.hpp): each chunk keeps
// room after its bars and slots, and a chunk a change touched is rewritten
// from the model alone, in model order, so that a patched copy holds
// exactly the sequences a fresh one would (DESIGN principle 1: a rule
// firing every step costs what it touched, not the model's size).
#include <cstdint>
#include <utility>
#include <vector>

#include "model/model.hpp"
#include "physics/lanes.hpp"

namespace tendril {

// A particle's force (x, y, z) and stiffness as the bar step sums them: one
// vector of four, so that a bar adds into an end with one load, addition
// and store (two with SSE2), each lane in the order the scalar sums took.
using ForceSum = Lanes;

struct BarChunks {
  struct Chunk {
    std::uint32_t particles_begin = 0, particles_end = 0;         // into `particles`
    std::uint32_t bars_begin = 0, crossing_begin = 0, bars_end = 0;  // [crossing_begin, bars_end) cross out
    std::uint32_t bars_limit = 0;                                  // its room ends here (the next one's begin)
    std::uint32_t slot_begin = 0, slot_limit = 0;                  // slot of its first crossing bar, room
    std::uint32_t inbox_begin = 0, inbox_end = 0;                  // into inbox_*
    std::uint32_t first_source = 0;  // the smallest chunk with a bar into this one's inbox (else itself)
    bool cables = false;             // a bar of it is tension only (else the step never reads `cable`)
    std::uint32_t block_begin = 0;   // into `same`: its first block's
  };
  // The step takes a chunk's bars in blocks of this many (forces.cpp).
  static constexpr std::uint32_t kBlock = 64;

  // The number of particles per chunk for a model of this capacity: a power
  // of two from 1024 to 16384, about capacity / 16.
  static std::uint32_t chunk_shift_for(std::size_t capacity);
  // The room a chunk keeps after n elements (bars, slots, hinges): what some
  // hundred rule firings in one chunk add before the copy is laid out
  // afresh.
  static std::uint32_t room(std::uint32_t n) { return n / 16 + 32; }
  // Up to date: nothing moved or was written since the last update.
  bool current(const Model& m) const;
  // Derives the copy afresh.
  void derive(const Model& m);
  // Brings the copy up to date: patched from m.bars.edits where it can,
  // else derived; restarts the edit list either way.
  void update(Model& m);
  std::size_t bar_count() const;       // bars in the copy (the room left out)
  std::size_t crossing_count() const;  // crossing bars
  // How the copy was last brought up to date, for tests and benchmarks.
  std::uint64_t derivations = 0, patches = 0;

  std::uint32_t shift = 10;
  std::vector<Chunk> chunks;
  std::vector<ParticleId> particles;  // integrated particles by chunk, in `integrated` order
  // Bars, chunk by chunk: ends, k = EA / L, rest length, prestress, cable
  // (tension only: 1, else 0; eight bytes like the doubles beside it, so
  // that the vectorised loop keeps one bar per double lane: a byte column
  // made GCC take 32 bars an iteration and spill: 1.5x slower).
  std::vector<ParticleId> i, j;
  std::vector<double> k, rest, prestress;
  std::vector<std::uint64_t> cable;
  // Per block of kBlock bars of a chunk: 1 where its bars share k, rest
  // length, prestress and cable flag bit for bit (a net or member of equal
  // bars), so that the step reads the first bar's and streams none of the
  // others' (stop 45).
  std::vector<std::uint8_t> same;
  // Per place, the model's index of its bar (kNone in the room); per awake
  // model bar, its place.
  std::vector<std::uint32_t> model_bar, place_of;
  // Whether chunk c's block starting at bar e0 is one of those.
  bool same_block(const Chunk& c, std::uint32_t e0) const { return same[c.block_begin + (e0 - c.bars_begin) / kBlock]; }
  std::vector<ParticleId> inbox_particle;
  std::vector<std::uint32_t> inbox_slot;
  // Scratch written by a pass: the force (on i; j takes minus it) and the
  // stiffness of every crossing bar.
  std::vector<Vec3> slot_force;
  std::vector<double> slot_stiffness;

 private:
  bool patch(const Model& m);
  void put(const Bar& b, std::uint32_t e, std::uint32_t at);
  void mark_blocks(const Chunk& ch);
  void append_empty_chunk();
  void derive_particles(const Model& m);
  void derive_inboxes();
  std::vector<std::uint32_t> touched_, affected_, interior_, crossing_;  // patch's scratch
  std::vector<std::pair<std::uint32_t, std::uint32_t>> joining_;        // (chunk, model bar)
  const Model* model_ = nullptr;
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::size_t capacity_ = 0;
};

}  // namespace tendril
