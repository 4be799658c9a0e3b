#pragma once
// Spatial queries and growth operations the agents build on.
#include <lua.hpp>

namespace tendril::lua {

// Adds neighbours and extend to the model methods table on top of the stack.
void add_query_methods(lua_State* L);

}  // namespace tendril::lua
