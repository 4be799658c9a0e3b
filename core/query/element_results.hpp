#pragma once
// Results a designer acts on (issue 14), per element of one block, in SI
// units, at the current positions and frames, by the laws the solver's
// elements use (a read, O(block)):
// - line elements (bars, cable segments, the links of a 3-DOF beam, 6-DOF
//   beam elements): axial force and strain, slack cables flagged; on beams
//   the bending moments, torsion (6 DOF), curvature and bending radius, and
//   with a section the normal stress at the extreme fibre and utilisation;
// - 3-DOF beam vertices: curvature and moment (eq. 3.41);
// - CST triangles: warp, weft and shear stress and the principal stresses
//   and directions (per unit width, N/m, as membranes are in tendril).
// The support reactions are the solver's (Solver::reaction), model-wide.
#include <limits>
#include <map>
#include <vector>

#include "model/model.hpp"

namespace tendril {

// What the stress needs of a beam's cross-section (model/cross_section.hpp):
// area and elastic moduli, and a strength for utilisation (0: none).
struct StressSection {
  double A = 0, Wy = 0, Wz = 0;
  double strength = 0;  // [Pa]
};

// The sections of a model's beams for its outputs: one for every beam, or
// one per block (a block listed takes its own; the others `all`, if set).
struct BeamSections {
  StressSection all;  // A == 0: none
  std::map<BlockId, StressSection> by_block;
  const StressSection* of(BlockId b) const {
    auto it = by_block.find(b);
    if (it != by_block.end()) return &it->second;
    return all.A > 0 ? &all : nullptr;
  }
  bool any() const { return all.A > 0 || !by_block.empty(); }
  bool any_strength() const {
    bool some = all.A > 0 && all.strength > 0;
    for (const auto& [b, s] : by_block) some |= s.strength > 0;
    return some;
  }
};

struct LineResult {
  ParticleId a = kNone, b = kNone;
  double axial = 0;    // N, tension > 0
  double strain = 0;   // (l - L) / L
  bool slack = false;  // a cable segment that would be in compression: it carries 0
  // Internal bending moments [N m] about the section's y and z axes and the
  // torsion at the end of the element where the resultant moment is larger
  // (6 DOF: the element's end moments, eq. 3.46, signed alike along the
  // beam; 3 DOF: the hinge moment of the end vertex, in My, Mz = 0).
  double My = 0, Mz = 0, torsion = 0;
  ParticleId at = kNone;  // that end (a or b), where the moment, curvature and stress are read
  double moment = 0;     // the resultant |M| there
  double curvature = 0;  // 1/m, M / EI (6 DOF) or 2 sin(alpha) / Lc (3 DOF) there
  double radius = std::numeric_limits<double>::infinity();  // 1 / curvature
  // With a section: |N| / A + |My| / Wy + |Mz| / Wz at the more stressed end
  // (3 DOF: |N| / A + |M| / min(Wy, Wz)); with a strength: stress / strength.
  // NaN without.
  double stress = std::numeric_limits<double>::quiet_NaN();
  double utilisation = std::numeric_limits<double>::quiet_NaN();
};

struct VertexResult {  // a 3-DOF beam vertex (eq. 3.41)
  ParticleId p = kNone;
  double curvature = 0;  // 1/m
  double moment = 0;     // N m, EI (curvature - rest curvature)
  double radius = std::numeric_limits<double>::infinity();
};

struct TriangleResult {  // a CST triangle: stresses per unit width [N/m]
  ParticleId i = kNone, j = kNone, k = kNone;
  double warp = 0, weft = 0, shear = 0;  // in the triangle's frame: x along side i -> j (the warp)
  double s1 = 0, s2 = 0;                 // principal stresses, s1 >= s2
  Vec3 d1 = Vec3::Zero(), d2 = Vec3::Zero();  // their unit directions
};

struct BlockResults {
  std::vector<LineResult> lines;        // path order (beams, cables), edge order (bar patches)
  std::vector<VertexResult> vertices;   // 3-DOF beams, path order
  std::vector<TriangleResult> triangles;  // CST patches
};

// `section` (may be null) gives beams their stress; it is ignored elsewhere.
BlockResults element_results(const Model& m, BlockId b, const StressSection* section = nullptr);

// Principal stresses of a plane stress (sx, sy, tau): s1 >= s2, and the
// angle [rad] of s1's direction from x.
void principal_stresses(double sx, double sy, double tau, double& s1, double& s2, double& angle);

}  // namespace tendril
