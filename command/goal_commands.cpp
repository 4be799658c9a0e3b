// Goals of the constraint-based solvers (thesis 3.3.5): anchors, planes,
// lines and lengths with a weight, and planar quad faces (fig. 6.6).
#include <utility>

#include "command/declare.hpp"
#include "physics/shell_bending.hpp"

namespace tendril::command {

namespace {

// goal KIND I (J LENGTH | POINT [DIRECTION]) WEIGHT
enum GoalParam { kKind, kI, kJ, kLength, kPoint, kDirection, kWeight };

bool goal_on_line(const Args& a, std::size_t next) {
  const std::string& kind = a[kKind].word;
  if (next == kJ || next == kLength) return kind == "length";
  if (next == kPoint) return kind != "length";
  if (next == kDirection) return kind == "plane" || kind == "line";
  return true;
}

// The goal added to the model, as a command's result.
Result goal_result(Target& t, const Goal& g) {
  Result r;
  r.kind = Returns::Goal;
  r.index = t.model.add_goal(g);
  return r;
}

// A goal on four particles (planarity, bend): the weight a[0], the particles a[1].
Goal four_particle_goal(Goal::Kind kind, const Args& a) {
  const std::vector<std::uint32_t>& c = a[1].ids;
  if (c.size() != 4) throw ArgumentError(1, "needs four particles, got " + std::to_string(c.size()));
  Goal g;
  g.kind = kind;
  g.i = c[0], g.j = c[1], g.k = c[2], g.l = c[3];
  g.weight = a[0].number;
  return g;
}

Result add_goal(Target& t, Args& a) {
  Goal g;
  parse_goal_kind(a[kKind].word, g.kind);
  g.i = particle(a, kI);
  if (g.kind == Goal::Length) {
    if (!a[kJ].given) throw ArgumentError(kJ, "is required for a length goal");
    if (!a[kLength].given) throw ArgumentError(kLength, "is required for a length goal");
    g.j = particle(a, kJ);
    g.length = a[kLength].number;
  } else {
    if (!a[kPoint].given) throw ArgumentError(kPoint, "is required");
    g.point = a[kPoint].vector;
    if (g.kind != Goal::Anchor) {
      if (!a[kDirection].given) throw ArgumentError(kDirection, "is required for a plane or a line");
      g.direction = a[kDirection].vector;
    }
  }
  g.weight = a[kWeight].number;
  Result r = goal_result(t, g);
  // The journal records what was given for this kind only.
  for (std::size_t k = kJ; k < kWeight; ++k) a[k].given = goal_on_line(a, k);
  return r;
}

}  // namespace

void declare_goals(std::vector<Command>& out) {
  out.push_back({"goal", "a goal of the constraint solvers: anchor, plane, line or length, with a weight",
                 Effect::Setting,
                 {{"kind", Type::Word, "what the goal holds", {}, {"anchor", "plane", "line", "length"}},
                  {"particle", Type::Particle, "the particle (length: the first)"},
                  {"other", Type::Particle, "length: the second particle", {}, {}, true},
                  {"length", Type::Number, "length: the distance [m]", {0, kInf}, {}, true},
                  {"point", Type::Vector, "anchor, plane, line: the point [m]", {}, {}, true},
                  {"direction", Type::Vector, "plane: its normal; line: its direction", {}, {}, true},
                  {"weight", Type::Number, "the stiffness of the goal [N/m]", {0, kInf, true}}},
                 Returns::Goal, add_goal, 0, Returns::Nothing, nullptr, false, goal_on_line});
  out.push_back({"planarity", "a planarity goal: a quad face's four corners onto their best-fit plane, with a weight",
                 Effect::Setting,
                 {{"weight", Type::Number, "the stiffness of the goal [N/m]", {0, kInf, true}},
                  {"corners", Type::Particles, "the quad's four corners in order round it"}},
                 Returns::Goal, [](Target& t, Args& a) { return goal_result(t, four_particle_goal(Goal::Planar, a)); }});
  out.push_back({"rigid", "a rigid-body goal: the particles move as one body, their shape now its rest shape (shape matching)",
                 Effect::Setting,
                 {{"weight", Type::Number, "the stiffness holding the shape [N/m]", {0, kInf, true}},
                  {"particles", Type::Particles, "three or more particles, not on a line"}},
                 Returns::Goal, [](Target& t, Args& a) {
                   Goal g;
                   g.kind = Goal::Rigid;
                   g.members.assign(a[1].ids.begin(), a[1].ids.end());
                   g.weight = a[0].number;
                   return goal_result(t, g);
                 }});
  out.back().lua = "";  // m:rigid(particles, weight), m:goal{kind = "rigid", ...} (grammar/lua_goals.cpp)
  out.push_back({"bend", "a bending hinge of a triangulated surface flat at rest: edge i-j between triangles (i, j, k) and "
                         "(i, j, l), its weights from their shape now (isometric bending)",
                 Effect::Setting,
                 {{"D", Type::Number, "the plate's bending stiffness E t^3 / 12 (1 - nu^2) [N m]", {0, kInf, true}},
                  {"hinge", Type::Particles, "i and j (the edge), k and l (the corners opposite it)"}},
                 Returns::Goal, [](Target& t, Args& a) {
                   Goal g = four_particle_goal(Goal::Bend, a);
                   const ParticleId c[4] = {g.i, g.j, g.k, g.l};
                   for (ParticleId p : c) t.model.require_particle(p, "bend");
                   const Vec3* x = t.model.particles.position.data();
                   BendHinge h;
                   if (!bend_hinge(x[c[0]], x[c[1]], x[c[2]], x[c[3]], h))
                     throw ModelError("bend: the triangles (" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " +
                                      std::to_string(c[2]) + ") and (" + std::to_string(c[0]) + ", " +
                                      std::to_string(c[1]) + ", " + std::to_string(c[3]) + ") must not be degenerate");
                   g.hinge = h.K;
                   g.hinge_area = h.area;
                   return goal_result(t, g);
                 }});
  out.back().lua = "";  // m:bend(hinge, D) (grammar/lua_goals.cpp)
  out.push_back({"goal_weight", "sets a goal's weight", Effect::Setting,
                 {{"goal", Type::Goal, "a goal"}, {"weight", Type::Number, "[N/m]", {0, kInf, true}}}, Returns::Nothing,
                 [](Target& t, Args& a) {
                   t.model.set_goal_weight(std::size_t(a[0].id), a[1].number);
                   return nothing();
                 },
                 1, Returns::Number,
                 [](Target& t, const Args& a) { return number_result(std::as_const(t.model.goals)[a[0].id].weight); }});
  out.push_back({"remove_goal", "removes a goal; later goals move down by one", Effect::Setting,
                 {{"goal", Type::Goal, "a goal"}}, Returns::Nothing, [](Target& t, Args& a) {
                   t.model.remove_goal(std::size_t(a[0].id));
                   return nothing();
                 }});
}

}  // namespace tendril::command
