// m:formulation(patch) -> "bars" | "cst", {stress = {sw, sf}, analysis = {...}}
// m:formulation(patch, "cst", {stress = {sw, sf} [, analysis = {dxx =, dxy =,
//     dyx =, dyy =, G =}] [, warp = {x, y, z}] [, seams = false]})
// m:formulation(patch, "bars")
// Form-finding without `analysis` (eq. 3.36, stresses in N/m); with it,
// analysis against the current shape (eq. 3.37-3.39), `stress` then being the
// prestress (default 0). The triangles come from edge classification
// (m:triangulation, fig. 5.30) with `warp` and `seams`; a patch already in
// CST mode keeps its triangles unless one of them is given. Everything is
// checked before the model changes; the switch is journaled with its
// triangles, so a replay needs no meshing.
#include "lua_patch_formulation.hpp"

#include <string>

#include "edge_classification.hpp"
#include "io/trace.hpp"
#include "command/registry.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"

namespace tendril::lua {

namespace {

constexpr const char* kFn = "formulation";

// {a, b}: two numbers.
void read_pair(lua_State* L, int idx, const char* key, double& a, double& b) {
  lua_getfield(L, idx, key);
  if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2) key_error(kFn, key, "must be a table of two numbers {warp, weft}");
  for (int k = 1; k <= 2; ++k) {
    lua_rawgeti(L, -1, k);
    if (!lua_isnumber(L, -1)) key_error(kFn, key, "must be a table of two numbers {warp, weft}");
    (k == 1 ? a : b) = lua_tonumber(L, -1);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

void read_analysis(lua_State* L, int idx, Membrane& m) {
  lua_getfield(L, idx, "analysis");
  const int t = lua_gettop(L);
  check_table(L, t, kFn);
  check_keys(L, t, kFn, {"dxx", "dxy", "dyx", "dyy", "G"});
  if (!has_field(L, t, "dxx") || !has_field(L, t, "dyy")) key_error(kFn, "analysis", "needs dxx and dyy [N/m]");
  m.dxx = field_number(L, t, "dxx", kFn, 0);
  m.dyy = field_number(L, t, "dyy", kFn, 0);
  m.dxy = field_number(L, t, "dxy", kFn, 0);
  m.dyx = field_number(L, t, "dyx", kFn, m.dxy);
  m.G = field_number(L, t, "G", kFn, 0);
  lua_pop(L, 1);
}

void push_current(lua_State* L, const Membrane& m) {
  lua_pushstring(L, m.cst() ? "cst" : "bars");
  if (!m.cst()) return;
  lua_createtable(L, 0, 2);
  lua_createtable(L, 2, 0);
  lua_pushnumber(L, m.sigma_warp);
  lua_rawseti(L, -2, 1);
  lua_pushnumber(L, m.sigma_weft);
  lua_rawseti(L, -2, 2);
  lua_setfield(L, -2, "stress");
  if (m.mode == Membrane::Analysis) {
    lua_createtable(L, 0, 5);
    const std::pair<const char*, double> d[] = {{"dxx", m.dxx}, {"dxy", m.dxy}, {"dyx", m.dyx}, {"dyy", m.dyy}, {"G", m.G}};
    for (const auto& [k, v] : d) {
      lua_pushnumber(L, v);
      lua_setfield(L, -2, k);
    }
    lua_setfield(L, -2, "analysis");
  }
}

}  // namespace

int patch_formulation(lua_State* L, Scene& s, BlockId b) {
  Model& model = s.model;
  if (lua_isnoneornil(L, 3)) {
    push_current(L, model.patch_formulation(b));
    return model.patch_formulation(b).cst() ? 2 : 1;
  }
  if (lua_type(L, 3) != LUA_TSTRING) arg_error(kFn, 3, "a patch's formulation is \"bars\" or \"cst\"");
  const std::string kind = lua_tostring(L, 3);
  Membrane mem;
  std::vector<Model::Triangle> triangles;
  if (kind == "bars") {
    if (!lua_isnoneornil(L, 4)) arg_error(kFn, 4, "\"bars\" takes no options");
  } else if (kind == "cst") {
    check_table(L, 4, kFn);
    check_keys(L, 4, kFn, {"stress", "analysis", "warp", "seams"});
    const bool analysis = has_field(L, 4, "analysis");
    mem.mode = analysis ? Membrane::Analysis : Membrane::FormFinding;
    if (has_field(L, 4, "stress")) read_pair(L, 4, "stress", mem.sigma_warp, mem.sigma_weft);
    else if (!analysis) key_error(kFn, "stress", "is required for form-finding: {warp, weft} in N/m");
    if (analysis) read_analysis(L, 4, mem);
    const bool options = has_field(L, 4, "warp") || has_field(L, 4, "seams");
    if (model.patch_formulation(b).cst() && !options) {
      triangles = model.patch_triangles(b);
    } else {
      meshing::ClassifyOptions o;
      o.allow_seams = field_bool(L, 4, "seams", kFn, false);
      if (has_field(L, 4, "warp")) o.warp = field_vec3(L, 4, "warp", kFn);
      try {
        for (const auto& t : meshing::cst_triangulation(model, b, o).triangles) triangles.push_back({t[0], t[1], t[2]});
      } catch (const ModelError& e) {
        throw LuaArgError(std::string(kFn) + ": " + e.what());
      }
    }
  } else {
    arg_error(kFn, 3, "a patch's formulation is \"bars\" or \"cst\", not \"" + kind + "\"");
  }
  using command::Value;
  command::Args args = {Value::of_id(b), Value::of_word(membrane_mode_name(mem.mode))};
  for (double x : {mem.sigma_warp, mem.sigma_weft, mem.dxx, mem.dxy, mem.dyx, mem.dyy, mem.G})
    args.push_back(Value::of_number(x));
  std::vector<std::uint32_t> ids;
  for (const Model::Triangle& t : triangles) ids.insert(ids.end(), t.begin(), t.end());
  args.push_back(Value::of_ids(std::move(ids)));
  const command::Command& c = command::get("formulation");
  for (std::size_t k = 2; k < args.size(); ++k) args[k].given = c.on_line(args, k);
  apply_command(L, s, c, std::move(args), kFn, 2);
  return 0;
}

}  // namespace tendril::lua
