#pragma once
// Catmull-Clark on the model: rule 19 (a patch from a loop of particles) and
// rule 25 (subdivide a patch). Both validate everything first and leave the
// model unchanged on a ModelError. Boundary rule: see catmull_clark.hpp.
#include <vector>

#include "commit_patch.hpp"
#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

inline constexpr int kMaxLoopLevels = 8;  // n * 4^8 quads: beyond that a patch is no longer interactive

// Rule 19 on positions: the loop as one n-gon, one Catmull-Clark step (n quads
// around the loop's centroid, n edge midpoints on the loop), then `levels`
// further steps. Vertices 0..n-1 are the loop, unmoved; the result has
// n * 4^levels quads and 1 + n * 4^levels + n * 2^levels vertices.
// Throws ModelError for n < 3, levels outside [0, kMaxLoopLevels], a point
// repeated, consecutive points that coincide, or a loop enclosing no area
// (|Newell normal| <= 1e-12 * perimeter^2, e.g. collinear points or a
// symmetric figure eight).
QuadMesh loop_catmull_clark(const std::vector<Vec3>& loop, int levels);

// Rule 19: a patch whose boundary is exactly the given closed loop of
// existing particles (in order; the last connects back to the first) plus the
// new edge points between them; interior particles are new (simple state).
CommittedPatch patch_from_loop(Model& m, const std::vector<ParticleId>& loop, int levels, const Section& s);

struct SubdividedPatch : CommittedPatch {
  BlockId replaced = kNone;  // the old patch, still alive: see subdivide_patch
};

// Rule 25: one Catmull-Clark step of patch `b` as a new patch with the given
// section (default: b's). Every particle of b is reused, so loads, locks and
// masses set on them survive; b's boundary particles and any particle that is
// locked or shared with another block stay where they are, its other
// particles move to their Catmull-Clark positions; edge and face points are
// new particles. Rest lengths of the new bars are the new edge lengths.
//
// TODO(core, rule 25 / rule 27): the old patch b is NOT deleted, because
// Model has no delete for patches yet. Until it does, b stays alive on top
// of the new patch (sharing all of b's particles, which are therefore in the
// Shared state) and the caller must delete it: once Model::delete_patch
// exists, call it on `result.replaced` right after this returns, inside the
// same rule transaction. Deleting b then removes only b's darts and bars;
// its particles survive because the new patch holds them.
SubdividedPatch subdivide_patch(Model& m, BlockId b);
SubdividedPatch subdivide_patch(Model& m, BlockId b, const Section& s);

}  // namespace tendril::meshing
