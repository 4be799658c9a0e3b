#pragma once
// Binary PLY through OpenMesh (issue 14: "PLY of patches through OpenMesh",
// Debian's libopenmesh-dev). tendril's own PLY (io/ply.hpp, io/mesh_import.hpp)
// is ASCII and carries the edges of cables and beams and a block id per
// element, which OpenMesh's PLY does not; CAD and scanning tools mostly
// write binary meshes, which OpenMesh reads. So:
// - import_mesh_file: what tendril.import reads: a binary PLY through
//   OpenMesh (its vertices and faces, one group; a binary file with edges
//   is refused: save it as ASCII), everything else by io/mesh_import.
// - patches_ply_binary: the patches' quads as a binary little-endian PLY
//   written by OpenMesh (vertices: the patches' particles in id order,
//   single precision as PLY tools expect), for MeshLab, Blender, CloudCompare.
#include <string>

#include "io/mesh_import.hpp"
#include "model/model.hpp"

namespace tendril::meshing {

ImportedMesh import_mesh_file(const std::string& path);
// Throws InputError naming the file when OpenMesh cannot read it whole.
ImportedMesh read_binary_ply(const std::string& bytes, const std::string& name);
// ModelError when the model has no patch.
std::string patches_ply_binary(const Model& m);

}  // namespace tendril::meshing
