#include "folded_quads.hpp"

#include <algorithm>

#include "patch_mesh.hpp"
#include "quality.hpp"

namespace tendril::meshing {

std::vector<FoldedQuad> folded_quads(const Model& m) { return FoldedQuadCheck()(m); }

std::vector<FoldedQuad> FoldedQuadCheck::operator()(const Model& m) {
  if (revision_ != m.revision) {
    patches_.clear();
    for (BlockId b : m.live_blocks()) {
      if (m.blocks[b].kind != BlockKind::Patch) continue;
      const PatchMesh pm = patch_mesh(m, b, "folded_quads");
      Patch& patch = patches_.emplace_back(Patch{b, {}});
      patch.quads.reserve(pm.mesh.quads.size());
      for (const QuadIndices& q : pm.mesh.quads)
        patch.quads.push_back({pm.particles[q[0]], pm.particles[q[1]], pm.particles[q[2]], pm.particles[q[3]]});
    }
    revision_ = m.revision;
  }
  const auto& x = m.particles.position;
  std::vector<FoldedQuad> out;
  for (const Patch& patch : patches_)
    for (const auto& q : patch.quads) {
      const double j = scaled_jacobian(x[q[0]], x[q[1]], x[q[2]], x[q[3]]);
      if (j < 0) out.push_back({patch.block, q, j});
    }
  std::stable_sort(out.begin(), out.end(), [](const FoldedQuad& a, const FoldedQuad& b) { return a.jacobian < b.jacobian; });
  return out;
}

}  // namespace tendril::meshing
