#pragma once
// ASCII PLY of the model's geometry (MeshLab, Blender, CloudCompare): the
// live particles as vertices (0-based, in id order), the segments of cables
// and beams as edges and the quads of patches as faces, each with the id of
// its block. A comment gives the units (m).
#include <string>

#include "model/model.hpp"

namespace tendril {

std::string ply_string(const Model& m);
// Written whole or not at all; throws OutputError when it cannot be (io/atomic_file.hpp).
void save_ply(const Model& m, const std::string& path);

}  // namespace tendril
