#include "lua_clamp.hpp"

#include <string>

#include "io/trace.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// m:clamp(p, beam [, {dx, dy, dz}]): fixes the tangent of the beam at its
// end p (default: along its end segment now).
int l_clamp(lua_State* L) {
  const char* fn = "clamp";
  Scene& s = check_scene(L, fn);
  const ParticleId p = check_particle(L, 2, s, fn);
  const BlockId b = check_block(L, 3, s, fn);
  const Vec3 t = lua_isnoneornil(L, 4) ? Vec3::Zero() : check_vec3(L, 4, fn);
  if (!lua_isnoneornil(L, 4) && t.isZero(0)) arg_error(fn, 4, "the direction must not be zero");
  using command::Value;
  apply_command(L, s, "clamp", {Value::of_id(p), Value::of_id(b), Value::of_vector(t)}, fn, 2);
  return 0;
}

// m:clamped(p, beam) -> {dx, dy, dz} (a unit vector) or nil.
int l_clamped(lua_State* L) {
  const char* fn = "clamped";
  Scene& s = check_scene(L, fn);
  const ParticleId p = check_particle(L, 2, s, fn);
  const BlockId b = check_block(L, 3, s, fn);
  Vec3 t;
  if (s.model.clamped(p, b, &t)) push_vec3(L, t);
  else lua_pushnil(L);
  return 1;
}

}  // namespace

void add_clamp_methods(lua_State* L) {
  set_fn<l_clamp>(L, "clamp");
  set_fn<l_clamped>(L, "clamped");
}

}  // namespace tendril::lua
