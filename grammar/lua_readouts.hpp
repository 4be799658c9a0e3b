#pragma once
// The read-only methods that return one value of a particle, a block or the
// solver (m:position(p), m:kind(b), m:residual(), ...), each one line in a
// table (lua_readouts.cpp) read by one binding.
#include <lua.hpp>

namespace tendril::lua {

// Adds them to the methods table on top of the stack.
void add_readout_methods(lua_State* L);

}  // namespace tendril::lua
