#pragma once
// Clamps of 3-DOF beam ends from Lua: m:clamp (an optional direction) and
// m:clamped; m:unclamp is the command's own binding
// (docs/lua-api.md, "Clamps").
#include <lua.hpp>

namespace tendril::lua {

// Adds the clamp methods to the model methods table on top of the stack.
void add_clamp_methods(lua_State* L);

}  // namespace tendril::lua
