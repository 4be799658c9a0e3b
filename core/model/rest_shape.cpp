// The rest shape of a beam: straight (bending-active, the default) or the
// shape it is in (no initial stress), for 3-DOF hinges (eq. 3.41's rest
// curvature) and 6-DOF beam ends (appendix A.2, fig. A.1a and A.1b). Each
// operation walks the one beam it changes.
#include <algorithm>
#include <cmath>

#include "model/frames.hpp"
#include "model/hinge_curvature.hpp"
#include "model/model.hpp"

namespace tendril {

const char* rest_shape_name(RestShape r) { return r == RestShape::Current ? "current" : "straight"; }

bool parse_rest_shape(const std::string& name, RestShape& out) {
  if (name == "straight") out = RestShape::Straight;
  else if (name == "current") out = RestShape::Current;
  else return false;
  return true;
}

RestShape Model::rest_shape(BlockId b) const {
  require_block(b, "rest_shape");
  if (blocks[b].kind != BlockKind::Beam)
    throw ModelError("rest_shape: block " + std::to_string(b) + " is a " + block_kind_name(blocks[b].kind) +
                     "; only beams have a rest shape");
  return blocks[b].rest;
}

void Model::set_vertex_rest_curvature(Dart d, double kappa) {
  ++revision;
  rest_curvature[d] = rest_curvature[map.alpha(1, d)] = kappa;
  if (const ElementIndex h = dart_hinge[d]; h != kNone) hinges[h].rest_curvature = kappa;
}

namespace {

// The interior vertices of a beam path: per vertex, the dart arriving at it
// (end of the segment before) and the dart leaving it (start of the next).
struct Vertex {
  Dart in, out;
};

}  // namespace

void Model::set_rest_shape(BlockId b, RestShape r) {
  rest_shape(b);  // a live beam
  const std::vector<Dart> seg = path_darts(b);
  const std::size_t n = seg.size();
  const bool closed = blocks[b].closed;
  std::vector<Vertex> vertices;
  for (std::size_t k = closed ? 0 : 1; k < n; ++k) vertices.push_back({map.alpha(0, seg[(k + n - 1) % n]), seg[k]});
  if (r == RestShape::Current) {
    for (Dart d : seg) {  // refuse before changing anything
      const ParticleId i = dart_particle[d], j = dart_particle[map.alpha(0, d)];
      if (!((particles.position[j] - particles.position[i]).norm() > 0))
        throw ModelError("rest_shape: particles " + std::to_string(i) + " and " + std::to_string(j) + " coincide");
    }
    if (blocks[b].dofs == 6) return release_beam_prestress(b);
    for (Dart d : seg) {  // rest lengths: the current lengths
      const double length =
          (particles.position[dart_particle[map.alpha(0, d)]] - particles.position[dart_particle[d]]).norm();
      set_edge_rest_length(d, length);
      if (const ElementIndex e = dart_bar[d]; e != kNone) {
        unbind_bar(e);
        bars[e].rest_length = length;
        bind_bar(e);
      }
    }
    for (const Vertex& v : vertices) {
      // Eq. 3.41's curvature as hinge_forces measures it, so the hinge's
      // moment is exactly 0 in this shape.
      const Vec3& xi = particles.position[dart_particle[map.alpha(0, v.out)]];
      const Vec3& xj = particles.position[dart_particle[v.out]];
      const Vec3& xk = particles.position[dart_particle[map.alpha(0, v.in)]];
      // The hinge at v.out reads i from alpha0(v.out)'s side: orient as it does.
      const Hinge* h = dart_hinge[v.out] != kNone ? &std::as_const(hinges)[dart_hinge[v.out]] : nullptr;
      const Vec3 &pi = h ? particles.position[h->i] : xk, &pj = h ? particles.position[h->j] : xj,
                 &pk = h ? particles.position[h->k] : xi;
      const Vec3 a = pj - pi, c = pk - pj;
      const double La = a.norm(), Lb = c.norm(), Lc = (pk - pi).norm();
      const double nn = a.cross(c).norm();
      set_vertex_rest_curvature(v.out, nn > 0 && Lc > 0 ? hinge_curvature(nn, 1.0 / La, 1.0 / Lb, Lc) : 0.0);
    }
    blocks[b].rest = RestShape::Current;
    return;
  }
  // Straight: hinges straight at rest; 6-DOF joints share one beam end (A.4)
  // averaged from the two they have.
  for (const Vertex& v : vertices) set_vertex_rest_curvature(v.out, 0.0);
  if (blocks[b].dofs == 6) {
    for (const Vertex& v : vertices) {
      const ParticleId p = dart_particle[v.out];
      const Quat q = particles.orientation[p];
      const Mat3 before = (q * beam_end[v.in] * end_flip()).toRotationMatrix();  // looking forwards
      const Mat3 after = (q * beam_end[v.out]).toRotationMatrix();
      const Quat joint = Quat(q.conjugate() * quat_of(averaged_joint(before, after))).normalized();
      beam_end[v.out] = joint;
      beam_end[v.in] = Quat(joint * end_flip());
    }
    for (Dart d : seg) refresh_beam6(d);
  }
  blocks[b].rest = RestShape::Straight;
}

// 3 -> 6 DOF on a Current beam: init_beam_frames gave each joint one shared
// beam end J (A.4); the two ends turn apart from it by half the rest turning
// angle each, about the normal of the current bend (J's z when straight), so
// the joint is stress free when bent as its hinge was at rest. The turning
// angle theta of two links of length l with 2 sin(theta) / Lc = kappa is
// 2 asin(kappa l / 2) (equal links; l their mean).
void Model::tilt_rest_ends(BlockId b) {
  const std::vector<Dart> seg = path_darts(b);
  const std::size_t n = seg.size();
  for (std::size_t k = blocks[b].closed ? 0 : 1; k < n; ++k) {
    const Dart in = map.alpha(0, seg[(k + n - 1) % n]), out = seg[k];
    const double kappa = rest_curvature[out];
    if (kappa == 0) continue;
    const double l = 0.5 * (rest_length[in] + rest_length[out]);
    const double theta = 2 * std::asin(std::min(1.0, 0.5 * kappa * l));
    const ParticleId p = dart_particle[out];
    const Vec3 x = particles.position[p];
    const Vec3 t_in = x - particles.position[dart_particle[map.alpha(0, in)]];
    const Vec3 t_out = particles.position[dart_particle[map.alpha(0, out)]] - x;
    const Quat q = particles.orientation[p];
    const Quat J = q * beam_end[out];
    Vec3 axis = t_in.cross(t_out);
    if (!(axis.norm() > 1e-12 * t_in.norm() * t_out.norm())) axis = J * Vec3::UnitZ();
    axis.normalize();
    const Quat half(Eigen::AngleAxisd(0.5 * theta, axis));
    beam_end[out] = Quat(q.conjugate() * half * J).normalized();
    beam_end[in] = Quat(q.conjugate() * half.conjugate() * J * end_flip()).normalized();
  }
}

// 6 -> 3 DOF on a Current beam: each hinge's rest curvature from the turning
// angle theta between its two beam ends (each looking forwards) and the rest
// lengths La, Lb: 2 sin(theta) / Lc, Lc^2 = La^2 + Lb^2 + 2 La Lb cos(theta)
// (eq. 3.41 on the rest polygon).
void Model::rest_curvature_from_ends(BlockId b) {
  const std::vector<Dart> seg = path_darts(b);
  const std::size_t n = seg.size();
  for (std::size_t k = blocks[b].closed ? 0 : 1; k < n; ++k) {
    const Dart in = map.alpha(0, seg[(k + n - 1) % n]), out = seg[k];
    const Vec3 t_in = -(beam_end[in] * Vec3::UnitX()), t_out = beam_end[out] * Vec3::UnitX();
    const double s = t_in.cross(t_out).norm(), c = t_in.dot(t_out);
    const double La = rest_length[in], Lb = rest_length[out];
    const double Lc = std::sqrt(std::max(0.0, La * La + Lb * Lb + 2 * La * Lb * c));
    set_vertex_rest_curvature(out, Lc > 0 ? 2 * s / Lc : 0.0);
  }
}

}  // namespace tendril
