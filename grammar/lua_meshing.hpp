#pragma once
// Lua access to the meshing layer (thesis 5.3, rules 19-22 and 25): tensile
// patches by paving, Catmull-Clark and projection, subdivision of a patch,
// its quality figures and its CST triangulation by edge classification.
#include <lua.hpp>

namespace tendril::lua {

// Adds pave, catmull_clark, project, subdivide_patch, quality and
// triangulation to the model methods table on top of the stack.
void add_meshing_methods(lua_State* L);

}  // namespace tendril::lua
