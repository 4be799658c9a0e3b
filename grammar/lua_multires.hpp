#pragma once
// Lua access to the multi-resolution tensile patch (thesis 5.5.2.3,
// meshing/multires.hpp): m:multires(patch, {factor =, EA =, prestress =,
// line_mass =}) returns a handle table {coarse = block or nil, fine = block,
// factor = k, particles = {fine-only particles}}; m:refine(mr) and
// m:coarsen(mr) switch it. Each records its primitives on the trace.
#include <lua.hpp>

namespace tendril::lua {

void add_multires_methods(lua_State* L);  // onto the model methods table on top of the stack

}  // namespace tendril::lua
