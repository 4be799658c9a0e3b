#pragma once
// Wavefront OBJ output of the model's geometry: a comment with the units
// (m), one "v" per live particle (numbered 1..n in the order of live ids),
// then per block a group "g KIND-ID" (g beam-3, g cable-4, g patch-7) with
// one "l" polyline per cable and beam (a ring repeats its first vertex) or
// one "f" per patch quad, all consistently oriented within a patch. Doubles
// carry 17 significant digits.
#include <string>
#include <vector>

#include "model/model.hpp"

namespace tendril {

std::string obj_string(const Model& m);
// The faces of patch b, each once, consistently wound, each starting at its
// lowest particle id (what the "f" lines hold; the studio draws them too).
std::vector<std::vector<ParticleId>> patch_faces(const Model& m, BlockId b);
// Written whole or not at all; throws OutputError when it cannot be (io/atomic_file.hpp).
void save_obj(const Model& m, const std::string& path);

}  // namespace tendril
