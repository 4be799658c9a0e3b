#include "lua_commands.hpp"

#include <string>

#include "command/listing.hpp"
#include "command/registry.hpp"
#include "lua_args.hpp"
#include "lua_rules.hpp"

namespace tendril::lua {

namespace {

using command::Command;
using command::Type;
using command::Value;

// An index of the scene's goals or joints, counted from 1 in Lua.
std::uint64_t check_index(lua_State* L, int idx, std::size_t count, const char* fn, const char* what) {
  const std::int64_t number = check_integer(L, idx, fn);
  if (number < 1 || std::uint64_t(number) > count) arg_error(fn, idx, std::string("no such ") + what);
  return std::uint64_t(number - 1);
}

Value read(lua_State* L, int idx, const command::Param& p, Scene& s, const char* fn) {
  if (p.optional && lua_isnoneornil(L, idx)) return Value::absent();
  switch (p.type) {
    case Type::Particle: return Value::of_id(check_particle(L, idx, s, fn));
    case Type::Block: return Value::of_id(check_block(L, idx, s, fn));
    case Type::Goal: return Value::of_id(check_index(L, idx, s.model.goals.size(), fn, "goal"));
    case Type::Joint: return Value::of_id(check_index(L, idx, s.model.joints.size(), fn, "joint"));
    case Type::Count: {
      const std::int64_t n = check_integer(L, idx, fn);
      if (n < 0) arg_error(fn, idx, "must be >= 0");
      return Value::of_id(std::uint64_t(n));
    }
    case Type::Flag:
      if (!lua_isboolean(L, idx)) arg_error(fn, idx, "expected true or false");
      return Value::of_id(lua_toboolean(L, idx) ? 1 : 0);
    case Type::Number: return Value::of_number(check_number(L, idx, fn));
    case Type::Vector: return Value::of_vector(check_vec3(L, idx, fn));
    case Type::Word: case Type::Path:
      if (lua_type(L, idx) != LUA_TSTRING) arg_error(fn, idx, std::string("expected a string, got ") + luaL_typename(L, idx));
      return Value::of_word(lua_tostring(L, idx));
    case Type::Particles: {
      std::vector<ParticleId> ps = check_particle_list(L, idx, s, fn);
      return Value::of_ids({ps.begin(), ps.end()});
    }
  }
  return {};
}

// m:NAME(...) for a command whose Lua arguments are its parameters in order.
int l_command(lua_State* L) {
  const Command& c = *static_cast<const Command*>(lua_touserdata(L, lua_upvalueindex(1)));
  const std::string method = c.lua ? c.lua : c.name;
  const char* fn = method.c_str();
  Scene& s = check_scene(L, fn);
  const int given = lua_gettop(L) - 1;
  command::Args args;
  if (c.query && given <= int(c.query_params)) {  // the getter: m:mass(p)
    for (std::size_t k = 0; k < c.query_params; ++k) args.push_back(read(L, int(k) + 2, c.params[k], s, fn));
    command::Target target{s.model, s.solver};
    return push_result(L, s, c.query(target, args));
  }
  for (std::size_t k = 0; k < c.params.size(); ++k) args.push_back(read(L, int(k) + 2, c.params[k], s, fn));
  const command::Result r = apply_command(L, s, c, std::move(args), fn, 2, true);
  return push_result(L, s, r);
}

}  // namespace

command::Result apply_command(lua_State* L, Scene& s, const Command& c, command::Args args, const char* fn,
                              int first_arg, bool positional) {
  const std::string description =
      c.effect == command::Effect::Topology && first_arg > 0 ? describe_args(L, first_arg, lua_gettop(L)) : "";
  try {
    return command::apply(s.session, c, std::move(args), description);
  } catch (const command::CommandError& e) {
    if (e.param >= c.params.size()) throw LuaArgError(std::string(fn) + ": " + e.why);
    if (positional) arg_error(fn, first_arg + int(e.param), e.why);
    key_error(fn, c.params[e.param].name, e.why);
  }
}

command::Result apply_command(lua_State* L, Scene& s, const char* name, command::Args args, const char* fn,
                              int first_arg) {
  return apply_command(L, s, command::get(name), std::move(args), fn, first_arg);
}

void all_or_nothing(Scene& s, const std::function<void()>& f) {
  Model& m = s.model;
  if (m.in_transaction()) return f();
  const Trace::Mark mark = s.trace.mark();
  m.begin_transaction();
  try {
    f();
  } catch (...) {
    m.rollback_transaction();
    s.trace.rewind(mark);
    throw;
  }
  m.commit_transaction();
}

void record_command(Scene& s, const char* name, const command::Args& args) { command::record(s.session, name, args); }

void record_patch_command(Scene& s, const Section& sec, const std::vector<Model::Quad>& quads) {
  command::Args args;
  for (double x : {sec.EA, sec.EI, sec.prestress, sec.line_mass}) args.push_back(Value::of_number(x));
  std::vector<std::uint32_t> corners;
  for (const Model::Quad& q : quads) corners.insert(corners.end(), q.begin(), q.end());
  args.push_back(Value::of_ids(std::move(corners)));
  record_command(s, "patch", args);
}

int push_result(lua_State* L, Scene& s, const command::Result& r) {
  using command::Returns;
  switch (r.kind) {
    case Returns::Nothing: return 0;
    case Returns::Particle: push_particle(L, s, r.ids[0]); return 1;
    case Returns::Block: push_block(L, s, r.ids[0]); return 1;
    case Returns::Particles:
      lua_createtable(L, int(r.ids.size()), 0);
      for (std::size_t k = 0; k < r.ids.size(); ++k) {
        push_particle(L, s, r.ids[k]);
        lua_rawseti(L, -2, lua_Integer(k + 1));
      }
      return 1;
    case Returns::ParticleAndBlock:
      push_particle(L, s, r.ids[0]);
      push_block(L, s, r.ids[1]);
      return 2;
    case Returns::Goal: case Returns::Joint: lua_pushinteger(L, lua_Integer(r.index + 1)); return 1;
    case Returns::Number: lua_pushnumber(L, r.number); return 1;
    case Returns::Vector: push_vec3(L, r.vector); return 1;
    case Returns::Flag: lua_pushboolean(L, r.flag); return 1;
    case Returns::Word: lua_pushstring(L, r.word.c_str()); return 1;
  }
  return 0;
}

void add_command_methods(lua_State* L) {
  for (const Command& c : command::commands()) {
    if (command::lua_method(c).empty()) continue;
    lua_pushlightuserdata(L, const_cast<Command*>(&c));
    lua_pushcclosure(L, guarded<l_command>, 1);
    lua_setfield(L, -2, c.lua ? c.lua : c.name);
  }
}

}  // namespace tendril::lua
