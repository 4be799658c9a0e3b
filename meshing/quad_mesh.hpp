#pragma once
// The plain mesh every meshing algorithm reads and writes: faces over a list
// of positions, independent of the model. Vertex i is positions[i]. Keeping
// the algorithms on this form lets them be tested against references
// (OpenMesh, closed-form numbers) without a Model, and lets the model-level
// rules validate a whole result before they change anything.
#include <array>
#include <cstdint>
#include <vector>

#include "model/types.hpp"

namespace tendril::meshing {

using Index = std::uint32_t;
using QuadIndices = std::array<Index, 4>;  // corners in order around the quad

struct QuadMesh {
  std::vector<Vec3> positions;
  std::vector<QuadIndices> quads;
};

// Faces of any size >= 3: the input of one Catmull-Clark step (rule 19
// starts from a single n-gon).
struct PolygonMesh {
  std::vector<Vec3> positions;
  std::vector<std::vector<Index>> faces;
};

PolygonMesh to_polygons(const QuadMesh& m);

}  // namespace tendril::meshing
