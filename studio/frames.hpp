#pragma once
// What the studio page draws, as binary WebSocket messages (little-endian).
// The topology (particle ids and states, edges, triangles, blocks) goes out
// when the model's revision moved; a frame (float32 positions in the
// topology's particle order, the step, the residual and one colour field)
// goes out at the rate the page asks for. web/src/protocol.js reads both.
//
//   topology: u32 kTopology, u32 revision, u32 particles, u32 edges,
//             u32 triangles, u32 blocks,
//             u32 id[particles], u32 block_id[blocks], u8 block_kind[blocks],
//             u8 block_form[blocks] (3/6 DOF; patches 0 bars, 1 CST),
//             u8 state[particles], u8 lock[particles] (LockBits),
//             u8 edge_kind[edges] (each u8 run padded
//             to 4), u32 edge[2 edges], u32 edge_block[edges] (block index),
//             f32 rest_length[edges], u32 triangle[3 triangles],
//             u32 triangle_block[triangles]
//   frame:    u32 kFrame, u32 revision, f64 step, f64 residual, f64 time,
//             u32 particles, u32 field values, f32 xyz[3 particles],
//             f32 field[values] (per edge)
#include <cstdint>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "physics/solver.hpp"

namespace tendril::studio {

inline constexpr std::uint32_t kTopology = 0x54504f54;  // "TOPT"
inline constexpr std::uint32_t kFrame = 0x4d415246;     // "FRAM"
// The same two messages for a model replayed from the journal (the timeline).
inline constexpr std::uint32_t kPreviewTopology = 0x54505250;  // "PRPT"
inline constexpr std::uint32_t kPreviewFrame = 0x46525250;     // "PRRF"

enum class EdgeKind : std::uint8_t { Cable, Beam, PatchBar };

struct Topology {
  std::uint32_t revision = 0;  // low bits of Model::revision (a tag, compared for equality)
  std::vector<ParticleId> ids;
  std::vector<std::uint8_t> states;
  std::vector<std::uint8_t> locks;
  std::vector<BlockId> blocks;
  std::vector<std::uint8_t> block_kind, block_form;
  std::vector<std::uint8_t> edge_kind;
  std::vector<std::uint32_t> edges;  // pairs of indices into ids
  std::vector<std::uint32_t> edge_block;
  std::vector<float> rest_length;
  std::vector<float> prestress;  // per edge [N] (not sent: the colour fields read it)
  std::vector<std::uint32_t> triangles;  // triples of indices into ids
  std::vector<std::uint32_t> triangle_block;
  std::vector<std::uint32_t> index_of;  // ParticleId -> index into ids (kNone if not drawn)
  // The same drawing (everything the page receives but the revision tag):
  // a change that moved the model's revision without changing what is
  // drawn (a goal moved by a drag) sends no new topology.
  bool same_drawing(const Topology& o) const;
};

Topology topology_of(const Model& m);
std::string encode(const Topology& t);
// The frame of the model's current positions in t's particle order, into
// out (its storage reused: a live session recycles its frame buffers).
void encode_frame(const Model& m, const Solver& s, const Topology& t, const std::vector<float>& field, std::string& out);
std::string encode_frame(const Model& m, const Solver& s, const Topology& t, const std::vector<float>& field);

}  // namespace tendril::studio
