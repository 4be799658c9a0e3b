#include "lua_sections.hpp"

#include <cmath>
#include <string>

#include "lua_args.hpp"
#include "model/cross_section.hpp"
#include "model/materials.hpp"

namespace tendril::lua {

namespace {

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

void set_string(lua_State* L, const char* key, const std::string& v) {
  lua_pushlstring(L, v.data(), v.size());
  lua_setfield(L, -2, key);
}

void push_material(lua_State* L, const Material& m) {
  lua_newtable(L);
  set_string(L, "name", m.name);
  set_number(L, "E", m.E);
  set_number(L, "G", m.G);
  set_number(L, "density", m.density);
  set_number(L, "strength", m.strength);
  set_string(L, "source", m.source);
}

std::string names_of_materials() {
  std::string out;
  for (const Material& m : materials()) out += (out.empty() ? "" : ", ") + m.name;
  return out;
}

// The section's `material`: a name of the table or {E =, G =, density =, strength =}.
bool read_material(lua_State* L, const char* fn, Material& out) {
  lua_getfield(L, 1, "material");
  const int type = lua_type(L, -1);
  if (type == LUA_TNIL) {
    lua_pop(L, 1);
    return false;
  }
  if (type == LUA_TSTRING) {
    const std::string name = lua_tostring(L, -1);
    lua_pop(L, 1);
    const Material* m = find_material(name);
    if (!m) key_error(fn, "material", "is '" + name + "', which is no material of the table (" + names_of_materials() + ")");
    out = *m;
    return true;
  }
  if (type != LUA_TTABLE) key_error(fn, "material", "must be a material's name or a table {E =, G =, density =, strength =}");
  const int t = lua_gettop(L);
  const std::string what = std::string(fn) + " material";
  check_keys(L, t, what.c_str(), {"name", "E", "G", "density", "strength", "source"});
  out.name = field_string(L, t, "name", what.c_str(), "custom");
  out.E = field_number(L, t, "E", what.c_str(), NAN);
  out.G = field_number(L, t, "G", what.c_str(), out.E / 2.6);  // isotropic, nu = 0.3
  out.density = field_number(L, t, "density", what.c_str(), 0);
  out.strength = field_number(L, t, "strength", what.c_str(), 0);
  out.source = field_string(L, t, "source", what.c_str(), "given by the scene");
  lua_pop(L, 1);
  if (!(std::isfinite(out.E) && out.E > 0)) key_error(fn, "material", "needs E > 0 [Pa]");
  if (!(std::isfinite(out.G) && out.G > 0)) key_error(fn, "material", "needs G > 0 [Pa]");
  if (!(std::isfinite(out.density) && out.density >= 0)) key_error(fn, "material", "density must be >= 0 [kg/m^3]");
  if (!(std::isfinite(out.strength) && out.strength >= 0)) key_error(fn, "material", "strength must be >= 0 [Pa]");
  return true;
}

// The section table; with a material also the member stiffnesses a beam,
// cable or bar takes (EA, EI = the smaller of EIy and EIz, EIy, EIz, GJ,
// line_mass) and the strength for utilisation.
int push_section(lua_State* L, const char* fn, const CrossSection& s) {
  Material mat;
  const bool has_material = read_material(L, fn, mat);
  lua_newtable(L);
  set_number(L, "A", s.A);
  set_number(L, "Iy", s.Iy);
  set_number(L, "Iz", s.Iz);
  set_number(L, "I", std::min(s.Iy, s.Iz));
  set_number(L, "J", s.J);
  set_number(L, "Wy", s.Wy);
  set_number(L, "Wz", s.Wz);
  if (!has_material) return 1;
  push_material(L, mat);
  lua_setfield(L, -2, "material");
  set_number(L, "EA", mat.E * s.A);
  set_number(L, "EI", mat.E * std::min(s.Iy, s.Iz));
  set_number(L, "EIy", mat.E * s.Iy);
  set_number(L, "EIz", mat.E * s.Iz);
  set_number(L, "GJ", mat.G * s.J);
  set_number(L, "line_mass", mat.density * s.A);
  set_number(L, "strength", mat.strength);
  return 1;
}

int l_rod(lua_State* L) {
  const char* fn = "tendril.section.rod";
  check_table(L, 1, fn);
  check_keys(L, 1, fn, {"d", "material"});
  return push_section(L, fn, rod_section(field_number(L, 1, "d", fn, NAN)));
}

int l_tube(lua_State* L) {
  const char* fn = "tendril.section.tube";
  check_table(L, 1, fn);
  check_keys(L, 1, fn, {"d", "t", "material"});
  return push_section(L, fn, tube_section(field_number(L, 1, "d", fn, NAN), field_number(L, 1, "t", fn, NAN)));
}

int l_rect(lua_State* L) {
  const char* fn = "tendril.section.rect";
  check_table(L, 1, fn);
  check_keys(L, 1, fn, {"b", "h", "material"});
  return push_section(L, fn, rect_section(field_number(L, 1, "b", fn, NAN), field_number(L, 1, "h", fn, NAN)));
}

int l_material(lua_State* L) {
  const char* fn = "tendril.material";
  const std::string name = luaL_checkstring(L, 1);
  const Material* m = find_material(name);
  if (!m) arg_error(fn, 1, "no material '" + name + "' (there are " + names_of_materials() + ")");
  push_material(L, *m);
  return 1;
}

int l_materials(lua_State* L) {
  lua_newtable(L);
  lua_Integer k = 0;
  for (const Material& m : materials()) {
    lua_pushlstring(L, m.name.data(), m.name.size());
    lua_seti(L, -2, ++k);
  }
  for (const Fabric& f : fabrics()) {
    lua_pushlstring(L, f.name.data(), f.name.size());
    lua_seti(L, -2, ++k);
  }
  return 1;
}

// A fabric's values and `analysis`, the orthotropic stiffnesses of
// m:formulation(patch, "cst", {analysis = ...}), eq. 3.38 in plane stress:
// dxx = Et_warp k, dyy = Et_weft k, dxy = nu Et_weft k, with nu the warp-
// weft Poisson's ratio, its converse nu Et_weft / Et_warp (symmetry) and
// k = 1 / (1 - the product of the two).
int l_fabric(lua_State* L) {
  const char* fn = "tendril.fabric";
  const std::string name = luaL_checkstring(L, 1);
  const Fabric* f = find_fabric(name);
  if (!f) {
    std::string names;
    for (const Fabric& x : fabrics()) names += (names.empty() ? "" : ", ") + x.name;
    arg_error(fn, 1, "no fabric '" + name + "' (there are " + names + ")");
  }
  lua_newtable(L);
  set_string(L, "name", f->name);
  set_number(L, "Et_warp", f->Et_warp);
  set_number(L, "Et_weft", f->Et_weft);
  set_number(L, "nu", f->nu);
  set_number(L, "G", f->G);
  set_number(L, "strength_warp", f->strength_warp);
  set_number(L, "strength_weft", f->strength_weft);
  set_number(L, "weight", f->weight);
  set_string(L, "source", f->source);
  const double nu_xy = f->nu, nu_yx = f->nu * f->Et_weft / f->Et_warp, k = 1 / (1 - nu_xy * nu_yx);
  lua_newtable(L);
  set_number(L, "dxx", k * f->Et_warp);
  set_number(L, "dyy", k * f->Et_weft);
  set_number(L, "dxy", k * nu_xy * f->Et_weft);
  set_number(L, "G", f->G);
  lua_setfield(L, -2, "analysis");
  return 1;
}

}  // namespace

void add_sections(lua_State* L) {
  lua_newtable(L);
  set_fn<l_rod>(L, "rod");
  set_fn<l_tube>(L, "tube");
  set_fn<l_rect>(L, "rect");
  lua_setfield(L, -2, "section");
  set_fn<l_material>(L, "material");
  set_fn<l_materials>(L, "materials");
  set_fn<l_fabric>(L, "fabric");
}

}  // namespace tendril::lua
