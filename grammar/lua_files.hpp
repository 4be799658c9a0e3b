#pragma once
// The file functions of the `tendril` module: tendril.write_file.
#include <lua.hpp>

namespace tendril::lua {

// Adds the file functions to the table on top of the stack.
void add_file_functions(lua_State* L);

}  // namespace tendril::lua
