// Rotational joints (thesis 6.5.2): bookkeeping and the topological query
// that finds a joint's four neighbours.
#include <cmath>

#include "model/model.hpp"

namespace tendril {

bool Model::joint_neighbours(ParticleId p, ParticleId out[4]) const {
  if (!particles.valid(p) || particles.degree[p] != 4) return false;
  // Four darts: two beam vertices of two distinct beams, each interior.
  BlockId first = kNone;
  int na = 0, nb = 0;
  Dart head = particles.first_dart[p], d = head;
  do {
    const BlockId b = dart_block[d];
    if (blocks[b].kind != BlockKind::Beam) return false;
    if (first == kNone) first = b;
    const ParticleId n = dart_particle[map.alpha(0, d)];
    if (b == first) {
      if (na == 2) return false;
      out[na++] = n;
    } else {
      if (nb == 2) return false;
      out[2 + nb++] = n;
    }
    d = ring_next[d];
  } while (d != head);
  return na == 2 && nb == 2;
}

std::size_t Model::add_joint(ParticleId p, double angle, double stiffness) {
  require_particle(p, "joint");
  ParticleId n[4];
  if (!joint_neighbours(p, n))
    throw ModelError("joint: particle " + std::to_string(p) + " is not an interior crossing of exactly two beams");
  if (!std::isfinite(angle)) throw ModelError("joint: the angle must be finite");
  if (!(stiffness > 0) || !std::isfinite(stiffness)) throw ModelError("joint: the stiffness must be > 0");
  ++revision;
  joints.items.push_back(RotationalJoint{p, angle, stiffness});
  return joints.size() - 1;
}

void Model::set_joint_angle(std::size_t joint, double angle) {
  if (joint >= joints.size()) throw ModelError("joint_angle: no joint " + std::to_string(joint));
  if (!std::isfinite(angle)) throw ModelError("joint_angle: the angle must be finite");
  joints[joint].angle = angle;
}

}  // namespace tendril
