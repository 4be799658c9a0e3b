// Particle and block handle metatables. The metamethods check the type of
// every operand with luaL_testudata: Lua calls `__eq` with any two userdata
// (a particle and a model), and a metamethod taken out of its metatable can
// be called with anything. They hold no C++ object with a destructor, so a
// Lua error raised here longjmps over nothing that needs unwinding.
#include "lua_handles.hpp"

#include <cstring>

#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// The handle at idx and its kind (kParticleMeta or kBlockMeta), or null.
const Handle* to_handle(lua_State* L, int idx, const char** kind) {
  for (const char* meta : {kParticleMeta, kBlockMeta}) {
    if (auto* h = static_cast<const Handle*>(luaL_testudata(L, idx, meta))) {
      if (kind) *kind = meta;
      return h;
    }
  }
  return nullptr;
}

const Handle* check_handle(lua_State* L, int idx, const char** kind, const char* what) {
  const Handle* h = to_handle(L, idx, kind);
  if (!h) {
    // A tendril userdata by its metatable's name ("tendril.Model"), the rest by type.
    const char* type = luaL_getmetafield(L, idx, "__name") == LUA_TSTRING ? lua_tostring(L, -1)
                                                                           : luaL_typename(L, idx);
    luaL_error(L, "%s: expected a particle or a block, got %s", what, type);
  }
  return h;
}

int l_handle_index(lua_State* L) {
  const Handle* h = check_handle(L, 1, nullptr, "handle index");
  const char* key = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : nullptr;
  if (key && std::strcmp(key, "id") == 0) {
    lua_pushinteger(L, h->id);
    return 1;
  }
  lua_pushnil(L);
  return 1;
}

// Equal: the same kind of handle to the same slot and generation of the same
// model. Anything else (a model, a multires box, a block with the particle's
// id) is unequal, never read as a handle.
int l_handle_eq(lua_State* L) {
  const char* kind_a = nullptr;
  const char* kind_b = nullptr;
  const Handle* a = to_handle(L, 1, &kind_a);
  const Handle* b = to_handle(L, 2, &kind_b);
  lua_pushboolean(L, a && b && kind_a == kind_b && a->scene == b->scene && a->id == b->id &&
                         a->generation == b->generation);
  return 1;
}

int l_handle_tostring(lua_State* L) {
  const char* kind = nullptr;
  const Handle* h = check_handle(L, 1, &kind, "tostring");
  lua_pushfstring(L, "%s %I", kind == kParticleMeta ? "particle" : "block", lua_Integer(h->id));
  return 1;
}

}  // namespace

void register_handle_metatables(lua_State* L) {
  for (const char* meta : {kParticleMeta, kBlockMeta}) {
    luaL_newmetatable(L, meta);
    lua_pushcfunction(L, l_handle_index);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, l_handle_eq);
    lua_setfield(L, -2, "__eq");
    lua_pushcfunction(L, l_handle_tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pop(L, 1);
  }
}

void protect_metatables(lua_State* L) {
  static constexpr char kPrefix[] = "tendril.";
  lua_pushnil(L);
  while (lua_next(L, LUA_REGISTRYINDEX)) {
    // key at -2, value at -1; lua_type first: lua_tostring would turn a
    // numeric key into a string and confuse lua_next.
    if (lua_type(L, -2) == LUA_TSTRING && lua_istable(L, -1) &&
        std::strncmp(lua_tostring(L, -2), kPrefix, sizeof kPrefix - 1) == 0) {
      lua_pushvalue(L, -2);
      lua_setfield(L, -2, "__metatable");
    }
    lua_pop(L, 1);
  }
}

}  // namespace tendril::lua
