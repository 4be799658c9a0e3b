#pragma once
// What a block carries at the current positions (issue 14, results): the
// axial force of every bar or cable segment and the bending moment of every
// 3-DOF beam vertex, by the same laws the solver's elements use (eq. 3.32,
// 3.41), in N and N m. A read, O(model).
#include <vector>

#include "model/model.hpp"

namespace tendril {

struct SegmentForce {
  ParticleId a, b;
  double axial = 0;   // N, tension > 0 (eq. 3.32: prestress + EA (l - L) / L)
  double strain = 0;  // (l - L) / L
  bool slack = false;  // a cable segment that would be in compression: it carries 0
};

struct VertexMoment {
  ParticleId p;            // the vertex of a 3-DOF beam
  double curvature = 0;    // 1/m, 2 sin(alpha) / Lc (eq. 3.41)
  double moment = 0;       // N m, EI (curvature - rest curvature)
};

struct MemberForces {
  std::vector<SegmentForce> segments;  // path order for beams and cables; edge order for patches
  std::vector<VertexMoment> vertices;  // 3-DOF beams only, path order
};

MemberForces member_forces(const Model& m, BlockId b);

}  // namespace tendril
