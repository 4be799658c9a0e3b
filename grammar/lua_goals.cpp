#include "lua_goals.hpp"

#include <string>
#include <utility>

#include "io/trace.hpp"
#include "lua_args.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// Adds the goal, journals it and returns its 1-based index.
int push_goal(lua_State* L, Scene& s, const Goal& g) {
  const std::size_t id = s.model.add_goal(g);
  const Goal& a = std::as_const(s.model.goals)[id];
  std::string line = std::string("goal ") + goal_kind_name(a.kind) + " " + std::to_string(a.i);
  if (a.kind == Goal::Length) line += " " + std::to_string(a.j) + " " + Trace::number(a.length);
  else line += " " + Trace::vec(a.point);
  if (a.kind == Goal::Plane || a.kind == Goal::Line) line += " " + Trace::vec(a.direction);
  s.record(line + " " + Trace::number(a.weight));
  lua_pushinteger(L, lua_Integer(id + 1));
  return 1;
}

std::size_t check_goal(lua_State* L, int idx, Scene& s, const char* fn) {
  const std::int64_t g = check_integer(L, idx, fn) - 1;
  if (g < 0 || std::size_t(g) >= s.model.goals.size()) arg_error(fn, idx, "no such goal");
  return std::size_t(g);
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
  return push_goal(L, s, g);
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
  if (!parse_goal_kind(kind, g.kind))
    key_error(fn, "kind", "must be \"anchor\", \"plane\", \"line\" or \"length\", got \"" + kind + "\"");
  if (!has_field(L, 2, "weight")) key_error(fn, "weight", "is required [N/m]");
  g.weight = field_number(L, 2, "weight", fn, 0);
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
  return push_goal(L, s, g);
}

// m:goal_weight(g): the weight; m:goal_weight(g, w) sets it.
int l_goal_weight(lua_State* L) {
  const char* fn = "goal_weight";
  Scene& s = check_scene(L, fn);
  const std::size_t g = check_goal(L, 2, s, fn);
  if (lua_isnoneornil(L, 3)) {
    lua_pushnumber(L, s.model.goals[g].weight);
    return 1;
  }
  const double w = check_number(L, 3, fn);
  s.model.set_goal_weight(g, w);
  s.record("goal_weight " + std::to_string(g) + " " + Trace::number(w));
  return 0;
}

// m:remove_goal(g): later goals move down by one.
int l_remove_goal(lua_State* L) {
  const char* fn = "remove_goal";
  Scene& s = check_scene(L, fn);
  const std::size_t g = check_goal(L, 2, s, fn);
  s.model.remove_goal(g);
  s.record("remove_goal " + std::to_string(g));
  return 0;
}

}  // namespace

void add_goal_methods(lua_State* L) {
  set_fn<l_anchor>(L, "anchor");
  set_fn<l_goal>(L, "goal");
  set_fn<l_goal_weight>(L, "goal_weight");
  set_fn<l_remove_goal>(L, "remove_goal");
}

}  // namespace tendril::lua
