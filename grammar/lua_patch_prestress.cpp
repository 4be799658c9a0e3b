// m:patch_prestress(patch, {warp, weft} [, {warp = {x, y, z}, seams = false}])
// gives a patch's bars a prestress [N] per yarn family: the warp and weft
// edges come from edge classification (fig. 5.30, the same as a CST
// switch's triangles: `warp` picks the direction, `seams` allows odd
// valences, a seam edge taking the mean). Journaled with its edges, so a
// replay needs no meshing.
#include "lua_patch_prestress.hpp"

#include <string>

#include "command/registry.hpp"
#include "edge_classification.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

constexpr const char* kFn = "patch_prestress";

int l_patch_prestress(lua_State* L) {
  Scene& s = check_scene(L, kFn);
  const BlockId b = check_block(L, 2, s, kFn);
  if (s.model.blocks[b].kind != BlockKind::Patch) arg_error(kFn, 2, "must be a patch");
  if (!lua_istable(L, 3) || lua_rawlen(L, 3) != 2) arg_error(kFn, 3, "must be {warp, weft}: two forces [N]");
  double T[2];
  for (int k = 0; k < 2; ++k) {
    lua_rawgeti(L, 3, k + 1);
    if (!lua_isnumber(L, -1)) arg_error(kFn, 3, "must be {warp, weft}: two forces [N]");
    T[k] = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  meshing::ClassifyOptions o;
  if (!lua_isnoneornil(L, 4)) {
    check_table(L, 4, kFn);
    check_keys(L, 4, kFn, {"warp", "seams"});
    o.allow_seams = field_bool(L, 4, "seams", kFn, false);
    if (has_field(L, 4, "warp")) o.warp = field_vec3(L, 4, "warp", kFn);
  }
  // Triangle sides v0-v1 are warp, v1-v2 weft (edge_classification.hpp):
  // every edge of a quad is one of them in one of its two triangles.
  std::vector<std::uint32_t> warp, weft;
  try {
    for (const auto& t : meshing::cst_triangulation(s.model, b, o).triangles) {
      warp.insert(warp.end(), {t[0], t[1]});
      weft.insert(weft.end(), {t[1], t[2]});
    }
  } catch (const ModelError& e) {
    throw LuaArgError(std::string(kFn) + ": " + e.what());
  }
  using command::Value;
  const std::size_t warp_pairs = warp.size() / 2;
  warp.insert(warp.end(), weft.begin(), weft.end());
  command::Args args = {Value::of_id(b), Value::of_number(T[0]), Value::of_number(T[1]), Value::of_id(warp_pairs),
                        Value::of_ids(std::move(warp))};
  apply_command(L, s, "patch_prestress", std::move(args), kFn, 2);
  return 0;
}

}  // namespace

void add_patch_prestress_methods(lua_State* L) { set_fn<l_patch_prestress>(L, "patch_prestress"); }

}  // namespace tendril::lua
