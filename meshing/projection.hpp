#pragma once
// Rule 21: a patch between two equally sized particle sequences A and B
// (thesis 5.3, fig. 5.8b). Row 0 is A, row r+1 is B, and rows 1..r are new
// particles on the straight segments A[i]-B[i], at A[i] + k/(r+1) (B[i] - A[i]);
// quads join consecutive rows. The sequences are open polylines, or closed
// loops (a tube between two rings, the building block of rule 22's
// catenoid-like surfaces). Straight rungs keep the construction predictable;
// form-finding gives the patch its shape afterwards.
#include <vector>

#include "commit_patch.hpp"
#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

inline constexpr int kMaxProjectionRows = 10000;

// Vertex numbering: A is 0..n-1, B is n..2n-1, then interior row k (1..r) at
// 2n + (k-1) n + i. (r+1) (n-1) quads, (r+1) n when closed; quad (k, i) is
// row k: i, i+1, then row k+1: i+1, i.
// Throws ModelError for sizes that differ, fewer than 2 points (3 when
// closed), rows outside [0, kMaxProjectionRows], non-finite points, A[i] at
// B[i], or consecutive points of A or B that coincide. The model-level call
// also refuses a particle that appears twice in A and B together.
QuadMesh projection(const std::vector<Vec3>& a, const std::vector<Vec3>& b, int rows, bool closed = false);

// Rule 21 on the model; A and B become the patch's two opposite sides.
CommittedPatch patch_by_projection(Model& m, const std::vector<ParticleId>& a, const std::vector<ParticleId>& b,
                                   int rows, const Section& s, bool closed = false);

}  // namespace tendril::meshing
