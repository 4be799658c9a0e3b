#include "lua_bridge.hpp"

#include <functional>
#include <stdexcept>

#include "lua_args.hpp"

namespace tendril::studio {

namespace {

constexpr int kMaxDepth = 8;

void push_json(lua_State* L, lua::Scene& s, const json& v, int depth) {
  if (depth > kMaxDepth) throw std::runtime_error("arguments nested too deeply");
  if (v.is_number_integer()) lua_pushinteger(L, v.get<lua_Integer>());
  else if (v.is_number()) lua_pushnumber(L, v.get<double>());
  else if (v.is_string()) lua_pushstring(L, v.get<std::string>().c_str());
  else if (v.is_boolean()) lua_pushboolean(L, v.get<bool>());
  else if (v.is_null()) lua_pushnil(L);
  else if (v.is_array()) {
    lua_createtable(L, int(v.size()), 0);
    for (std::size_t k = 0; k < v.size(); ++k) {
      push_json(L, s, v[k], depth + 1);
      lua_rawseti(L, -2, lua_Integer(k + 1));
    }
  } else if (v.size() == 1 && (v.contains("particle") || v.contains("block"))) {
    const bool particle = v.contains("particle");
    const json& id = particle ? v["particle"] : v["block"];
    if (!id.is_number_unsigned()) throw std::runtime_error(std::string(particle ? "particle" : "block") + " ids are integers >= 0");
    const auto n = id.get<std::uint64_t>();
    if (particle) {
      if (n >= s.model.particles.capacity() || !s.model.particle_valid(ParticleId(n)))
        throw std::runtime_error("particle " + std::to_string(n) + " does not exist");
      lua::push_particle(L, s, ParticleId(n));
    } else {
      if (n >= s.model.blocks.size() || !s.model.block_valid(BlockId(n)))
        throw std::runtime_error("block " + std::to_string(n) + " does not exist");
      lua::push_block(L, s, BlockId(n));
    }
  } else if (v.size() == 1 && v.contains("particles")) {
    json list = json::array();
    for (const json& id : v["particles"]) list.push_back(json{{"particle", id}});
    push_json(L, s, list, depth + 1);
  } else {
    lua_createtable(L, 0, int(v.size()));
    for (const auto& [key, item] : v.items()) {
      push_json(L, s, item, depth + 1);
      lua_setfield(L, -2, key.c_str());
    }
  }
}

json to_json(lua_State* L, int idx, int depth) {
  idx = lua_absindex(L, idx);
  if (auto* h = static_cast<lua::Handle*>(luaL_testudata(L, idx, lua::kParticleMeta))) return {{"particle", h->id}};
  if (auto* h = static_cast<lua::Handle*>(luaL_testudata(L, idx, lua::kBlockMeta))) return {{"block", h->id}};
  switch (lua_type(L, idx)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, idx)) return lua_tointeger(L, idx);
      return lua_tonumber(L, idx);
    case LUA_TSTRING: return lua_tostring(L, idx);
    case LUA_TBOOLEAN: return bool(lua_toboolean(L, idx));
    case LUA_TTABLE: {
      if (depth > kMaxDepth) return "...";
      const lua_Integer n = lua_Integer(lua_rawlen(L, idx));
      if (n > 0) {
        json out = json::array();
        for (lua_Integer k = 1; k <= n; ++k) {
          lua_rawgeti(L, idx, k);
          out.push_back(to_json(L, -1, depth + 1));
          lua_pop(L, 1);
        }
        return out;
      }
      json out = json::object();
      lua_pushnil(L);
      while (lua_next(L, idx)) {
        if (lua_type(L, -2) == LUA_TSTRING) out[lua_tostring(L, -2)] = to_json(L, -1, depth + 1);
        lua_pop(L, 1);
      }
      return out;
    }
    default: return nullptr;
  }
}

// Runs body inside a C function whose first argument is the model, so the
// bindings' handle helpers (which read the model at stack index 1) work.
// Lua errors raised inside body's own pcalls come back as messages; a C++
// exception becomes the result's message.
struct Body {
  std::function<CallResult(lua_State*, lua::Scene&)> fn;
  CallResult result;
};

int trampoline(lua_State* L) {
  auto* body = static_cast<Body*>(lua_touserdata(L, lua_upvalueindex(1)));
  try {
    body->result = body->fn(L, lua::check_scene(L, "studio"));
  } catch (const std::exception& e) {
    body->result = {false, e.what(), nullptr};
  }
  return 0;
}

CallResult with_model(lua_State* L, int model_ref, std::function<CallResult(lua_State*, lua::Scene&)> fn) {
  Body body{std::move(fn), {}};
  const int top = lua_gettop(L);
  lua_pushlightuserdata(L, &body);
  lua_pushcclosure(L, trampoline, 1);
  lua_rawgeti(L, LUA_REGISTRYINDEX, model_ref);
  if (lua_pcall(L, 1, 0, 0) != LUA_OK) {
    body.result = {false, lua_tostring(L, -1) ? lua_tostring(L, -1) : "error", nullptr};
  }
  lua_settop(L, top);
  return body.result;
}

// With the function to call on top of the stack: pushes the model and the
// arguments, calls it protected, and returns its results as a JSON list.
CallResult call_top(lua_State* L, lua::Scene& s, const std::vector<std::function<void()>>& pushers, const json& args) {
  const int fn = lua_gettop(L);
  lua_pushvalue(L, 1);
  for (const auto& push : pushers) push();
  if (!args.is_array()) throw std::runtime_error("'args' must be a list");
  if (args.size() > 16) throw std::runtime_error("at most 16 arguments");
  for (const json& a : args) push_json(L, s, a, 0);
  if (lua_pcall(L, lua_gettop(L) - fn, LUA_MULTRET, 0) != LUA_OK)
    return {false, lua_tostring(L, -1) ? lua_tostring(L, -1) : "error", nullptr};
  json out = json::array();
  for (int k = fn; k <= lua_gettop(L); ++k) out.push_back(to_json(L, k, 0));
  return {true, "", out};
}

void push_studio(lua_State* L) {
  lua_getglobal(L, "tendril");
  lua_getfield(L, -1, "studio");
  lua_remove(L, -2);
  if (!lua_istable(L, -1)) throw std::runtime_error("the studio's preload (studio.lua) did not run");
}

}  // namespace

lua::Scene& scene_of(lua_State* L, int model_ref) {
  lua_rawgeti(L, LUA_REGISTRYINDEX, model_ref);
  auto* s = static_cast<lua::Scene**>(luaL_testudata(L, -1, lua::kModelMeta));
  lua_pop(L, 1);
  if (!s || !*s) throw std::runtime_error("the watched model is gone");
  return **s;
}

CallResult call_method(lua_State* L, int model_ref, const std::string& method, const json& args) {
  return with_model(L, model_ref, [&](lua_State* L, lua::Scene& s) -> CallResult {
    lua_getfield(L, 1, method.c_str());
    if (!lua_isfunction(L, -1)) return {false, "the model has no method '" + method + "'", nullptr};
    return call_top(L, s, {}, args);
  });
}

CallResult apply_rule(lua_State* L, int model_ref, const std::string& key, const json& args) {
  return with_model(L, model_ref, [&](lua_State* L, lua::Scene& s) -> CallResult {
    push_studio(L);
    lua_getfield(L, -1, "rule");
    lua_pushstring(L, key.c_str());
    lua_call(L, 1, 1);  // a plain table lookup: cannot raise
    if (!lua_istable(L, -1)) return {false, "no rule '" + key + "' (see the palette)", nullptr};
    const int rule = lua_gettop(L);
    lua_getfield(L, 1, "apply");
    CallResult r = call_top(L, s, {[&] { lua_pushvalue(L, rule); }}, args);
    if (!r.ok) return r;
    if (r.value.empty() || r.value[0] != true) {  // false, reason
      const json& why = r.value.size() > 1 ? r.value[1] : json("refused");
      return {false, why.is_string() ? why.get<std::string>() : why.dump(), r.value};
    }
    r.value.erase(r.value.begin());
    return r;
  });
}

json studio_list(lua_State* L, const char* function) {
  const int top = lua_gettop(L);
  push_studio(L);
  lua_getfield(L, -1, function);
  json out = json::array();
  if (lua_pcall(L, 0, 1, 0) == LUA_OK) out = to_json(L, -1, 0);
  lua_settop(L, top);
  return out;
}

}  // namespace tendril::studio
