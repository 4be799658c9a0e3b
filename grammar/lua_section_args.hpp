#pragma once
// A block's section read from a Lua option table ({EA =, EI =} or {E =, A =,
// I =}, with prestress and line_mass) and handed to a command as its four
// section arguments: shared by m:beam, m:cable, m:bar, m:quad_grid and
// m:import.
#include <lua.hpp>

#include "command/value.hpp"
#include "model/types.hpp"

namespace tendril::lua {

// The section of the options at idx; `beam` asks for EI (or I) too.
Section read_section(lua_State* L, int idx, const char* fn, bool beam);
// Appends EA, EI, prestress and line_mass.
void append_section(command::Args& args, const Section& sec);

}  // namespace tendril::lua
