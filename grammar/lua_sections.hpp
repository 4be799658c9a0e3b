#pragma once
// tendril.section.rod/tube/rect{...}, tendril.material(name),
// tendril.fabric(name): cross-sections and materials for scenes
// (model/cross_section.hpp, model/materials.hpp), so that a scene writes
// `tendril.section.tube{d = 0.02, t = 0.002, material = "gfrp"}.EI`
// instead of pi d^4 / 64 by hand.
#include <lua.hpp>

namespace tendril::lua {

// Adds section, material, materials, fabric, fabrics to the `tendril` table on top of the stack.
void add_sections(lua_State* L);

}  // namespace tendril::lua
