#pragma once
// Bending of a triangulated surface that is flat at rest (thesis 6.1: the
// CFRP strips "carefully triangulated to facilitate the definition of the
// required constraints for simulating bending behaviors"), by the quadratic
// isometric bending model of Bergou, Wardetzky, Harmon, Zorin and Grinspun
// (2006). Each interior edge i-j of the triangles (i, j, k) and (i, j, l) is
// a hinge: with the cotangent weights K of its four corners at rest,
//   v = K_i x_i + K_j x_j + K_k x_k + K_l x_l
// is its discrete mean-curvature vector, zero for any flat placement of the
// rest triangles, and the energy (1/2) w |v|^2 with w = D / (A_ijk + A_ijl),
// D = E t^3 / 12 (1 - nu^2), sums over the hinges to the plate's
// (1/2) D (k1 + k2)^2 per area: exact for the isometric (developable)
// deformations an inextensible strip undergoes, its Gauss term constant.
// The goal keeps K, the two triangles' area and D (its weight [N m]).
// The energy is quadratic in the positions, so every integrator takes it
// as it is: the explicit ones its force -w K_a v and its row sums
// w |K_a| sum |K_b| (Gershgorin) into S, projective dynamics the matrix
// w K K^T (its projection v = 0 adds nothing on the right-hand side).
// The weights depend only on the triangles' shape, kept by an isometric
// deformation: a developable strip already bent (a PQ strip) gives the
// weights of its flat development.
#include <array>

#include "model/elements.hpp"

namespace tendril {

struct BendHinge {
  std::array<double, 4> K{};  // corners i, j (the edge), k, l (the opposite ones)
  double area = 0;            // of the two triangles [m^2]
};

// The hinge of edge a-b between triangles (a, b, c) and (a, b, d); false
// when a triangle is degenerate (its cotangents unbounded).
bool bend_hinge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, BendHinge& out);

struct BendPulls {
  ParticleId p[4];
  Vec3 f[4];     // -w K_a v
  double k[4];   // w |K_a| sum |K_b|: the row sums of w K K^T
};

// Goal::Bend: corners g.i, g.j, g.k, g.l, cotangent weights g.hinge, the
// two triangles' area g.hinge_area, the plate's D as its weight: w = D / area.
BendPulls bend_pulls(const Goal& g, const Vec3* x);

}  // namespace tendril
