#pragma once
// tendril.param(name, default): a scene declares a parameter and reads its
// --param value. A --param the scene has not declared by its first step, or
// a word for a parameter whose default is a number, is a usage error: the
// scene stops and run_scene returns 2.
#include <lua.hpp>

#include <string>

#include "lua_host.hpp"

namespace tendril::lua {

// Sets tendril.param on the `tendril` table on top of the stack.
void add_param(lua_State* L);

// m:run{} and m:step() call this before they step: the first call checks
// the --param names against the declarations; a declarations_only scene
// stops here.
void begin_stepping();

// The first --param the scene does not declare, as a message; "" when none.
std::string undeclared_param(const SceneOptions& options, const SceneReport& report);

}  // namespace tendril::lua
