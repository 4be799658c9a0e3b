#pragma once
// CST triangulation of a quad patch by edge classification (thesis 5.5.2.2,
// fig. 5.30). A constant-strain triangle needs one side along the warp of
// the fabric; a patch's quads already carry two yarn families, and this
// module finds them and cuts every quad along a consistently aligned
// diagonal. Nothing here changes the model: the triangles are data for the
// CST element, and the bars come back from them exactly (reversible).
//
// Classification: every quad gets a frame, its corners labelled as the
// corners (0,0), (1,0), (1,1), (0,1) of a unit square whose u axis is the
// warp and v axis the weft. Quad 0 (or the quad the options pick) starts
// with its edge from corner 0 to corner 1 as warp; the frame then spreads
// breadth-first across shared edges, each neighbour's frame the mirror image
// of the current one across the shared edge. So opposite edges of a quad
// share a class and adjacent edges differ, and a whole chord of quads (the
// strip through opposite edges) carries one class.
//
// Conflicts. Around an interior vertex of odd valence (3, 5: paving and
// odd-sided Catmull-Clark leave them) the frames come back rotated by 90
// degrees: a warp chord closes onto a weft chord and no consistent classes
// exist. By default this is an error (ModelError naming the edge where the
// two quads disagree and the nearest odd-valence vertex). With allow_seams
// the propagation keeps going: each quad keeps the frame it was reached with
// first, so every triangle still has its first side along its own quad's
// warp, and the edges where neighbouring quads disagree are reported as
// `seams`: lines where the warp turns by 90 degrees, like the seams between
// the cut panels of a real membrane. Around an even irregular vertex
// (valence 2, 6) the classes are consistent but the frames come back
// mirrored or turned by 180 degrees; the diagonals then change direction
// across the edges reported as `flips`. A structured grid has neither.
#include <array>
#include <vector>

#include "edge_table.hpp"
#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

enum class Yarn : std::uint8_t { Warp, Weft };

struct ClassifyOptions {
  bool allow_seams = false;  // see above: false throws on a class conflict
  // Nonzero: quad 0's edge most parallel to this direction is warp, its u
  // axis pointing along it. Zero: corner 0 to corner 1 of quad 0.
  Vec3 warp = Vec3::Zero();
};

// A triangle of a quad, corners (0,0), (1,0), (1,1) or (1,1), (0,1), (0,0)
// of its frame: side v0-v1 is warp, v1-v2 weft, v2-v0 the quad's diagonal.
using Triangle = std::array<Index, 3>;

struct EdgeClasses {
  EdgeTable edges;
  std::vector<Yarn> yarn;  // per edge; on a seam, the class the first-labelled quad gave it
  // Per quad: the mesh vertices at (0,0), (1,0), (1,1), (0,1) of its frame.
  std::vector<QuadIndices> frame;
  std::vector<Index> seams;  // edges whose two quads disagree on the class
  std::vector<Index> flips;  // edges whose quads agree on the class but not on the diagonal's direction
};

// Throws ModelError("edge classification: ...") for an invalid mesh (see
// edge_table) or, without allow_seams, a class conflict.
EdgeClasses classify_edges(const QuadMesh& m, const ClassifyOptions& options = {});

// Two triangles per quad, in quad order: (f00, f10, f11), (f11, f01, f00),
// so the diagonal of every quad runs from its frame's (0,0) to (1,1) corner.
std::vector<Triangle> cst_triangles(const EdgeClasses& c);

// The reverse shift, CST back to bars: each pair of triangles made by
// cst_triangles is one quad again (f00, f10, f11, f01), and the bars are the
// quads' edges: sides v0-v1 and v1-v2 of every triangle, diagonals dropped,
// each edge once, in order of first appearance. Throws ModelError for an odd
// number of triangles or a pair that does not share its diagonal.
std::vector<QuadIndices> quads_from_triangles(const std::vector<Triangle>& t);
std::vector<std::array<Index, 2>> bars_from_triangles(const std::vector<Triangle>& t);

// The same on a patch block of a model, in particle ids.
struct PatchTriangulation {
  std::vector<std::array<ParticleId, 3>> triangles;
  std::vector<std::array<ParticleId, 2>> seams, flips;
  std::size_t warp_edges = 0, weft_edges = 0;
};
PatchTriangulation cst_triangulation(const Model& m, BlockId patch, const ClassifyOptions& options = {});

}  // namespace tendril::meshing
