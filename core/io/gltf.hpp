#pragma once
// glTF 2.0 binary (.glb) of the model's current state for three.js, Blender
// and Rhino 8 (issue 14), written with Debian's tinygltf. One mesh, two
// primitives: LINES, one segment per line element (bars, cable segments,
// 3-DOF beam links, 6-DOF beam elements), and TRIANGLES, the CST triangles
// and the quads of bar patches (two triangles each). Every element has its
// own vertices, coloured (COLOR_0) by the element's kind or one of its
// results (query/element_results.hpp). glTF is y-up in metres: tendril's
// (x, y, z), z up, is written as (x, z, -y).
#include <array>
#include <string>

#include "model/model.hpp"
#include "query/element_results.hpp"

namespace tendril {

// "kind": beams dark grey, cables orange, bars blue, patches light grey;
// "axial": compression blue, 0 white, tension red, scaled by the largest
// |N|; "moment", "stress": 0 blue to the largest red; "utilisation": 0
// blue to 1 red (above 1 red); "s1": a membrane's larger principal stress,
// 0 blue to the largest red. Line results colour lines, s1 triangles; what
// a field does not apply to is grey.
struct GltfOptions {
  std::string colour = "kind";
  const BeamSections* sections = nullptr;  // beams' stress and utilisation
};

// True for the names above.
bool gltf_colour_known(const std::string& name);
// The colour [0, 1] of t along blue (0) -> white (0.5) -> red (1), t clamped.
std::array<float, 3> gltf_ramp(double t);

// Throws ModelError when the colour is unknown, or is stress or
// utilisation without any section (with a strength).
std::string gltf_bytes(const Model& m, const GltfOptions& options);
// Written whole or not at all; throws OutputError when it cannot be (io/atomic_file.hpp).
void save_gltf(const Model& m, const std::string& path, const GltfOptions& options);

}  // namespace tendril
