#pragma once
// Edges of a polygon mesh, numbered in order of first appearance when walking
// the faces in order (so the numbering is deterministic), with the one or two
// faces on each edge. Shared by quality, subdivision and validation.
#include <string>
#include <vector>

#include "quad_mesh.hpp"

namespace tendril::meshing {

inline constexpr Index kNoFace = 0xffffffffu;

struct EdgeTable {
  std::vector<std::array<Index, 2>> ends;   // vertex ids, as first met
  std::vector<std::array<Index, 2>> faces;  // faces[e][1] == kNoFace: a boundary edge
  std::vector<std::vector<Index>> face_edges;  // face_edges[f][k]: edge from corner k to k+1

  bool boundary(Index e) const { return faces[e][1] == kNoFace; }
};

// Throws ModelError("<what>: ...") for a face with fewer than 3 corners, a
// corner out of range or repeated in its face, or an edge in more than two
// faces (the map of a patch is quasi-manifold).
EdgeTable edge_table(const std::vector<std::vector<Index>>& faces, std::size_t vertex_count, const std::string& what);

// Per vertex: true when it lies on a boundary edge.
std::vector<bool> boundary_vertices(const EdgeTable& t, std::size_t vertex_count);

}  // namespace tendril::meshing
