#include "lua_args.hpp"

#include <cmath>
#include <set>
#include <string_view>

namespace tendril::lua {

namespace {

// Under lua_pcall, so that running out of Lua memory while the message is
// made cannot longjmp out of the catch block that holds the exception.
// Level 2 is the code that called the binding (level 1 is the binding).
int where_and_message(lua_State* L) {
  const char* message = static_cast<const char*>(lua_touserdata(L, 1));
  luaL_where(L, 2);
  lua_pushstring(L, message);
  lua_concat(L, 2);
  return 1;
}

// Leaves only the message on the stack, copied into Lua, or Lua's own error
// when even that failed (out of memory).
void push_message(lua_State* L, const char* message) noexcept {
  lua_settop(L, 0);  // a binding has LUA_MINSTACK free slots once its own are dropped
  lua_pushcfunction(L, where_and_message);
  lua_pushlightuserdata(L, const_cast<char*>(message));
  lua_pcall(L, 1, 1, 0);
}

}  // namespace

int call_binding(lua_State* L, lua_CFunction f) noexcept {
  try {
    return f(L);
  } catch (const std::exception& e) {
    push_message(L, e.what());
  } catch (...) {
    push_message(L, "unknown C++ exception");
  }
  return -1;
}

void arg_error(const char* fn, int arg, const std::string& msg) {
  throw LuaArgError(std::string(fn) + ": argument " + std::to_string(arg) + ": " + msg);
}

void key_error(const char* fn, const char* key, const std::string& msg) {
  throw LuaArgError(std::string(fn) + ": '" + key + "' " + msg);
}

double check_number(lua_State* L, int idx, const char* fn) {
  int ok = 0;
  double v = lua_tonumberx(L, idx, &ok);
  if (!ok) arg_error(fn, idx, std::string("expected a number, got ") + luaL_typename(L, idx));
  if (!std::isfinite(v)) arg_error(fn, idx, "expected a finite number");
  return v;
}

std::int64_t check_integer(lua_State* L, int idx, const char* fn) {
  int ok = 0;
  lua_Integer v = lua_tointegerx(L, idx, &ok);
  if (!ok) arg_error(fn, idx, std::string("expected an integer, got ") + luaL_typename(L, idx));
  return v;
}

void check_table(lua_State* L, int idx, const char* fn) {
  if (!lua_istable(L, idx)) arg_error(fn, idx, std::string("expected a table, got ") + luaL_typename(L, idx));
}

namespace {
bool read_vec3(lua_State* L, int idx, Vec3& out) {
  if (!lua_istable(L, idx) || lua_rawlen(L, idx) != 3) return false;
  for (int k = 0; k < 3; ++k) {
    lua_rawgeti(L, idx, k + 1);
    int ok = 0;
    out[k] = lua_tonumberx(L, -1, &ok);
    lua_pop(L, 1);
    if (!ok || !std::isfinite(out[k])) return false;
  }
  return true;
}
}  // namespace

Vec3 check_vec3(lua_State* L, int idx, const char* fn) {
  Vec3 v;
  if (!read_vec3(L, lua_absindex(L, idx), v)) arg_error(fn, idx, "expected a table of 3 finite numbers {x, y, z}");
  return v;
}

void check_keys(lua_State* L, int idx, const char* fn, std::initializer_list<const char*> allowed) {
  idx = lua_absindex(L, idx);
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    lua_pop(L, 1);  // keep the key
    if (lua_type(L, -1) != LUA_TSTRING) {
      lua_pop(L, 1);
      throw LuaArgError(std::string(fn) + ": option keys must be names");
    }
    std::string_view key = lua_tostring(L, -1);
    bool known = false;
    for (const char* a : allowed) known |= key == a;
    if (!known) {
      std::string k(key), list;
      for (const char* a : allowed) list += std::string(list.empty() ? "" : ", ") + a;
      lua_pop(L, 1);
      throw LuaArgError(std::string(fn) + ": unknown key '" + k + "' (known: " + list + ")");
    }
  }
}

bool has_field(lua_State* L, int idx, const char* key) {
  lua_getfield(L, idx, key);
  bool has = !lua_isnil(L, -1);
  lua_pop(L, 1);
  return has;
}

double field_number(lua_State* L, int idx, const char* key, const char* fn, double fallback) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return fallback;
  }
  int ok = 0;
  double v = lua_tonumberx(L, -1, &ok);
  std::string type = luaL_typename(L, -1);
  lua_pop(L, 1);
  if (!ok) key_error(fn, key, "must be a number, got " + type);
  if (!std::isfinite(v)) key_error(fn, key, "must be finite");
  return v;
}

bool field_bool(lua_State* L, int idx, const char* key, const char* fn, bool fallback) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return fallback;
  }
  bool is_bool = lua_isboolean(L, -1);
  bool v = lua_toboolean(L, -1);
  lua_pop(L, 1);
  if (!is_bool) key_error(fn, key, "must be true or false");
  return v;
}

std::string field_string(lua_State* L, int idx, const char* key, const char* fn, const std::string& fallback) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    return fallback;
  }
  if (lua_type(L, -1) != LUA_TSTRING) {
    lua_pop(L, 1);
    key_error(fn, key, "must be a string");
  }
  std::string v = lua_tostring(L, -1);
  lua_pop(L, 1);
  return v;
}

Vec3 field_vec3(lua_State* L, int idx, const char* key, const char* fn) {
  lua_getfield(L, idx, key);
  Vec3 v;
  bool ok = read_vec3(L, lua_gettop(L), v);
  lua_pop(L, 1);
  if (!ok) key_error(fn, key, "must be a table of 3 finite numbers {x, y, z}");
  return v;
}

void push_vec3(lua_State* L, const Vec3& v) {
  lua_createtable(L, 3, 0);
  for (int k = 0; k < 3; ++k) {
    lua_pushnumber(L, v[k]);
    lua_rawseti(L, -2, k + 1);
  }
}

}  // namespace tendril::lua
