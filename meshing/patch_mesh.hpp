#pragma once
// A patch block of the model read as a QuadMesh: the quads are the face
// orbits <alpha0, alpha1> of its darts, the vertices its particles.
#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

struct PatchMesh {
  QuadMesh mesh;
  std::vector<ParticleId> particles;  // particles[i] sits at mesh.positions[i]
};

// Vertices in ascending particle id, quads in order of their smallest dart, each
// starting at that dart and walking alpha0, alpha1, ... (a G-map has no
// orientation: neighbouring quads may wind either way; every metric and
// algorithm here is independent of the winding). Throws ModelError when b is
// not a live patch block.
PatchMesh patch_mesh(const Model& m, BlockId b, const char* what = "patch_mesh");

}  // namespace tendril::meshing
