#pragma once
// Geometry from other tools (io/mesh_import.hpp) into a scene:
// tendril.import(path) reads it, m:import(path, mapping) builds it
// (docs/lua-api.md, "Importing geometry").
#include <lua.hpp>

namespace tendril::lua {

// Adds tendril.import to the `tendril` table on top of the stack.
void add_import_function(lua_State* L);
// Adds m:import to the model methods table on top of the stack.
void add_import_methods(lua_State* L);

}  // namespace tendril::lua
