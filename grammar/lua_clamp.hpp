#pragma once
// Clamps of 3-DOF beam ends from Lua: m:clamp, m:unclamp, m:clamped
// (docs/lua-api.md, "Clamps").
#include <lua.hpp>

namespace tendril::lua {

// Adds the clamp methods to the model methods table on top of the stack.
void add_clamp_methods(lua_State* L);

}  // namespace tendril::lua
