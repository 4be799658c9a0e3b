#pragma once
// The force kernels of single elements, shared by the force accumulation of
// the explicit integrators (forces.cpp) and the projections of the
// constraint-based ones (projections.cpp), so both see the same mechanics.
#include <algorithm>
#include <cmath>

#include "model/elements.hpp"
#include "model/frames.hpp"
#include "model/hinge_curvature.hpp"

namespace tendril {

// Spline-beam hinge (eq. 3.41-3.43): shears on the ends i and k (j takes
// -(fi + fk)) and the direct stiffnesses of its two links.
struct HingeForces {
  Vec3 fi = Vec3::Zero(), fk = Vec3::Zero();
  double ka = 0, kb = 0;  // 4 EI / La^3, 4 EI / Lb^3 (eq. 3.43)
};

inline HingeForces hinge_forces(const Hinge& h, const Vec3* x) {
  HingeForces f;
  const Vec3 a = x[h.j] - x[h.i], b = x[h.k] - x[h.j];
  const double La = a.norm(), Lb = b.norm(), Lc = (x[h.k] - x[h.i]).norm();
  const double inv_La = 1.0 / La, inv_Lb = 1.0 / Lb;
  f.ka = 4 * h.EI * (inv_La * inv_La * inv_La);
  f.kb = 4 * h.EI * (inv_Lb * inv_Lb * inv_Lb);
  const Vec3 nrm = a.cross(b);
  const double nn = nrm.norm();
  if (nn <= 0 || Lc <= 0) return f;  // straight (or degenerate): no bending force
  // Moment EI*(kappa - kappa0) (eq. 3.41).
  const double M = h.EI * (hinge_curvature(nn, inv_La, inv_Lb, Lc) - h.rest_curvature);
  // Shears M/La and M/Lb act normal to the links in the plane ijk
  // (eq. 3.42), pushing the ends away from the centre of curvature. a is
  // normal to nrm, so |a x nrm| = La |nrm|: the unit directions without
  // their norms.
  const double inv_nn = 1.0 / nn;
  f.fi = (M * (inv_La * inv_La * inv_nn)) * a.cross(nrm);
  f.fk = (M * (inv_Lb * inv_Lb * inv_nn)) * b.cross(nrm);
  return f;
}

// Clamp of a 3-DOF beam end p (Model::set_clamp): the hinge between the
// fixed unit tangent t and the end segment p -> q, M = 2 EI sin(alpha) / L1
// (the end vertex owns half its segment: twice an interior hinge's
// stiffness; a circle through the particles is exact). q takes fq, normal
// to the segment in the plane of t and the segment, p takes -fq: the
// clamp's reaction is a moment only. k: 8 EI / L1^3 on both.
struct ClampForces {
  Vec3 fq = Vec3::Zero();
  double k = 0;
};

inline ClampForces clamp_forces(const Vec3& t, double EI, const Vec3& xp, const Vec3& xq) {
  ClampForces f;
  const Vec3 b = xq - xp;
  const double L = b.norm();
  f.k = 8 * EI / (L * L * L);
  const Vec3 nrm = t.cross(b);
  const double nn = nrm.norm();
  if (nn <= 0 || L <= 0) return f;  // along the clamp (or degenerate): no moment
  const double M = 2 * EI * (nn / L) / L;
  f.fq = (M / L) * b.cross(nrm).normalized();
  return f;
}

// Rigid joint of two 3-DOF beams at a shared particle p (Model::set_joint):
// the end segments p -> a and p -> b keep their included angle theta0, in
// the plane they span. theta = atan2(|u x v|, u . v) with u = xa - xp,
// v = xb - xp, exact at any angle (the hinge's 2 sin(alpha) / Lc has no
// stiffness at a right angle); energy k (theta - theta0)^2 / 2, so the
// moment M = k (theta - theta0) acts as the shears M / |u| on a and M / |v|
// on b, normal to their segments in that plane, and p takes the sum
// reversed: a couple only, like a hinge across the joint. k is the
// rotational stiffness (Model::rigid_stiffness). ka, kb: 4 k / L^2 of each
// segment, the hinge's 4 EI / L^3 (eq. 3.43). Collinear segments (theta 0
// or pi) span no plane: no force (the joint then sits at its rest angle or
// at a fold a 3-DOF joint cannot orient).
struct RigidJointForces {
  Vec3 fa = Vec3::Zero(), fb = Vec3::Zero();
  double ka = 0, kb = 0;
};

inline RigidJointForces rigid_joint_forces(double k, double theta0, const Vec3& xp, const Vec3& xa, const Vec3& xb) {
  RigidJointForces f;
  const Vec3 u = xa - xp, v = xb - xp;
  const double lu = u.norm(), lv = v.norm();
  if (!(lu > 0) || !(lv > 0)) return f;
  f.ka = 4 * k / (lu * lu);
  f.kb = 4 * k / (lv * lv);
  const Vec3 n = u.cross(v);
  const double s = n.norm();
  if (!(s > 0)) return f;
  const double M = k * (std::atan2(s, u.dot(v)) - theta0);
  const Vec3 nh = n / s;
  f.fa = (M / lu) * nh.cross(u / lu);   // towards b when opened beyond theta0
  f.fb = (-M / lv) * nh.cross(v / lv);  // towards a
  return f;
}

// Eq. 3.47 and 3.49 bound each direction of a beam end by its own diagonal
// stiffness (12 EI / L^3 for translation, 4 EI / L for rotation). Coupled,
// the bending modes of a beam with those lumped masses reach
// omega^2 = 2.69 * 2 / dt^2 (a chain's free end; 3.5 for one free element),
// beyond Leapfrog's 4 / dt^2. 7/4 on both bending terms bounds every
// element's bending modes, hence every model's, by 4 / dt^2.
inline constexpr double kBendingMassFactor = 1.75;

// Li's co-rotational Euler-Bernoulli element (eq. 3.44-3.46): the force on
// j (i takes -fj), the end torques, and the direct stiffnesses of each end.
struct Beam6Ends {
  Vec3 fj = Vec3::Zero(), ta = Vec3::Zero(), tb = Vec3::Zero();
  double k = 0, kr = 0;  // eq. 3.47, 3.49
};

// Included angles of the beam ends in the element frame, end moments from
// them, the shear forces that balance those moments, and the axial force.
inline Beam6Ends beam6_ends(const Beam6& b, const Vec3* x, const Quat* q, double gf) {
  Beam6Ends e;
  const double L = b.rest_length;
  const Vec3 d = x[b.j] - x[b.i];
  const double l = d.norm();
  const double N = b.prestress + b.EA * (l - L) / L;  // eq. 3.32 with K = EA / L
  const double EI = std::max(b.EIy, b.EIz);
  e.k = std::max(b.EA / L, kBendingMassFactor * 12 * EI / (L * L * L)) +
        (l > 0 && N > 0 ? gf * N / l : 0.0);                        // eq. 3.47
  e.kr = std::max(b.GJ / L, kBendingMassFactor * 4 * EI / L);  // eq. 3.49
  if (!(l > 0)) return e;
  const ParticleId i = b.i, j = b.j;
  const Mat3 Ea = (q[i] * b.end_i).toRotationMatrix(), Eb = (q[j] * b.end_j).toRotationMatrix();
  const Vec3 ux = d / l;  // eq. 3.45
  const Mat3 U = element_frame(ux, Ea, Eb);
  const Vec3 uy = U.col(1), uz = U.col(2);
  // Eq. 3.44: the beam-end tangents measured against the chord, and the
  // relative twist of the two ends about it.
  const double za = Ea.col(0).dot(uy), zb = Eb.col(0).dot(uy);
  const double ya = -Ea.col(0).dot(uz), yb = -Eb.col(0).dot(uz);
  const double twist = 0.5 * (Eb.col(1).dot(Ea.col(2)) - Ea.col(1).dot(Eb.col(2)));
  // Eq. 3.46: end moments; a positive angle is turned back by its moment.
  const double cz = 2 * b.EIz / L, cy = 2 * b.EIy / L;
  const double Mza = cz * (2 * za + zb), Mzb = cz * (za + 2 * zb);
  const double Mya = cy * (2 * ya + yb), Myb = cy * (ya + 2 * yb);
  const double Mx = b.GJ / L * twist;
  e.ta = Mx * ux - Mya * uy - Mza * uz;
  e.tb = -Mx * ux - Myb * uy - Mzb * uz;
  // Shears: the couple that balances the end moments (eq. 3.46's
  // f_y = 6 EI (theta_a + theta_b) / L^2), plus the axial force.
  e.fj = ux.cross(e.ta + e.tb) / l - N * ux;
  return e;
}

// Rotational joint (thesis 6.5.2, fig. 6.32): the targets of its four
// neighbours n (read by Model::joint_neighbours). The axis is the normal of
// the two beams at the shared particle c; one beam's neighbours turn by
// -delta/2 about it, the other's by +delta/2, delta the target included angle
// minus the current one. False when the beams are parallel (no plane).
inline bool joint_targets(const RotationalJoint& jt, const ParticleId n[4], const Vec3* x, Vec3 target[4]) {
  const Vec3 ta = x[n[1]] - x[n[0]], tb = x[n[3]] - x[n[2]];
  Vec3 axis = ta.cross(tb);
  const double len = axis.norm();
  if (!(len > 0)) return false;
  axis /= len;
  const double delta = jt.angle - std::atan2(len, ta.dot(tb));
  const Vec3 c = x[jt.particle];
  for (int k = 0; k < 4; ++k) {
    const double turn = (k < 2 ? -0.5 : 0.5) * delta;
    const Vec3 r = x[n[k]] - c;  // Rodrigues
    target[k] = c + r * std::cos(turn) + axis.cross(r) * std::sin(turn) + axis * axis.dot(r) * (1 - std::cos(turn));
  }
  return true;
}

// Goal (elements.hpp): the pull on i towards its projection (j takes -fi
// for a length) and the goal's direct stiffness, its weight (plus eq. 3.35's
// geometric term for a stretched length goal).
struct GoalForce {
  Vec3 fi = Vec3::Zero();
  double k = 0;
};

inline GoalForce goal_force(const Goal& g, const Vec3* x, double gf) {
  const double w = g.weight;
  const Vec3 r = x[g.i] - g.point;
  switch (g.kind) {
    case Goal::Anchor: return {-w * r, w};
    case Goal::Plane: return {Vec3(-w * r.dot(g.direction) / g.direction.squaredNorm() * g.direction), w};
    case Goal::Line: return {Vec3(-w * (r - r.dot(g.direction) / g.direction.squaredNorm() * g.direction)), w};
    case Goal::Length: {
      const Vec3 d = x[g.j] - x[g.i];
      const double l = d.norm(), T = w * (l - g.length);
      if (!(l > 0)) return {Vec3::Zero(), w};
      return {Vec3((T / l) * d), w + (T > 0 ? gf * T / l : 0.0)};
    }
    case Goal::Planar: break;  // four corners: physics/planarity.hpp
    case Goal::Rigid: break;   // its members: physics/rigid_body.hpp
    case Goal::Bend: break;    // four corners: physics/shell_bending.hpp
  }
  return {};
}

}  // namespace tendril
