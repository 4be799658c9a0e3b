#pragma once
// Goals of the constraint-based solvers from Lua: m:anchor, m:goal,
// m:goal_weight, m:remove_goal (docs/lua-api.md).
#include <lua.hpp>

namespace tendril::lua {

// Adds the goal methods to the model methods table on top of the stack.
void add_goal_methods(lua_State* L);

}  // namespace tendril::lua
