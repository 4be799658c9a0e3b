#include "lua_goals.hpp"

#include <string>
#include <utility>

#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// Adds the goal through its command and returns its 1-based index.
int push_goal(lua_State* L, Scene& s, const Goal& g, const char* fn) {
  using command::Value;
  command::Args args = {Value::of_word(goal_kind_name(g.kind)), Value::of_id(g.i), Value::of_id(g.j),
                        Value::of_number(g.length), Value::of_vector(g.point), Value::of_vector(g.direction),
                        Value::of_number(g.weight)};
  if (g.kind != Goal::Length) args[2] = args[3] = Value::absent();
  else args[4] = Value::absent();
  if (g.kind != Goal::Plane && g.kind != Goal::Line) args[5] = Value::absent();
  return push_result(L, s, apply_command(L, s, "goal", std::move(args), fn));
}

// m:anchor(p, {x, y, z}, weight): pulls p to the point.
int l_anchor(lua_State* L) {
  const char* fn = "anchor";
  Scene& s = check_scene(L, fn);
  Goal g;
  g.kind = Goal::Anchor;
  g.i = check_particle(L, 2, s, fn);
  g.point = check_vec3(L, 3, fn);
  g.weight = check_number(L, 4, fn);
  return push_goal(L, s, g, fn);
}

// m:goal{kind =, particle = | particles = {p, q}, point =, normal = |
// direction =, length =, weight =}.
int l_goal(lua_State* L) {
  const char* fn = "goal";
  Scene& s = check_scene(L, fn);
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"kind", "particle", "particles", "point", "normal", "direction", "length", "weight"});
  Goal g;
  const std::string kind = field_string(L, 2, "kind", fn, "");
  if (!parse_goal_kind(kind, g.kind) || g.kind == Goal::Bend)
    key_error(fn, "kind", "must be \"anchor\", \"plane\", \"line\", \"length\", \"planar\" or \"rigid\", got \"" + kind + "\"" +
                              (kind == "bend" ? " (a bending hinge: m:bend)" : ""));
  if (!has_field(L, 2, "weight")) key_error(fn, "weight", "is required [N/m]");
  g.weight = field_number(L, 2, "weight", fn, 0);
  if (g.kind == Goal::Rigid) {  // the rigid command
    lua_getfield(L, 2, "particles");
    const std::vector<ParticleId> ps = check_particle_list(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    using command::Value;
    return push_result(L, s, apply_command(L, s, "rigid", {Value::of_number(g.weight), Value::of_ids({ps.begin(), ps.end()})}, fn));
  }
  if (g.kind == Goal::Planar) {  // the planarity command
    lua_getfield(L, 2, "particles");
    const std::vector<ParticleId> ps = check_particle_list(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    if (ps.size() != 4) key_error(fn, "particles", "must hold the quad's four corners");
    using command::Value;
    return push_result(L, s, apply_command(L, s, "planarity",
                                           {Value::of_number(g.weight), Value::of_ids({ps.begin(), ps.end()})}, fn));
  }
  if (g.kind == Goal::Length) {
    lua_getfield(L, 2, "particles");
    const std::vector<ParticleId> ps = check_particle_list(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    if (ps.size() != 2) key_error(fn, "particles", "must hold two particles");
    g.i = ps[0];
    g.j = ps[1];
    if (!has_field(L, 2, "length")) key_error(fn, "length", "is required [m]");
    g.length = field_number(L, 2, "length", fn, 0);
  } else {
    lua_getfield(L, 2, "particle");
    g.i = check_particle(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    if (!has_field(L, 2, "point")) key_error(fn, "point", "is required");
    g.point = field_vec3(L, 2, "point", fn);
    const char* axis = g.kind == Goal::Plane ? "normal" : "direction";
    if (g.kind != Goal::Anchor) {
      if (!has_field(L, 2, axis)) key_error(fn, axis, "is required");
      g.direction = field_vec3(L, 2, axis, fn);
    }
  }
  return push_goal(L, s, g, fn);
}

// m:NAME(particles, number): the command NAME of a number and particles
// (planarity and bend: `count` of them, described by `which`; rigid: any).
int particles_and_number(lua_State* L, const char* fn, std::size_t count, const char* which) {
  Scene& s = check_scene(L, fn);
  const std::vector<ParticleId> ps = check_particle_list(L, 2, s, fn);
  if (count > 0 && ps.size() != count)
    arg_error(fn, 2, std::string("expected ") + which + ", got " + std::to_string(ps.size()));
  using command::Value;
  return push_result(L, s, apply_command(L, s, fn,
                                         {Value::of_number(check_number(L, 3, fn)), Value::of_ids({ps.begin(), ps.end()})},
                                         fn));
}

// m:planarity({a, b, c, d}, weight): the quad face onto its best-fit plane.
int l_planarity(lua_State* L) { return particles_and_number(L, "planarity", 4, "the quad's four corners"); }

// m:rigid({p, q, r, ...}, weight): the particles as one rigid body.
int l_rigid(lua_State* L) { return particles_and_number(L, "rigid", 0, nullptr); }

// m:bend({i, j, k, l}, D): a bending hinge on edge i-j between the
// triangles (i, j, k) and (i, j, l), flat at rest.
int l_bend(lua_State* L) {
  return particles_and_number(L, "bend", 4, "the edge's two particles and the two opposite it");
}

}  // namespace

void add_goal_methods(lua_State* L) {
  set_fn<l_anchor>(L, "anchor");
  set_fn<l_bend>(L, "bend");
  set_fn<l_rigid>(L, "rigid");
  set_fn<l_planarity>(L, "planarity");
  set_fn<l_goal>(L, "goal");
}

}  // namespace tendril::lua
