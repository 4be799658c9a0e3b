// Projections of every element (projections.hpp), accumulated per particle.
#include "physics/projections.hpp"

#include "physics/element_forces.hpp"
#include "physics/planarity.hpp"
#include "physics/rigid_body.hpp"
#include "physics/shell_bending.hpp"

namespace tendril {

namespace {

inline void add(const ProjectionSums& s, ParticleId p, double K, const Vec3& pull) {
  s.weight[p] += K;
  s.pull[p] += pull;
}

// Bar or cable: both ends move along the bar, halfway each, to the length
// at which its tension T (eq. 3.32) vanishes; K (p - x) = T along the bar.
void project_bar(const Bar& b, const Vec3* x, double gf, const ProjectionSums& s) {
  const Vec3 d = x[b.j] - x[b.i];
  const double l = d.norm();
  const double k = b.EA / b.rest_length;
  double T = b.prestress + k * (l - b.rest_length);
  if (b.tension_only && T < 0) T = 0;  // slack: l <= L holds, p = x
  const double K = 2 * (k + (l > 0 && T > 0 ? gf * T / l : 0.0));
  const Vec3 f = l > 0 ? Vec3((T / l) * d) : Vec3::Zero();
  add(s, b.i, K, f);
  add(s, b.j, K, -f);
}

}  // namespace

void accumulate_projections(const Model& m, const Vec3* x, const Quat* q, double gf, const ProjectionSums& s) {
  const Particles& P = m.particles;
  for (ParticleId p : P.integrated.raw()) {  // passive particles: never read (ElementBuffer)
    s.pull[p].setZero();
    s.weight[p] = 0;
  }
  for (ParticleId p : P.rotational.raw()) {
    s.turn[p].setZero();
    s.rot_weight[p] = 0;
  }
  const std::uint8_t* active = P.active.data();
  for (const Bar* b = m.bars.awake_begin(); b != m.bars.awake_end(); ++b) project_bar(*b, x, gf, s);
  for (const Hinge* hp = m.hinges.awake_begin(); hp != m.hinges.awake_end(); ++hp) {
    const Hinge& h = *hp;
    const HingeForces f = hinge_forces(h, x);
    add(s, h.i, f.ka, f.fi);
    add(s, h.k, f.kb, f.fk);
    add(s, h.j, f.ka + f.kb, -(f.fi + f.fk));
  }
  for (Dart d : m.clamp_darts.raw()) {  // clamped 3-DOF beam ends
    if (!m.clamp_acts(d)) continue;
    const ParticleId p = m.dart_particle[d], q = m.dart_particle[m.map.alpha(0, d)];
    if (!(active[p] & active[q])) continue;
    const ClampForces f = clamp_forces(m.clamp[d], m.blocks[m.dart_block[d]].section.EI, x[p], x[q]);
    add(s, q, f.k, f.fq);
    add(s, p, f.k, -f.fq);
  }
  for (const RigidJoint& j : m.rigid_joints.raw()) {  // rigid joints of 3-DOF beams
    if (!m.rigid_acts(j)) continue;
    const ParticleId p = m.dart_particle[j.a];
    const ParticleId a = m.dart_particle[m.map.alpha(0, j.a)], b = m.dart_particle[m.map.alpha(0, j.b)];
    if (!(active[p] & active[a] & active[b])) continue;
    const RigidJointForces f = rigid_joint_forces(m.rigid_stiffness(j), j.angle, x[p], x[a], x[b]);
    add(s, a, f.ka, f.fa);
    add(s, b, f.kb, f.fb);
    add(s, p, f.ka + f.kb, -(f.fa + f.fb));
  }
  for (const Beam6* bp = m.beam6s.awake_begin(); bp != m.beam6s.awake_end(); ++bp) {
    const Beam6& b = *bp;
    const Beam6Ends e = beam6_ends(b, x, q, gf);
    add(s, b.i, 2 * e.k, -e.fj);
    add(s, b.j, 2 * e.k, e.fj);
    s.rot_weight[b.i] += 2 * e.kr;
    s.rot_weight[b.j] += 2 * e.kr;
    s.turn[b.i] += e.ta;
    s.turn[b.j] += e.tb;
  }
  std::vector<Vec3> pulls;  // a rigid body's, reused
  for (const Goal& g : m.goals) {  // the exact projections, weight w (twice it for a length)
    if (!active[g.i] || (g.j != kNone && !active[g.j])) continue;
    if (g.kind == Goal::Rigid) {  // each member onto the fitted rest shape, weight w
      if (!members_active(g, active)) continue;
      rigid_pulls(g, x, pulls);
      for (std::size_t a = 0; a < g.members.size(); ++a) add(s, g.members[a], g.weight, pulls[a]);
      continue;
    }
    if (g.kind == Goal::Bend) {  // each corner by its force over its row sum
      if (!(active[g.k] & active[g.l])) continue;
      const BendPulls f = bend_pulls(g, x);
      for (int a = 0; a < 4; ++a) add(s, f.p[a], f.k[a], f.f[a]);
      continue;
    }
    if (g.kind == Goal::Planar) {  // each corner onto the best-fit plane, weight w
      if (!(active[g.k] & active[g.l])) continue;
      const PlanarityPulls f = planarity_pulls(g, x);
      for (int a = 0; a < 4; ++a) add(s, f.p[a], g.weight, f.f[a]);
      continue;
    }
    const GoalForce f = goal_force(g, x, gf);
    if (g.kind != Goal::Length) {
      add(s, g.i, f.k, f.fi);
    } else {
      add(s, g.i, 2 * f.k, f.fi);
      add(s, g.j, 2 * f.k, -f.fi);
    }
  }
  for (const RotationalJoint& jt : m.joints.items) {
    ParticleId nb[4];
    Vec3 target[4];
    if (!m.joint_neighbours(jt.particle, nb)) continue;
    // A joint touching a passive particle is dormant, like an element.
    if (!(active[jt.particle] & active[nb[0]] & active[nb[1]] & active[nb[2]] & active[nb[3]])) continue;
    if (!joint_targets(jt, nb, x, target)) continue;
    Vec3 sum = Vec3::Zero();
    for (int k = 0; k < 4; ++k) {
      const Vec3 f = jt.stiffness * (target[k] - x[nb[k]]);
      add(s, nb[k], 2 * jt.stiffness, f);
      sum += f;
    }
    add(s, jt.particle, 8 * jt.stiffness, -sum);
  }
}

}  // namespace tendril
