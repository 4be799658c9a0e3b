// Bindings of the multi-resolution patch. The C++ state (which particles are
// fine, their bilinear parents, the coarse quads) lives in a userdata kept in
// the handle table under "core"; the table's visible fields follow each
// switch. Every change is recorded primitive by primitive (particle, patch,
// lock, passive, position, delete), so a replayed journal rebuilds it bit
// for bit without knowing about multi-resolution.
#include "lua_multires.hpp"

#include <new>
#include <string>

#include "io/trace.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"
#include "multires.hpp"

namespace tendril::lua {

namespace {

using command::Value;

constexpr const char* kMultiresMeta = "tendril.Multires";

struct MultiresBox {
  Scene* scene;
  meshing::MultiresPatch mr;
};

int l_box_gc(lua_State* L) {
  static_cast<MultiresBox*>(luaL_checkudata(L, 1, kMultiresMeta))->~MultiresBox();
  return 0;
}

MultiresBox& check_box(lua_State* L, int idx, Scene& s, const char* fn) {
  if (!lua_istable(L, idx)) arg_error(fn, idx, std::string("expected a multi-resolution patch (from m:multires), got ") + luaL_typename(L, idx));
  lua_getfield(L, idx, "core");
  auto* box = static_cast<MultiresBox*>(luaL_testudata(L, -1, kMultiresMeta));
  lua_pop(L, 1);  // the table keeps the userdata alive
  if (!box) arg_error(fn, idx, "expected a multi-resolution patch (from m:multires)");
  if (box->scene != &s) arg_error(fn, idx, "the patch belongs to another model");
  return *box;
}

// The visible fields of the handle table at idx.
void refresh_fields(lua_State* L, int idx, Scene& s, const meshing::MultiresPatch& mr) {
  if (mr.coarse_mode()) push_block(L, s, mr.coarse);
  else lua_pushnil(L);
  lua_setfield(L, idx, "coarse");
  push_block(L, s, mr.fine);
  lua_setfield(L, idx, "fine");
  lua_pushinteger(L, mr.factor);
  lua_setfield(L, idx, "factor");
  lua_pushboolean(L, mr.coarse_mode());
  lua_setfield(L, idx, "is_coarse");
}

// m:multires(patch [, {factor = 2, EA =, prestress =, line_mass =}]).
int l_multires(lua_State* L) {
  const char* fn = "multires";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  const BlockId b = check_block(L, 2, s, fn);
  int factor = 2;
  const Section* fine = nullptr;
  Section custom;
  if (!lua_isnoneornil(L, 3)) {
    check_table(L, 3, fn);
    check_keys(L, 3, fn, {"factor", "EA", "prestress", "line_mass"});
    const double f = field_number(L, 3, "factor", fn, 2);
    if (f != double(int(f))) key_error(fn, "factor", "must be an integer");
    factor = int(f);
    if (has_field(L, 3, "EA") || has_field(L, 3, "prestress") || has_field(L, 3, "line_mass")) {
      if (s.model.block_valid(b)) custom = s.model.blocks[b].section;
      const double k = factor > 0 ? factor : 1;
      custom.EA = field_number(L, 3, "EA", fn, custom.EA / k);
      custom.prestress = field_number(L, 3, "prestress", fn, custom.prestress / k);
      custom.line_mass = field_number(L, 3, "line_mass", fn, custom.line_mass / k);
      fine = &custom;
    }
  }
  meshing::MultiresPatch mr = meshing::multires_patch(s.model, b, factor, fine);
  const Model& m = s.model;
  for (ParticleId p : mr.particles) record_command(s, "particle", {Value::of_vector(m.particles.position[p])});
  record_patch_command(s, mr.fine_section, mr.fine_quads);
  for (ParticleId p : mr.particles) {
    if (m.particles.lock[p]) record_command(s, "lock", {Value::of_id(p), Value::of_id(m.particles.lock[p])});
    record_command(s, "passive", {Value::of_id(p), Value::of_id(1)});
  }
  lua_createtable(L, 0, 6);
  const int table = lua_gettop(L);
  auto* box = static_cast<MultiresBox*>(lua_newuserdatauv(L, sizeof(MultiresBox), 0));
  new (box) MultiresBox{&s, std::move(mr)};
  luaL_setmetatable(L, kMultiresMeta);
  lua_setfield(L, table, "core");
  lua_createtable(L, int(box->mr.particles.size()), 0);
  for (std::size_t k = 0; k < box->mr.particles.size(); ++k) {
    push_particle(L, s, box->mr.particles[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, table, "particles");
  refresh_fields(L, table, s, box->mr);
  record.done();
  return 1;
}

// m:refine(mr): the fine particles onto the coarse surface, active; the
// coarse links deleted.
int l_refine(lua_State* L) {
  const char* fn = "refine";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  MultiresBox& box = check_box(L, 2, s, fn);
  const BlockId coarse = box.mr.coarse;
  meshing::multires_refine(s.model, box.mr);
  const Model& m = s.model;
  for (ParticleId p : box.mr.particles)
    record_command(s, "position", {Value::of_id(p), Value::of_vector(m.particles.position[p])});
  for (ParticleId p : box.mr.particles) record_command(s, "passive", {Value::of_id(p), Value::of_id(0)});
  record_command(s, "delete", {Value::of_id(coarse)});
  refresh_fields(L, 2, s, box.mr);
  record.done();
  return 0;
}

// m:coarsen(mr): the coarse links again, the fine particles passive.
int l_coarsen(lua_State* L) {
  const char* fn = "coarsen";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  MultiresBox& box = check_box(L, 2, s, fn);
  meshing::multires_coarsen(s.model, box.mr);
  record_patch_command(s, box.mr.coarse_section, box.mr.coarse_quads);
  for (ParticleId p : box.mr.particles) record_command(s, "passive", {Value::of_id(p), Value::of_id(1)});
  refresh_fields(L, 2, s, box.mr);
  record.done();
  return 0;
}

}  // namespace

void add_multires_methods(lua_State* L) {
  if (luaL_newmetatable(L, kMultiresMeta)) {
    lua_pushcfunction(L, l_box_gc);
    lua_setfield(L, -2, "__gc");
  }
  lua_pop(L, 1);
  set_fn<l_multires>(L, "multires");
  set_fn<l_refine>(L, "refine");
  set_fn<l_coarsen>(L, "coarsen");
}

}  // namespace tendril::lua
