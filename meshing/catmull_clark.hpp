#pragma once
// One step of Catmull-Clark subdivision on a polygon mesh (rules 19 and 25).
//
// Interior rules are the classic ones (the same as OpenMesh's CatmullClarkT):
// face point = centroid of the face; interior edge point = mean of the two
// ends and the two face points; interior vertex of valence n =
// (Q + 2R + (n - 3) V) / n, with Q the mean of its face points and R the mean
// of its edge midpoints.
//
// Boundary rule (ours, not OpenMesh's): a boundary vertex keeps its position,
// and a boundary edge point is the edge midpoint. Boundary particles of a
// patch belong to beams (or are the loop the designer picked), so the
// surface must not pull them; midpoints keep the new boundary on the chords
// between them, which is where the bars that carry the boundary lie.
// OpenMesh instead moves a boundary vertex to (V + sum of its boundary edge
// midpoints) / 3, which would drag the corners of a patch off its beams.
// Vertices flagged in `pinned` (locked or shared particles) keep their
// position too; their edges and faces follow the interior rules.
//
// Output numbering: the input vertices keep their indices, then one face point
// per face (face order), then one edge point per edge (edge_table order). A
// face with k corners becomes k quads (corner, next edge point, face point,
// previous edge point), winding as the face did.
#include <vector>

#include "quad_mesh.hpp"

namespace tendril::meshing {

// Throws ModelError for invalid faces (see edge_table), a pinned mask of the
// wrong size, or a vertex whose faces do not form one fan (non-manifold).
QuadMesh catmull_clark(const PolygonMesh& m, const std::vector<bool>& pinned = {});
QuadMesh catmull_clark(const QuadMesh& m, const std::vector<bool>& pinned = {});

}  // namespace tendril::meshing
