#pragma once
// Frames of the 6-DOF beam: the rotation of a rotation vector (eq. 3.16),
// appendix A's initial beam orientation (A.1-A.3) and averaged joint (A.4),
// and the element frame the included angles of eq. 3.44 are measured in.
// A frame is a rotation matrix whose columns are the local x, y, z axes.
#include <cmath>

#include "model/half_angle.hpp"
#include "model/types.hpp"

namespace tendril {

// Eq. 3.16: the rotation by the angle |r| about the axis r / |r|.
// A beam end stored at a dart looks along its edge, away from the dart's
// particle (Model::beam_end); the element from i to j reads the end at j
// turned around: a half turn about z, x -> -x, y -> -y. So a straight joint
// stores J at the dart leaving forwards and J * end_flip() at the dart
// arriving, and an edge may take either of its darts as its start.
inline Quat end_flip() { return Quat(0.0, 0.0, 0.0, 1.0); }

// Below this squared angle sin(t/2)/t is 1/2 to double precision.
constexpr double kSmallAngle2 = 1e-24;

inline Quat rotation_of(const Vec3& r) {
  const double theta2 = r.squaredNorm();
  if (theta2 < kSmallAngle2) {
    Quat q(1.0, 0.5 * r.x(), 0.5 * r.y(), 0.5 * r.z());
    q.normalize();
    return q;
  }
  const double theta = std::sqrt(theta2);
  double sin_half, cos_half;
  half_angle_sincos(0.5 * theta, sin_half, cos_half);  // as frame_drift.cpp's blocks
  const double s = sin_half / theta;
  return Quat(cos_half, s * r.x(), s * r.y(), s * r.z());
}

// The frame with x along `x` and y as close to `ref` as x allows; false when
// `ref` is (nearly) parallel to x.
inline bool frame_with_reference(const Vec3& x, const Vec3& ref, Mat3& out) {
  Vec3 y = ref - ref.dot(x) * x;
  const double n = y.norm();
  if (!(n > 1e-9 * (1 + ref.norm()))) return false;
  y /= n;
  out.col(0) = x;
  out.col(1) = y;
  out.col(2) = x.cross(y);
  return true;
}

// A.1-A.3: x along the chord, y = Z x u_x (another global axis when the chord
// is vertical), z = x cross y.
inline Mat3 initial_beam_frame(const Vec3& ux) {
  Mat3 f;
  Vec3 y = Vec3::UnitZ().cross(ux);
  if (y.norm() < 1e-9) y = Vec3::UnitY().cross(ux);
  y.normalize();
  f.col(0) = ux;
  f.col(1) = y;
  f.col(2) = ux.cross(y);
  return f;
}

// A.4: the shared beam-end orientation of an initially straight joint between
// the beam orientations l and r. Falls back to r for a joint folded back on
// itself.
inline Mat3 averaged_joint(const Mat3& l, const Mat3& r) {
  Vec3 ez = l.col(2) + r.col(2);
  if (ez.norm() < 1e-9) return r;
  ez.normalize();
  Vec3 ey = ez.cross(l.col(0) + r.col(0));
  if (ey.norm() < 1e-9) return r;
  ey.normalize();
  Mat3 f;
  f.col(0) = ey.cross(ez);
  f.col(1) = ey;
  f.col(2) = ez;
  return f;
}

// The element frame of eq. 3.44: x along the chord u_x, y and z from the
// average of the two beam ends' z (their y when that average lies along the
// chord).
inline Mat3 element_frame(const Vec3& ux, const Mat3& Ea, const Mat3& Eb) {
  Mat3 f;
  f.col(0) = ux;
  Vec3 y = (Ea.col(2) + Eb.col(2)).cross(ux);
  double n = y.norm();
  if (n > 1e-12) {
    f.col(1) = y / n;
    f.col(2) = ux.cross(f.col(1));
  } else {
    Vec3 z = ux.cross(Ea.col(1) + Eb.col(1));
    n = z.norm();
    if (!(n > 1e-12)) return initial_beam_frame(ux);
    f.col(2) = z / n;
    f.col(1) = f.col(2).cross(ux);
  }
  return f;
}

inline Quat quat_of(const Mat3& frame) {
  Quat q(frame);
  q.normalize();
  return q;
}

// The middle of a 6-DOF beam element whose ends sit at xa, xb with beam-end
// frames Ea, Eb (both looking from a to b): the point and frame of its cubic (Hermite) deflection curve
// at half length, the curve eq. 3.46's end moments belong to. Splitting the
// element there (rule 13) keeps its state: each half is the same cubic.
inline void beam6_midpoint(const Vec3& xa, const Vec3& xb, const Quat& Ea, const Quat& Eb, Vec3& x, Quat& frame) {
  const double l = (xb - xa).norm();
  frame = Quat(Ea.slerp(0.5, Eb)).normalized();  // the twist halfway
  x = 0.5 * (xa + xb);
  if (!(l > 0)) return;
  const Mat3 A = Ea.toRotationMatrix(), B = Eb.toRotationMatrix();
  const Vec3 ux = (xb - xa) / l;
  const Mat3 U = element_frame(ux, A, B);
  // End slopes of the deflections along the element's y and z.
  const double va = A.col(0).dot(U.col(1)), vb = B.col(0).dot(U.col(1));
  const double wa = A.col(0).dot(U.col(2)), wb = B.col(0).dot(U.col(2));
  x += (l / 8) * ((va - vb) * U.col(1) + (wa - wb) * U.col(2));
  const Vec3 tangent = (ux - 0.25 * (va + vb) * U.col(1) - 0.25 * (wa + wb) * U.col(2)).normalized();
  frame = Quat(Quat::FromTwoVectors(frame * Vec3::UnitX(), tangent) * frame).normalized();
}

}  // namespace tendril
