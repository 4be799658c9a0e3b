#pragma once
// Geometry drawn elsewhere (Rhino, Blender, tendril's own OBJ and PLY
// output) read as vertices and, per group, polylines and faces, for a
// scene to map onto particles and blocks (tendril.import, m:import;
// docs/lua-api.md "Importing geometry"). Wavefront OBJ: v, l, f (v, v/vt,
// v//vn, v/vt/vn; negative indices count back from the last vertex), g and
// o start a group; other statements (vt, vn, usemtl, s, comments ...) are
// skipped. PLY: ASCII, its vertex x y z, its edges (vertex1 vertex2) as
// polylines (an edge that starts where the last ended continues it) and its faces (vertex_indices) in one group, or in
// one group per value of an edge's or face's `block` property (what
// tendril's PLY writes); binary PLY goes through OpenMesh in the meshing
// layer (meshing/ply_openmesh.hpp). A malformed file is refused naming its line.
#include <string>
#include <vector>

#include "model/types.hpp"

namespace tendril {

struct ImportedGroup {
  std::string name;
  std::vector<std::vector<std::size_t>> lines, faces;  // 0-based vertex indices
};

struct ImportedMesh {
  std::vector<Vec3> vertices;
  std::vector<ImportedGroup> groups;  // in the order they first appear; none empty
};

// By the file's extension (.obj, .ply, any case); throws InputError naming
// the file and the line at fault.
ImportedMesh import_mesh(const std::string& path);
ImportedMesh parse_obj(const std::string& text, const std::string& name);
ImportedMesh parse_ply(const std::string& text, const std::string& name);

}  // namespace tendril
