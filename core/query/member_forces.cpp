#include "query/member_forces.hpp"

#include <algorithm>
#include <map>

#include "model/hinge_curvature.hpp"

namespace tendril {

MemberForces member_forces(const Model& m, BlockId block) {
  m.require_block(block, "forces");
  MemberForces out;
  const Vec3* x = m.particles.position.data();
  // Path order: the bars and hinges of the block keyed by the position of
  // their first particle along the block's particles.
  const std::vector<ParticleId> order = m.particles_of(block);
  std::map<ParticleId, std::size_t> at;
  for (std::size_t k = 0; k < order.size(); ++k) at.emplace(order[k], k);
  auto rank = [&](ParticleId p) { auto it = at.find(p); return it == at.end() ? order.size() : it->second; };
  for (const Bar& bar : m.bars.items) {
    if (m.dart_block[bar.dart] != block) continue;
    SegmentForce f{bar.i, bar.j};
    const double l = (x[bar.j] - x[bar.i]).norm();
    f.strain = (l - bar.rest_length) / bar.rest_length;
    f.axial = bar.prestress + bar.EA * f.strain;
    if (bar.tension_only && f.axial < 0) {
      f.axial = 0;
      f.slack = true;
    }
    out.segments.push_back(f);
  }
  for (const Hinge& h : m.hinges.items) {
    if (m.dart_block[h.dart] != block) continue;
    VertexMoment v{h.j};
    const Vec3 a = x[h.j] - x[h.i], c = x[h.k] - x[h.j];
    const double Lc = (x[h.k] - x[h.i]).norm();
    v.curvature = Lc > 0 ? hinge_curvature(a.cross(c).norm(), 1.0 / a.norm(), 1.0 / c.norm(), Lc) : 0;
    v.moment = h.EI * (v.curvature - h.rest_curvature);
    out.vertices.push_back(v);
  }
  // A segment ranks by its earlier end; a ring's closing segment comes last.
  auto segment_rank = [&](const SegmentForce& s) {
    const std::size_t ra = rank(s.a), rb = rank(s.b);
    return ra + 1 < rb || rb + 1 < ra ? std::max(ra, rb) : std::min(ra, rb);
  };
  std::stable_sort(out.segments.begin(), out.segments.end(),
                   [&](const SegmentForce& s, const SegmentForce& t) { return segment_rank(s) < segment_rank(t); });
  std::stable_sort(out.vertices.begin(), out.vertices.end(),
                   [&](const VertexMoment& s, const VertexMoment& t) { return rank(s.p) < rank(t.p); });
  return out;
}

}  // namespace tendril
