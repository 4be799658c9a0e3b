#pragma once
// Element quality of a quad mesh, the numbers issue 5 compares paving with gmsh
// on. Definitions (fixed here so benchmarks are comparable over time):
//
// - Corner Jacobian: at corner i with edges a = p[i+1] - p[i], b = p[i-1] - p[i],
//   J_i = ((a x b) . n) / (|a| |b|), where n is the quad's unit average
//   normal, (p2 - p0) x (p3 - p1) normalised (the bilinear patch's normal at
//   its centre). For a planar quad this is the standard scaled Jacobian (sine
//   of the corner angle, negative at a reflex corner). For a non-planar quad
//   it also measures the warp: a corner whose own plane tilts away from the
//   average plane scores lower. Zero-length edges or a zero average normal
//   give J_i = 0.
// - Scaled Jacobian of a quad: the minimum over its four corners. The mesh's
//   jacobian_min and jacobian_mean are the minimum and mean over quads.
// - Corner angle: the angle between a and b in degrees, taken as 360 minus it
//   where J_i < 0 (a reflex corner of a planar quad). angle_min / angle_max
//   are over all corners.
// - Irregular vertices: interior vertices (on no boundary edge) whose valence
//   (number of edges) is not 4; the fraction is over interior vertices, 0
//   when there are none.
#include "model/model.hpp"
#include "quad_mesh.hpp"

namespace tendril::meshing {

struct Quality {
  std::size_t quads = 0;
  double jacobian_min = 0;
  double jacobian_mean = 0;
  double angle_min = 0;  // degrees
  double angle_max = 0;  // degrees
  std::size_t interior_vertices = 0;
  std::size_t irregular_vertices = 0;
  double irregular_fraction = 0;
};

// The four corner Jacobians of one quad, corner order as given.
std::array<double, 4> corner_jacobians(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);
double scaled_jacobian(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3);

// Throws ModelError for an empty mesh or one whose quads are not valid faces
// (see edge_table).
Quality quality(const QuadMesh& m);
// The same for a patch block of a model (ModelError if it is not one).
Quality quality(const Model& m, BlockId patch);

}  // namespace tendril::meshing
