#pragma once
// Where an element loop adds its forces, stiffnesses, torques and
// rotational stiffnesses: the model's arrays (the element pass), or a
// chunk's 4-lane sums (the fused step, bar_chunks.hpp's ForceSum: force or
// torque in lanes 0-2, stiffness in lane 3), so that every sum takes the
// element pass's additions in its order, bit for bit.
#include "model/types.hpp"
#include "physics/bar_chunks.hpp"

namespace tendril {

struct ModelSink {
  Vec3 *F;
  double* S;
  Vec3* T = nullptr;
  double* K = nullptr;
  void force(ParticleId p, const Vec3& f) const { F[p] += f; }
  // S[p] += s, then += each of `more`, in order: one load and one store.
  template <class... More>
  void stiffness(ParticleId p, double s, More... more) const {
    S[p] = ((S[p] + s) + ... + more);
  }
  void torque(ParticleId p, const Vec3& t) const { T[p] += t; }
  void rot_stiffness(ParticleId p, double k) const { K[p] += k; }
  // A force and a stiffness (a torque and a rotational stiffness) at once.
  void force_stiffness(ParticleId p, const Vec3& f, double s) const { F[p] += f, S[p] += s; }
  void torque_stiffness(ParticleId p, const Vec3& t, double k) const { T[p] += t, K[p] += k; }
};

struct ChunkSink {
  ForceSum* sums;             // forces and stiffnesses from the chunk's first id
  ParticleId base;
  ForceSum* turns = nullptr;  // torques and rotational stiffnesses, the same way
  // The fourth lane takes + 0, which is exact: a stiffness sum starts at
  // +0 and never becomes -0. (A stiffness added as a 4-vector would add
  // + 0 to the force lanes, which turns a -0 into +0: it is added alone.)
  static void add(ForceSum& v, const Vec3& f) { v += ForceSum{f.x(), f.y(), f.z(), 0.0}; }
  void force(ParticleId p, const Vec3& f) const { add(sums[p - base], f); }
  template <class... More>
  void stiffness(ParticleId p, double s, More... more) const {
    ForceSum& v = sums[p - base];  // (a reference to one lane is GCC's only)
    v[3] = ((v[3] + s) + ... + more);
  }
  void torque(ParticleId p, const Vec3& t) const { add(turns[p - base], t); }
  void rot_stiffness(ParticleId p, double k) const { turns[p - base][3] += k; }
  // One addition per lane, as the two calls make: one 4-vector.
  void force_stiffness(ParticleId p, const Vec3& f, double s) const {
    sums[p - base] += ForceSum{f.x(), f.y(), f.z(), s};
  }
  void torque_stiffness(ParticleId p, const Vec3& t, double k) const {
    turns[p - base] += ForceSum{t.x(), t.y(), t.z(), k};
  }
};

}  // namespace tendril
