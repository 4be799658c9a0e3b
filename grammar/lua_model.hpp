#pragma once
// The `tendril` Lua module: model, particle and block handles (docs/lua-api.md).
#include <lua.hpp>

#include "lua_host.hpp"

namespace tendril::lua {

// Pushes the `tendril` table (model constructor, load, out, seed, args).
void open_tendril(lua_State* L, const SceneOptions& options);

}  // namespace tendril::lua
