#pragma once
// Warp and weft prestress on a patch of bars from Lua: m:patch_prestress
// (docs/lua-api.md, "Tensile patches").
#include <lua.hpp>

namespace tendril::lua {

// Adds m:patch_prestress to the model methods table on top of the stack.
void add_patch_prestress_methods(lua_State* L);

}  // namespace tendril::lua
