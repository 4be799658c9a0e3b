#pragma once
// m:formulation on a patch: bars or constant strain triangles (thesis
// 5.5.2.2), the triangulation from edge classification (meshing layer).
#include <lua.hpp>

#include "lua_scene.hpp"

namespace tendril::lua {

// The patch branch of m:formulation(patch [, "bars" | "cst" [, options]]).
int patch_formulation(lua_State* L, Scene& s, BlockId patch);

}  // namespace tendril::lua
