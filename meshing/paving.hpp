#pragma once
// Rule 20: a patch inside a closed loop of particles by paving (thesis 5.3,
// fig. 5.8a). The loop, planar or not, is projected on its best-fit plane
// (centroid, Newell normal), paved there (paving_2d.hpp), and the new nodes
// are lifted back: in-plane coordinates from the paving, heights above the
// plane harmonic (each the mean of its neighbours') so that a non-planar
// loop gets a smooth first surface for form-finding to take over. The
// boundary is exactly the given loop; the result is all quads.
#include <vector>

#include "commit_patch.hpp"
#include "model/model.hpp"
#include "paving_2d.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

// Vertices 0..n-1 are the loop, unmoved. Throws ModelError for fewer than 8
// points, an odd count (an all-quad mesh needs an even boundary), repeated
// or non-finite points, a loop enclosing no area, a loop whose projection on
// its best-fit plane intersects itself (CGAL exact predicates), or a front
// the simple paver cannot advance.
QuadMesh paving(const std::vector<Vec3>& loop, const PavingOptions& options = {});

// A domain with holes: the outer loop (at least 8 points) and inner loops (at
// least 3 points each, either orientation), projected on the outer loop's
// best-fit plane. Vertices are the outer loop's, then each hole's, unmoved.
// Throws ModelError as above, and when the total count is odd, a hole
// intersects itself, touches or crosses the outer loop or another hole, lies
// outside the outer loop or inside another hole (exact predicates).
QuadMesh paving(const std::vector<Vec3>& outer, const std::vector<std::vector<Vec3>>& holes,
                const PavingOptions& options = {});

CommittedPatch patch_by_paving(Model& m, const std::vector<ParticleId>& loop, const Section& s,
                               const PavingOptions& options = {});
// The patch's boundary is the outer loop and every hole's loop.
CommittedPatch patch_by_paving(Model& m, const std::vector<ParticleId>& outer,
                               const std::vector<std::vector<ParticleId>>& holes, const Section& s,
                               const PavingOptions& options = {});

}  // namespace tendril::meshing
