// Rule 9: a spline beam that grows particle by particle (thesis fig. 4.26),
// the way an agent's children become a beam.
#include "model/frames.hpp"
#include "model/hinge_curvature.hpp"
#include "model/model.hpp"

namespace tendril {

void Model::extend_beam(BlockId b, ParticleId end, ParticleId p) {
  require_block(b, "extend_beam");
  require_particle(end, "extend_beam");
  require_particle(p, "extend_beam");
  const Block& blk = blocks[b];
  if (blk.kind != BlockKind::Beam || blk.closed)
    throw ModelError("extend_beam: block " + std::to_string(b) + " is not an open beam");
  // The end dart: a dart of `end` in this beam without an alpha1 partner.
  Dart tip = kNoDart;
  for (Dart d : darts_of(end))
    if (dart_block[d] == b && map.is_free(1, d)) tip = d;
  if (tip == kNoDart)
    throw ModelError("extend_beam: particle " + std::to_string(end) + " is not an end of beam " + std::to_string(b));
  if (!clamp[tip].isZero(0))
    throw ModelError("extend_beam: the end of beam " + std::to_string(b) + " at particle " + std::to_string(end) +
                     " is clamped; unclamp it first");
  for (Dart d : darts_of(p))
    if (dart_block[d] == b) throw ModelError("extend_beam: particle " + std::to_string(p) + " is already on the beam");
  const double length = (particles.position[p] - particles.position[end]).norm();
  if (!(length > 0)) throw ModelError("extend_beam: particles " + std::to_string(end) + " and " + std::to_string(p) + " coincide");
  Dart d = new_dart(b, end), e = new_dart(b, p);
  map.link(0, d, e);
  map.link(1, tip, d);
  set_edge_rest_length(d, length);
  const bool as_built = blk.rest == RestShape::Current;
  if (blk.dofs == 6) {
    // A straight joint at `end`: the new beam end is the old one turned to
    // look along the new edge; p's is that orientation carried along to the
    // new chord (turned to look back). A Current beam takes the joint as it
    // is: the new beam end along the new chord (fig. A.1b, no prestress).
    beam_end[d] = Quat(beam_end[tip] * end_flip());
    if (as_built) {
      const Quat at = particles.orientation[end] * beam_end[d];
      const Vec3 chord = (particles.position[p] - particles.position[end]) / length;
      beam_end[d] = Quat(particles.orientation[end].conjugate() *
                         Quat::FromTwoVectors(at * Vec3::UnitX(), chord) * at).normalized();
    }
    const Quat joint = particles.orientation[end] * beam_end[d];
    const Vec3 chord = (particles.position[p] - particles.position[end]) / length;
    const Quat far = Quat(Quat::FromTwoVectors(joint * Vec3::UnitX(), chord) * joint).normalized();
    if (particles.rot_degree[p] == 0 && !(particles.lock[p] & kLockRotation)) {
      particles.orientation[p] = far;
      particles.angular_velocity[p].setZero();
      beam_end[e] = end_flip();
    } else {
      beam_end[e] = Quat(particles.orientation[p].conjugate() * far * end_flip()).normalized();
    }
  }
  add_edge_element(d);
  // The new vertex at `end`: straight at rest, or on a Current beam the
  // curvature it is built with (eq. 3.41, as hinge_forces measures it).
  double kappa = 0;
  if (as_built) {
    const Vec3& prev = particles.position[dart_particle[map.alpha(0, tip)]];
    const Vec3 a = particles.position[end] - prev, c = particles.position[p] - particles.position[end];
    const double La = a.norm(), Lb = c.norm(), Lc = (particles.position[p] - prev).norm();
    const double nn = a.cross(c).norm();
    if (nn > 0 && Lc > 0) kappa = hinge_curvature(nn, 1.0 / La, 1.0 / Lb, Lc);
  }
  rest_curvature[tip] = rest_curvature[d] = kappa;
  add_vertex_element(tip);
  if (blocks[b].dart == tip) blocks[b].dart = e;  // grown at its start: the path now starts at p
}

}  // namespace tendril
