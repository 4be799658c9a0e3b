#pragma once
// Where an element loop adds its forces, stiffnesses, torques and
// rotational stiffnesses: the model's arrays (the element pass), or a
// chunk's 4-lane sums (the fused step, bar_chunks.hpp's ForceSum: force or
// torque in lanes 0-2, stiffness in lane 3), lane by lane, so that a force
// leaves the stiffness lane untouched and the other way round, and every
// sum takes the element pass's additions in its order, bit for bit.
#include "model/types.hpp"
#include "physics/bar_chunks.hpp"

namespace tendril {

struct ModelSink {
  Vec3 *F;
  double* S;
  Vec3* T = nullptr;
  double* K = nullptr;
  void force(ParticleId p, const Vec3& f) const { F[p] += f; }
  void stiffness(ParticleId p, double s) const { S[p] += s; }
  void torque(ParticleId p, const Vec3& t) const { T[p] += t; }
  void rot_stiffness(ParticleId p, double k) const { K[p] += k; }
};

struct ChunkSink {
  ForceSum* sums;             // forces and stiffnesses from the chunk's first id
  ParticleId base;
  ForceSum* turns = nullptr;  // torques and rotational stiffnesses, the same way
  static void add(ForceSum& v, const Vec3& f) {
    v[0] += f.x();
    v[1] += f.y();
    v[2] += f.z();
  }
  void force(ParticleId p, const Vec3& f) const { add(sums[p - base], f); }
  void stiffness(ParticleId p, double s) const { sums[p - base][3] += s; }
  void torque(ParticleId p, const Vec3& t) const { add(turns[p - base], t); }
  void rot_stiffness(ParticleId p, double k) const { turns[p - base][3] += k; }
};

}  // namespace tendril
