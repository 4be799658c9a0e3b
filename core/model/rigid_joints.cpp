// Joints between members (issue 12): where beams share a particle, each
// connection between two of them is pinned (no moment crosses it: the
// default, what 3-DOF beams sharing a particle always were) or rigid (it
// keeps its built angle and carries moment). model.hpp says what a rigid
// 3-DOF joint is; physics/element_forces.hpp's rigid_joint_forces its
// mechanics.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "model/model.hpp"

namespace tendril {

const char* joint_kind_name(JointKind k) { return k == JointKind::Rigid ? "rigid" : "pinned"; }

bool parse_joint_kind(const std::string& name, JointKind& out) {
  if (name == "rigid") out = JointKind::Rigid;
  else if (name == "pinned" || name == "pin") out = JointKind::Pinned;
  else return false;
  return true;
}

namespace {

std::string pid(ParticleId p) { return std::to_string(p); }
std::string bid(BlockId b) { return std::to_string(b); }

}  // namespace

// The segment of beam b that a joint at p acts on, as its dart at p: the end
// segment when p is an end of b (`skip`: another end dart, for a beam whose
// two ends meet at p), else the segment towards p's neighbour on b with the
// smaller id (ids keep their order through the model database, so a loaded
// model picks the same segment).
Dart Model::joint_dart(ParticleId p, BlockId b, Dart skip, const char* fn) const {
  require_particle(p, fn);
  require_block(b, fn);
  if (blocks[b].kind != BlockKind::Beam)
    throw ModelError(std::string(fn) + ": block " + bid(b) + " is a " + block_kind_name(blocks[b].kind) +
                     "; joints connect beams");
  Dart end = kNoDart, inner = kNoDart;
  for (Dart head = particles.first_dart[p], d = head; d != kNone;) {
    if (dart_block[d] == b && d != skip && !map.is_free(0, d)) {
      if (map.is_free(1, d)) {
        if (end == kNoDart) end = d;
      } else if (inner == kNoDart || dart_particle[map.alpha(0, d)] < dart_particle[map.alpha(0, inner)]) {
        inner = d;
      }
    }
    d = ring_next[d];
    if (d == head) break;
  }
  if (end != kNoDart) return end;
  if (inner != kNoDart && skip == kNoDart) return inner;
  if (skip != kNoDart)
    throw ModelError(std::string(fn) + ": beam " + bid(b) + " does not have both its ends at particle " + pid(p) +
                     "; give two beams");
  throw ModelError(std::string(fn) + ": particle " + pid(p) + " is not on beam " + bid(b));
}

// The included angle at p between the segments of darts a and b [rad, 0..pi].
double Model::joint_angle_now(Dart a, Dart b) const {
  const Vec3 xp = pos(a);
  const Vec3 u = pos(map.alpha(0, a)) - xp, v = pos(map.alpha(0, b)) - xp;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

bool Model::rigid_acts(const RigidJoint& j) const {
  if (!rigid_joined(j) || map.is_free(0, j.a) || map.is_free(0, j.b)) return false;
  const Block &A = blocks[dart_block[j.a]], &B = blocks[dart_block[j.b]];
  return A.alive && B.alive && A.kind == BlockKind::Beam && B.kind == BlockKind::Beam && A.dofs == 3 &&
         B.dofs == 3;
}

double Model::rigid_stiffness(const RigidJoint& j) const {
  // The joint owns half of each end segment, like a hinge its vertex: the
  // two halves in series.
  const double ca = 0.5 * rest_length[j.a] / blocks[dart_block[j.a]].section.EI;
  const double cb = 0.5 * rest_length[j.b] / blocks[dart_block[j.b]].section.EI;
  return ca + cb > 0 ? 1 / (ca + cb) : 0.0;
}

std::size_t Model::find_rigid(Dart a, Dart b) const {
  for (std::size_t k = 0; k < rigid_joints.size(); ++k) {
    const RigidJoint& j = rigid_joints[k];
    if (!rigid_joined(j)) continue;
    if ((j.a == a && j.b == b) || (j.a == b && j.b == a)) return k;
  }
  return rigid_joints.size();
}

bool Model::rigid_joined(const RigidJoint& j) const {
  return map.alive(j.a) && map.alive(j.b) && rigid_mark[j.a] == j.mark_a && rigid_mark[j.b] == j.mark_b &&
         dart_particle[j.a] == dart_particle[j.b];
}

void Model::set_rigid_joint(ParticleId p, BlockId a, ParticleId a_to, BlockId b, ParticleId b_to, double angle) {
  const char* fn = "rigid joint";
  require_particle(p, fn);
  auto dart_to = [&](BlockId blk, ParticleId to, Dart skip) {
    require_block(blk, fn);
    for (Dart head = particles.first_dart[p], d = head; d != kNone;) {
      if (dart_block[d] == blk && d != skip && !map.is_free(0, d) && dart_particle[map.alpha(0, d)] == to) return d;
      d = ring_next[d];
      if (d == head) break;
    }
    throw ModelError(std::string(fn) + ": beam " + bid(blk) + " has no segment from particle " + pid(p) + " to " +
                     pid(to));
  };
  const Dart da = dart_to(a, a_to, kNoDart);
  const Dart db = dart_to(b, b_to, da);
  if (blocks[a].kind != BlockKind::Beam || blocks[b].kind != BlockKind::Beam)
    throw ModelError(std::string(fn) + ": joints connect beams");
  if (!(angle >= 0 && angle <= std::numbers::pi)) throw ModelError(std::string(fn) + ": the angle must be within 0 .. pi");
  make_rigid(da, db, angle);
}

void Model::make_rigid(Dart da, Dart db, double angle) {
  RigidJoint j;
  j.a = da;
  j.b = db;
  j.angle = angle;
  ++revision;
  const std::size_t found = find_rigid(da, db);
  if (found != rigid_joints.size()) {
    j.mark_a = rigid_joints[found].mark_a;
    j.mark_b = rigid_joints[found].mark_b;
    rigid_joints[found] = j;
    return;
  }
  auto mark = [&](Dart d) {
    if (rigid_mark[d] == 0) rigid_mark[d] = ++rigid_stamp_;
    return rigid_mark[d];
  };
  j.mark_a = mark(da);
  j.mark_b = mark(db);
  rigid_joints.push_back(j);
}

void Model::set_joint(ParticleId p, BlockId a, BlockId b, JointKind kind, double angle) {
  const char* fn = "connection";
  const Dart da = joint_dart(p, a, kNoDart, fn);
  const Dart db = joint_dart(p, b, a == b ? da : kNoDart, fn);
  const int fa = blocks[a].dofs, fb = blocks[b].dofs;
  if (fa != fb && kind == JointKind::Rigid)
    throw ModelError(std::string(fn) + ": beam " + bid(a) + " has " + std::to_string(fa) + " DOF and beam " + bid(b) +
                     " " + std::to_string(fb) +
                     "; a rigid joint connects two 3-DOF beams (6-DOF beams sharing a particle are rigid through "
                     "its frame): switch them to the same formulation");
  if (fa == 6 && fb == 6 && kind == JointKind::Pinned)
    throw ModelError(std::string(fn) + ": beams " + bid(a) + " and " + bid(b) +
                     " have 6 DOF: sharing particle " + pid(p) +
                     ", they share its frame and are rigid there; switch them to 3 DOF to pin them");
  if (!std::isfinite(angle) || angle > std::numbers::pi)
    throw ModelError(std::string(fn) + ": the angle must be within 0 .. pi (negative: as built)");
  const std::size_t found = find_rigid(da, db);
  if (kind == JointKind::Pinned) {
    if (found == rigid_joints.size()) return;
    ++revision;
    if (found + 1 != rigid_joints.size()) rigid_joints[found] = rigid_joints.back();
    rigid_joints.pop_back();
    return;
  }
  make_rigid(da, db, angle >= 0 ? angle : joint_angle_now(da, db));
}

JointKind Model::joint_kind(ParticleId p, BlockId a, BlockId b, double* angle) const {
  const Dart da = joint_dart(p, a, kNoDart, "connection");
  const Dart db = joint_dart(p, b, a == b ? da : kNoDart, "connection");
  if (blocks[a].dofs == 6 && blocks[b].dofs == 6) {
    if (angle) *angle = joint_angle_now(da, db);
    return JointKind::Rigid;
  }
  if (blocks[a].dofs != blocks[b].dofs) return JointKind::Pinned;
  const std::size_t k = find_rigid(da, db);
  if (k == rigid_joints.size()) return JointKind::Pinned;
  if (angle) *angle = rigid_joints[k].angle;
  return JointKind::Rigid;
}

}  // namespace tendril
