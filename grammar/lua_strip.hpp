#pragma once
// Bending strips from Lua: m:strip (docs/lua-api.md, "Bending strips").
#include <lua.hpp>

namespace tendril::lua {

// Adds m:strip to the model methods table on top of the stack.
void add_strip_methods(lua_State* L);

}  // namespace tendril::lua
