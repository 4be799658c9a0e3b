// Switching a beam between the 3-DOF spline beam and the 6-DOF beam
// (thesis 5.5.2.1) and the initial frames of 6-DOF beams (appendix A). Each
// operation walks the one beam it changes.
#include <set>

#include "model/frames.hpp"
#include "model/model.hpp"

namespace tendril {

std::vector<Dart> Model::path_darts(BlockId b) const {
  const Block& blk = blocks[b];
  std::vector<Dart> out;
  Dart d = blk.dart;
  for (std::size_t guard = 0; guard <= blk.darts; ++guard) {
    out.push_back(d);
    const Dart e = map.alpha(0, d), next = map.alpha(1, e);
    if (next == e || next == blk.dart) break;
    d = next;
  }
  return out;
}

int Model::beam_formulation(BlockId b) const {
  require_block(b, "formulation");
  return blocks[b].dofs;
}

void Model::set_beam_formulation(BlockId b, int dofs) {
  require_block(b, "formulation");
  if (blocks[b].kind != BlockKind::Beam)
    throw ModelError("formulation: block " + std::to_string(b) + " is a " + block_kind_name(blocks[b].kind) +
                     "; only beams switch between 3 and 6 DOF");
  if (dofs != 3 && dofs != 6)
    throw ModelError("formulation: a beam has 3 or 6 DOF per particle, not " + std::to_string(dofs));
  if (blocks[b].dofs == dofs) return;
  const std::vector<Dart> darts = map.orbit(kComponentOrbit, blocks[b].dart);
  for (Dart d : darts) {
    remove_hinge(d);
    remove_edge_element(d);
  }
  blocks[b].dofs = std::uint8_t(dofs);
  if (dofs == 6) init_beam_frames(b);
  if (blocks[b].rest == RestShape::Current) {  // the curved rest shape goes along
    if (dofs == 6) tilt_rest_ends(b);
    else rest_curvature_from_ends(b);
  }
  for (Dart d : darts) {
    if (dart_bar[d] == kNone && dart_beam6[d] == kNone) add_edge_element(d);
    if (dart_hinge[d] == kNone) add_vertex_element(d);
  }
  if (dofs == 3)  // rotations drop where no other 6-DOF beam keeps them
    for (Dart d : darts)
      if (particles.rot_degree[dart_particle[d]] == 0) particles.angular_velocity[dart_particle[d]].setZero();
}

void Model::init_beam_frames(BlockId b) {
  const Block& blk = blocks[b];
  const std::vector<Dart> seg = path_darts(b);  // segment k starts at seg[k]
  const std::size_t n = seg.size();
  auto start = [&](std::size_t k) { return dart_particle[seg[k]]; };
  auto finish = [&](std::size_t k) { return dart_particle[map.alpha(0, seg[k])]; };

  // Chord directions; a segment squeezed to nothing borrows its neighbour's.
  std::vector<Vec3> t(n, Vec3::UnitX());
  std::vector<bool> known(n, false);
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3 c = particles.position[finish(k)] - particles.position[start(k)];
    if (c.norm() > 0 && c.allFinite()) {
      t[k] = c.normalized();
      known[k] = true;
    }
  }
  for (std::size_t k = 1; k < n; ++k)
    if (!known[k] && known[k - 1]) t[k] = t[k - 1], known[k] = true;
  for (std::size_t k = n - 1; k-- > 0;)
    if (!known[k] && known[k + 1]) t[k] = t[k + 1], known[k] = true;

  // The twist reference: the first rotation-locked particle's frame, else
  // appendix A.1 on the first chord.
  const std::size_t vertices = blk.closed ? n : n + 1;
  auto vertex_particle = [&](std::size_t v) { return v < n ? start(v) : finish(n - 1); };
  std::vector<Mat3> chord(n);
  std::size_t ref = 0;
  bool referenced = false;
  for (std::size_t v = 0; v < vertices && !referenced; ++v) {
    const ParticleId p = vertex_particle(v);
    if (!(particles.lock[p] & kLockRotation)) continue;
    const std::size_t k = v < n ? v : n - 1;
    const Mat3 R = particles.orientation[p].toRotationMatrix();
    if (frame_with_reference(t[k], R.col(1), chord[k]) || frame_with_reference(t[k], R.col(2), chord[k])) {
      ref = k;
      referenced = true;
    }
  }
  if (!referenced) chord[ref] = initial_beam_frame(t[ref]);
  // Parallel transport: each chord frame is its neighbour's turned by the
  // smallest rotation between their chords, so no twist is invented.
  auto transport = [&](std::size_t from, std::size_t to) {
    chord[to] = Quat::FromTwoVectors(t[from], t[to]).toRotationMatrix() * chord[from];
  };
  if (blk.closed) {
    for (std::size_t s = 1; s < n; ++s) transport((ref + s - 1) % n, (ref + s) % n);
  } else {
    for (std::size_t k = ref + 1; k < n; ++k) transport(k - 1, k);
    for (std::size_t k = ref; k-- > 0;) transport(k + 1, k);
  }

  // One shared beam-end orientation per joint (A.4), the chord frame at the
  // ends of an open beam.
  std::set<ParticleId> framed;  // particles given a frame by this walk
  for (std::size_t v = 0; v < vertices; ++v) {
    Mat3 joint;
    if (!blk.closed && v == 0) joint = chord[0];
    else if (!blk.closed && v == n) joint = chord[n - 1];
    else joint = averaged_joint(chord[(v + n - 1) % n], chord[v % n]);
    const ParticleId p = vertex_particle(v);
    Quat rel = Quat::Identity();
    if (particles.lock[p] & kLockRotation) {
      // A rotation-locked particle imposes its own twist on its beam end.
      const Mat3 R = particles.orientation[p].toRotationMatrix();
      Mat3 twisted;
      if (frame_with_reference(joint.col(0), R.col(1), twisted) ||
          frame_with_reference(joint.col(0), R.col(2), twisted))
        joint = twisted;
      rel = Quat(particles.orientation[p].conjugate() * quat_of(joint)).normalized();
    } else if (particles.rot_degree[p] > 0 || framed.count(p)) {
      rel = Quat(particles.orientation[p].conjugate() * quat_of(joint)).normalized();
    } else {
      particles.orientation[p] = quat_of(joint);
      particles.angular_velocity[p].setZero();
      framed.insert(p);
    }
    // The darts of this vertex: the end of the segment before (looking
    // back), the start of the one after.
    if (blk.closed || v > 0) beam_end[map.alpha(0, seg[(v + n - 1) % n])] = Quat(rel * end_flip());
    if (blk.closed || v < n) beam_end[seg[v % n]] = rel;
  }
}

void Model::release_beam_prestress(BlockId b) {
  require_block(b, "release_prestress");
  if (blocks[b].kind != BlockKind::Beam || blocks[b].dofs != 6)
    throw ModelError("release_prestress: block " + std::to_string(b) + " is not a 6-DOF beam");
  const std::vector<Dart> darts = path_darts(b);
  for (Dart d : darts) {  // refuse before changing anything
    const ParticleId i = dart_particle[d], j = dart_particle[map.alpha(0, d)];
    if (!((particles.position[j] - particles.position[i]).norm() > 0))
      throw ModelError("release_prestress: particles " + std::to_string(i) + " and " + std::to_string(j) +
                       " coincide");
  }
  for (Dart d : darts) {
    const Dart e = map.alpha(0, d);
    const ParticleId i = dart_particle[d], j = dart_particle[e];
    const Vec3 c = particles.position[j] - particles.position[i];
    const double length = c.norm();
    const Quat qi = particles.orientation[i], qj = particles.orientation[j];
    const Mat3 Ei = (qi * beam_end[d]).toRotationMatrix(), Ej = (qj * beam_end[e] * end_flip()).toRotationMatrix();
    const Quat element = quat_of(element_frame(c / length, Ei, Ej));
    beam_end[d] = Quat(qi.conjugate() * element).normalized();
    beam_end[e] = Quat(qj.conjugate() * element * end_flip()).normalized();
    set_edge_rest_length(d, length);
    refresh_beam6(d);
  }
  blocks[b].rest = RestShape::Current;
}

}  // namespace tendril
