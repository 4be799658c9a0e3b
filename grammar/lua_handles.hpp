#pragma once
// The metatables of particle and block handles, and the protection of every
// tendril metatable from the scene (issue 13: `p == m` read past the model's
// userdata; `getmetatable(m).__gc(m)` freed a running scene).
#include <lua.hpp>

namespace tendril::lua {

// Creates the metatables of particle and block handles (lua_scene.hpp:
// kParticleMeta, kBlockMeta): `h.id`, `==` and tostring, each type-checked.
void register_handle_metatables(lua_State* L);

// Sets `__metatable` on every metatable registered under a "tendril." name,
// so getmetatable returns that name and setmetatable refuses: a scene cannot
// reach a metamethod (`__gc` above all) or swap a metatable. Call it after
// the last luaL_newmetatable.
void protect_metatables(lua_State* L);

}  // namespace tendril::lua
