// Goals of the constraint-based solvers: anchors, planes, lines, lengths,
// planar quad faces.
#include <algorithm>
#include <cmath>
#include <utility>

#include "model/model.hpp"

namespace tendril {

const char* goal_kind_name(Goal::Kind k) {
  switch (k) {
    case Goal::Anchor: return "anchor";
    case Goal::Plane: return "plane";
    case Goal::Line: return "line";
    case Goal::Length: return "length";
    case Goal::Planar: return "planar";
    case Goal::Rigid: return "rigid";
    case Goal::Bend: return "bend";
  }
  return "?";
}

bool parse_goal_kind(const std::string& name, Goal::Kind& out) {
  for (Goal::Kind k : {Goal::Anchor, Goal::Plane, Goal::Line, Goal::Length, Goal::Planar, Goal::Rigid, Goal::Bend})
    if (name == goal_kind_name(k)) {
      out = k;
      return true;
    }
  return false;
}

// A rigid body's members: at least three distinct live particles not on
// one line (fewer or collinear ones leave a rotation the fit cannot fix);
// the rest shape, when not given (a new body), their offsets from their
// centroid now. Sets i to the first member.
void Model::check_rigid_members(Goal& g, const std::string& fn) const {
  if (g.members.size() < 3)
    throw ModelError(fn + ": needs three or more particles, got " + std::to_string(g.members.size()));
  for (std::size_t a = 0; a < g.members.size(); ++a) {
    require_particle(g.members[a], fn.c_str());
    for (std::size_t b = 0; b < a; ++b)
      if (g.members[a] == g.members[b])
        throw ModelError(fn + ": particle " + std::to_string(g.members[a]) + " is given twice");
  }
  if (g.rest.empty()) {
    Vec3 c = Vec3::Zero();
    for (ParticleId p : g.members) c += particles.position[p];
    c /= double(g.members.size());
    for (ParticleId p : g.members) g.rest.push_back(particles.position[p] - c);
  }
  if (g.rest.size() != g.members.size())
    throw ModelError(fn + ": " + std::to_string(g.rest.size()) + " rest offsets for " + std::to_string(g.members.size()) +
                     " particles");
  double size = 0, spread = 0;
  Vec3 sum = Vec3::Zero();
  for (const Vec3& r : g.rest) {
    if (!r.allFinite()) throw ModelError(fn + ": a rest offset is not finite");
    size = std::max(size, r.norm());
    sum += r;
  }
  // Not on one line: some offset leaves the line of the largest one.
  const Vec3 axis = g.rest[0].norm() > 0 ? Vec3(g.rest[0].normalized()) : Vec3(g.rest[1].normalized());
  for (const Vec3& r : g.rest) spread = std::max(spread, (r - r.dot(axis) * axis).norm());
  if (!(size > 0) || !(spread > 1e-9 * size))
    throw ModelError(fn + ": its particles are on one line; a rigid body needs three not on a line");
  if (sum.norm() > 1e-9 * size * double(g.rest.size()))
    throw ModelError(fn + ": the rest offsets must sum to zero (offsets from their centroid)");
  g.i = g.members[0];
}

std::size_t Model::add_goal(Goal g) {
  const std::string fn = std::string("goal (") + goal_kind_name(g.kind) + ")";
  if (g.kind == Goal::Rigid) {
    check_rigid_members(g, fn);
  } else {
    g.members.clear();
    g.rest.clear();
  }
  require_particle(g.i, fn.c_str());
  if (g.kind == Goal::Rigid) {
    // i, j, k, l unused but i: the first member (activity checks read it)
  } else if (g.kind == Goal::Planar || g.kind == Goal::Bend) {
    const ParticleId c[4] = {g.i, g.j, g.k, g.l};
    for (int a = 1; a < 4; ++a) require_particle(c[a], fn.c_str());
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (c[a] == c[b]) throw ModelError(fn + ": corner " + std::to_string(a + 1) + " and corner " +
                                           std::to_string(b + 1) + " are both particle " + std::to_string(c[a]));
  } else if (g.kind == Goal::Length) {
    require_particle(g.j, fn.c_str());
    if (g.i == g.j) throw ModelError(fn + ": the two particles must differ");
    if (!(g.length >= 0) || !std::isfinite(g.length)) throw ModelError(fn + ": the length must be a finite number >= 0");
  } else {
    g.j = kNone;
    if (!g.point.allFinite()) throw ModelError(fn + ": the point is not finite");
  }
  if (g.kind == Goal::Rigid) g.j = kNone;
  if (g.kind != Goal::Planar && g.kind != Goal::Bend) g.k = g.l = kNone;
  if (g.kind == Goal::Bend) {
    for (double k : g.hinge)
      if (!std::isfinite(k)) throw ModelError(fn + ": a cotangent weight is not finite (a degenerate triangle)");
    if (!(g.hinge_area > 0) || !std::isfinite(g.hinge_area))
      throw ModelError(fn + ": the two triangles' area must be > 0 [m^2]");
  } else {
    g.hinge = {};
    g.hinge_area = 0;
  }
  if (g.kind == Goal::Plane || g.kind == Goal::Line) {
    const double n = g.direction.norm();
    if (!(n > 0) || !std::isfinite(n))
      throw ModelError(fn + ": the " + (g.kind == Goal::Plane ? "normal" : "direction") + " must be a non-zero vector");
  }
  if (!(g.weight > 0) || !std::isfinite(g.weight))
    throw ModelError(fn + (g.kind == Goal::Bend ? ": the bending stiffness D must be > 0 [N m]" : ": the weight must be > 0 [N/m]"));
  ++revision;
  goals.push_back(g);
  return goals.size() - 1;
}

void Model::remove_goal(std::size_t index) {
  if (index >= goals.size()) throw ModelError("remove_goal: no goal " + std::to_string(index));
  ++revision;
  for (std::size_t k = index; k + 1 < goals.size(); ++k) goals[k] = std::as_const(goals)[k + 1];
  goals.pop_back();
}

void Model::set_goal_weight(std::size_t index, double weight) {
  if (index >= goals.size()) throw ModelError("goal_weight: no goal " + std::to_string(index));
  if (!(weight > 0) || !std::isfinite(weight)) throw ModelError("goal_weight: the weight must be > 0 [N/m]");
  ++revision;
  goals[index].weight = weight;
}

void Model::remove_goals_of(ParticleId p) {
  for (std::size_t k = goals.size(); k-- > 0;) {
    const Goal& g = std::as_const(goals)[k];
    if (g.i == p || g.j == p || g.k == p || g.l == p ||
        std::find(g.members.begin(), g.members.end(), p) != g.members.end())
      remove_goal(k);
  }
}

}  // namespace tendril
