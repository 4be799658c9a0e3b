#include "folded_quads.hpp"

#include <algorithm>

#include "patch_mesh.hpp"
#include "quality.hpp"

namespace tendril::meshing {

std::vector<FoldedQuad> folded_quads(const Model& m) {
  std::vector<FoldedQuad> out;
  for (BlockId b : m.live_blocks()) {
    if (m.blocks[b].kind != BlockKind::Patch) continue;
    const PatchMesh pm = patch_mesh(m, b, "folded_quads");
    for (const QuadIndices& q : pm.mesh.quads) {
      const auto& x = pm.mesh.positions;
      const double j = scaled_jacobian(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
      if (j < 0) out.push_back({b, {pm.particles[q[0]], pm.particles[q[1]], pm.particles[q[2]], pm.particles[q[3]]}, j});
    }
  }
  std::stable_sort(out.begin(), out.end(), [](const FoldedQuad& a, const FoldedQuad& b) { return a.jacobian < b.jacobian; });
  return out;
}

}  // namespace tendril::meshing
