#include "query/element_results.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <unordered_map>

#include "model/frames.hpp"
#include "model/hinge_curvature.hpp"
#include "physics/element_forces.hpp"

namespace tendril {

void principal_stresses(double sx, double sy, double tau, double& s1, double& s2, double& angle) {
  const double mean = 0.5 * (sx + sy), radius = std::hypot(0.5 * (sx - sy), tau);  // Mohr's circle
  s1 = mean + radius;
  s2 = mean - radius;
  angle = 0.5 * std::atan2(2 * tau, sx - sy);
}

namespace {

// Two end values within this relative difference are a tie (rounding).
constexpr double kTie = 1e-12;

double bar_axial(const Bar& bar, const Vec3* x, LineResult& r) {
  const double l = (x[bar.j] - x[bar.i]).norm();
  r.strain = (l - bar.rest_length) / bar.rest_length;
  r.axial = bar.prestress + bar.EA * r.strain;  // eq. 3.32
  if (bar.tension_only && r.axial < 0) {
    r.axial = 0;
    r.slack = true;
  }
  return r.axial;
}

// A 6-DOF element: the end torques of the solver's kernel (beam6_ends)
// resolved in its element frame. At end a the internal moment is the
// torque the element puts on node a turned back (-ta), at end b the
// torque on b (tb): one sign along the beam, so a constant moment reads the
// same at both ends.
void beam6_result(const Beam6& b, const Vec3* x, const Quat* q, const StressSection* sec, LineResult& r) {
  const Vec3 d = x[b.j] - x[b.i];
  const double l = d.norm();
  r.strain = (l - b.rest_length) / b.rest_length;
  r.axial = b.prestress + b.EA * r.strain;  // eq. 3.32, as in beam6_ends
  if (!(l > 0)) return;
  const Beam6Ends e = beam6_ends(b, x, q, 0);
  const Mat3 U = element_frame(d / l, (q[b.i] * b.end_i).toRotationMatrix(), (q[b.j] * b.end_j).toRotationMatrix());
  r.torsion = e.ta.dot(U.col(0));
  const double end_y[2] = {-e.ta.dot(U.col(1)), e.tb.dot(U.col(1))};
  const double end_z[2] = {-e.ta.dot(U.col(2)), e.tb.dot(U.col(2))};
  double worst = -1;
  // The end with the smaller particle id first, and a tie to rounding keeps
  // it: the same end whichever way the element is walked (a reloaded ring
  // may close the other way round).
  for (int k : b.i < b.j ? std::array{0, 1} : std::array{1, 0}) {
    const double My = end_y[k], Mz = end_z[k];
    const double M = std::hypot(My, Mz);
    const double s = sec ? std::abs(r.axial) / sec->A + std::abs(My) / sec->Wy + std::abs(Mz) / sec->Wz : M;
    if (worst >= 0 && s <= worst * (1 + kTie)) continue;
    worst = s;
    r.My = My, r.Mz = Mz, r.moment = M, r.at = k == 0 ? b.i : b.j;
    r.curvature = std::hypot(b.EIy > 0 ? My / b.EIy : 0.0, b.EIz > 0 ? Mz / b.EIz : 0.0);
    if (sec) r.stress = s;
  }
  r.radius = r.curvature > 0 ? 1 / r.curvature : std::numeric_limits<double>::infinity();
}

}  // namespace

BlockResults element_results(const Model& m, BlockId block, const StressSection* section) {
  m.require_block(block, "results");
  const Block& blk = m.blocks[block];
  const bool beam = blk.kind == BlockKind::Beam;
  const StressSection* sec = beam && section && section->A > 0 ? section : nullptr;
  BlockResults out;
  const Vec3* x = m.particles.position.data();
  const Quat* q = m.particles.orientation.data();
  // Path order: elements keyed by the position of their particles along the
  // block's particles; a ring's closing element comes last.
  const std::vector<ParticleId> order = m.particles_of(block);
  std::unordered_map<ParticleId, std::size_t> at;
  for (std::size_t k = 0; k < order.size(); ++k) at.emplace(order[k], k);
  auto rank = [&](ParticleId p) { auto it = at.find(p); return it == at.end() ? order.size() : it->second; };
  auto line_rank = [&](const LineResult& s) {
    const std::size_t ra = rank(s.a), rb = rank(s.b);
    return ra + 1 < rb || rb + 1 < ra ? std::max(ra, rb) : std::min(ra, rb);
  };

  for (const Hinge& h : m.hinges.items) {
    if (m.dart_block[h.dart] != block) continue;
    VertexResult v{h.j};
    const Vec3 a = x[h.j] - x[h.i], c = x[h.k] - x[h.j];
    const double Lc = (x[h.k] - x[h.i]).norm();
    v.curvature = Lc > 0 ? hinge_curvature(a.cross(c).norm(), 1.0 / a.norm(), 1.0 / c.norm(), Lc) : 0;  // eq. 3.41
    v.moment = h.EI * (v.curvature - h.rest_curvature);
    v.radius = v.curvature > 0 ? 1 / v.curvature : std::numeric_limits<double>::infinity();
    out.vertices.push_back(v);
  }
  std::stable_sort(out.vertices.begin(), out.vertices.end(),
                   [&](const VertexResult& s, const VertexResult& t) { return rank(s.p) < rank(t.p); });

  for (const Bar& bar : m.bars.items) {
    if (m.dart_block[bar.dart] != block) continue;
    LineResult r{bar.i, bar.j};
    r.at = std::min(bar.i, bar.j);  // no moment: the stress is N / A all along
    bar_axial(bar, x, r);
    out.lines.push_back(r);
  }
  for (const Beam6& b : m.beam6s.items) {
    if (m.dart_block[b.dart] != block) continue;
    LineResult r{b.i, b.j};
    beam6_result(b, x, q, sec, r);
    out.lines.push_back(r);
  }
  std::stable_sort(out.lines.begin(), out.lines.end(),
                   [&](const LineResult& s, const LineResult& t) { return line_rank(s) < line_rank(t); });

  // 3-DOF links: the larger hinge moment of their two end vertices.
  if (beam && blk.dofs == 3) {
    std::unordered_map<ParticleId, const VertexResult*> vertex;
    for (const VertexResult& v : out.vertices) vertex.emplace(v.p, &v);
    const double W = sec ? std::min(sec->Wy, sec->Wz) : 0;
    for (LineResult& r : out.lines) {
      bool found = false;  // as for 6 DOF: the smaller id first, ties keep it
      for (ParticleId p : {std::min(r.a, r.b), std::max(r.a, r.b)}) {
        auto it = vertex.find(p);
        if (it == vertex.end() || (found && std::abs(it->second->moment) <= r.moment * (1 + kTie))) continue;
        found = true;
        r.moment = std::abs(it->second->moment);
        r.at = p;
        r.My = it->second->moment;
        r.curvature = it->second->curvature;
        r.radius = it->second->radius;
      }
      if (sec) r.stress = std::abs(r.axial) / sec->A + r.moment / W;
    }
  }
  if (sec && sec->strength > 0)
    for (LineResult& r : out.lines) r.utilisation = r.stress / sec->strength;

  for (const Cst& t : m.csts.items) {
    if (m.dart_block[t.dart] != block) continue;
    TriangleResult r{t.i, t.j, t.k};
    const Membrane& mb = t.membrane;
    r.warp = mb.sigma_warp, r.weft = mb.sigma_weft;
    const Vec3 a = x[t.j] - x[t.i], b = x[t.k] - x[t.i];
    const Vec3 n = a.cross(b);
    const double twice_area = n.norm(), l1 = a.norm();
    if (!(twice_area > 0 && l1 > 0)) {  // no plane: no stress (cst_forces.cpp exerts none)
      out.triangles.push_back(r);
      continue;
    }
    const Vec3 e1 = a / l1, e3 = n / twice_area, e2 = e3.cross(e1);
    if (mb.mode == Membrane::Analysis) {  // eq. 3.37-3.38, as cst_forces.cpp
      const CstReference& ref = t.ref;
      const double h = twice_area / l1, c = b.dot(e1);
      const double ex = l1 / ref.l1 - 1, ey = h / ref.h - 1;
      r.warp += mb.dxx * ex + mb.dxy * ey;
      r.weft += mb.dyx * ex + mb.dyy * ey;
      r.shear = mb.G * (c - ref.c * (1 + ex)) / ref.h;
    }
    double angle = 0;
    principal_stresses(r.warp, r.weft, r.shear, r.s1, r.s2, angle);
    r.d1 = std::cos(angle) * e1 + std::sin(angle) * e2;
    r.d2 = e3.cross(r.d1);
    out.triangles.push_back(r);
  }
  return out;
}

}  // namespace tendril
