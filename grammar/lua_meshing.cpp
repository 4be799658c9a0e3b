// Lua bindings of the meshing layer. Each patch-making method validates
// everything before it changes the model (meshing/commit_patch.hpp), so a
// refused call leaves the model as it was; a successful one records the
// primitives it caused on the trace — moved particles, new particles, the
// patch — so that a replayed journal rebuilds the same model bit for bit.
#include "lua_meshing.hpp"

#include <cmath>
#include <string>
#include <utility>

#include "catmull_clark_rules.hpp"
#include "edge_classification.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"
#include "paving.hpp"
#include "projection.hpp"
#include "quality.hpp"
#include "tube.hpp"

namespace tendril::lua {

namespace {

// Runs a meshing call and rewords its ModelError so it names the Lua method:
// "paving: needs at least 8 particles" becomes "pave: needs at least 8 particles".
template <class F>
auto as_method(const char* fn, const std::string& inner, F&& f) {
  try {
    return f();
  } catch (const ModelError& e) {
    std::string message = e.what();
    const std::string prefix = inner + ": ";
    if (message.compare(0, prefix.size(), prefix) == 0) message.erase(0, prefix.size());
    throw LuaArgError(std::string(fn) + ": " + message);
  }
}

std::vector<ParticleId> field_particles(lua_State* L, int idx, const char* key, Scene& s, const char* fn) {
  lua_getfield(L, idx, key);
  if (lua_isnil(L, -1)) {
    lua_pop(L, 1);
    key_error(fn, key, "is required (a list of particles)");
  }
  try {
    std::vector<ParticleId> out = check_particle_list(L, lua_gettop(L), s, fn);
    lua_pop(L, 1);
    return out;
  } catch (...) {
    lua_pop(L, 1);
    throw;
  }
}

// A patch's section: EA (or E with A), prestress, line_mass; unset keys keep
// `base`'s values.
Section read_patch_section(lua_State* L, int idx, const char* fn, Section base, bool ea_required) {
  const bool by_modulus = has_field(L, idx, "E");
  if (by_modulus && has_field(L, idx, "EA")) throw LuaArgError(std::string(fn) + ": give EA or E with A, not both");
  if (by_modulus) {
    if (!has_field(L, idx, "A")) key_error(fn, "A", "is required with E");
    base.EA = field_number(L, idx, "E", fn, 0) * field_number(L, idx, "A", fn, 0);
  } else if (has_field(L, idx, "EA")) {
    base.EA = field_number(L, idx, "EA", fn, 0);
  } else if (ea_required) {
    key_error(fn, "EA", "is required (or E with A)");
  }
  base.prestress = field_number(L, idx, "prestress", fn, base.prestress);
  base.line_mass = field_number(L, idx, "line_mass", fn, base.line_mass);
  if (!(base.EA > 0)) key_error(fn, "EA", "must be > 0");
  if (!(base.prestress >= 0)) key_error(fn, "prestress", "must be >= 0");
  if (!(base.line_mass >= 0)) key_error(fn, "line_mass", "must be >= 0");
  return base;
}

int field_count(lua_State* L, int idx, const char* key, const char* fn, int fallback, int least, int most) {
  const double v = field_number(L, idx, key, fn, fallback);
  if (v != std::floor(v) || v < least || v > most)
    key_error(fn, key, "must be an integer from " + std::to_string(least) + " to " + std::to_string(most));
  return int(v);
}

// The trace lines of a committed patch, in the order commit_patch made the
// changes: moves, new particles, the patch.
void record_patch(Scene& s, const meshing::CommittedPatch& c, const Section& sec) {
  using command::Value;
  const Model& m = s.model;
  for (ParticleId p : c.moved) record_command(s, "position", {Value::of_id(p), Value::of_vector(m.particles.position[p])});
  for (ParticleId p : c.created) record_command(s, "particle", {Value::of_vector(m.particles.position[p])});
  record_patch_command(s, sec, c.quads);
}

// holes = {{...}, {...}}: a list of particle lists (may be empty).
std::vector<std::vector<ParticleId>> field_holes(lua_State* L, int idx, Scene& s, const char* fn) {
  std::vector<std::vector<ParticleId>> out;
  lua_getfield(L, idx, "holes");
  const int t = lua_gettop(L);
  try {
    if (!lua_isnil(L, t)) {
      if (!lua_istable(L, t)) key_error(fn, "holes", "must be a list of particle lists");
      const lua_Integer n = lua_Integer(lua_rawlen(L, t));
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, t, i);
        if (!lua_istable(L, -1))
          key_error(fn, "holes", "must be a list of particle lists (item " + std::to_string(i) + " is not a list)");
        out.push_back(check_particle_list(L, lua_gettop(L), s, fn));
        lua_pop(L, 1);
      }
    }
  } catch (...) {
    lua_settop(L, t - 1);
    throw;
  }
  lua_settop(L, t - 1);
  return out;
}

// m:pave{particles = {...}, holes = {{...}, ...}, EA =, prestress =, line_mass =}:
// rule 20, optionally with holes.
int l_pave(lua_State* L) {
  const char* fn = "pave";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"particles", "holes", "EA", "E", "A", "prestress", "line_mass"});
  const Section sec = read_patch_section(L, 2, fn, {}, true);
  const std::vector<ParticleId> loop = field_particles(L, 2, "particles", s, fn);
  const auto holes = field_holes(L, 2, s, fn);
  const auto c = as_method(fn, "paving", [&] { return meshing::patch_by_paving(s.model, loop, holes, sec); });
  record_patch(s, c, sec);
  push_block(L, s, c.patch);
  record.done();
  return 1;
}

// m:catmull_clark{particles = {...}, levels = k, EA =, ...}: rule 19.
int l_catmull_clark(lua_State* L) {
  const char* fn = "catmull_clark";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"particles", "levels", "EA", "E", "A", "prestress", "line_mass"});
  const Section sec = read_patch_section(L, 2, fn, {}, true);
  const int levels = field_count(L, 2, "levels", fn, 0, 0, meshing::kMaxLoopLevels);
  const std::vector<ParticleId> loop = field_particles(L, 2, "particles", s, fn);
  const auto c =
      as_method(fn, "catmull_clark_patch", [&] { return meshing::patch_from_loop(s.model, loop, levels, sec); });
  record_patch(s, c, sec);
  push_block(L, s, c.patch);
  record.done();
  return 1;
}

// m:project{from = {...}, to = {...}, rows = r, closed = false, EA =, ...}:
// rule 21; closed = true is the tube between two rings (rule 22).
int l_project(lua_State* L) {
  const char* fn = "project";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"from", "to", "rows", "closed", "EA", "E", "A", "prestress", "line_mass"});
  const Section sec = read_patch_section(L, 2, fn, {}, true);
  const int rows = field_count(L, 2, "rows", fn, 0, 0, meshing::kMaxProjectionRows);
  const bool closed = field_bool(L, 2, "closed", fn, false);
  const std::vector<ParticleId> a = field_particles(L, 2, "from", s, fn);
  const std::vector<ParticleId> b = field_particles(L, 2, "to", s, fn);
  const auto c =
      as_method(fn, "projection", [&] { return meshing::patch_by_projection(s.model, a, b, rows, sec, closed); });
  record_patch(s, c, sec);
  push_block(L, s, c.patch);
  record.done();
  return 1;
}

void push_particle_list(lua_State* L, Scene& s, const std::vector<ParticleId>& ps) {
  lua_createtable(L, int(ps.size()), 0);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    push_particle(L, s, ps[i]);
    lua_rawseti(L, -2, lua_Integer(i + 1));
  }
}

// m:tube{between = {p1, p2}, rows = r, rings = k, EA =, prestress =, line_mass =}:
// rule 22, the tube between two patches' interiors; returns the tube and
// the two rims (rim_b[i] faces rim_a[i]).
int l_tube(lua_State* L) {
  const char* fn = "tube";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"between", "rows", "rings", "EA", "E", "A", "prestress", "line_mass"});
  const Section sec = read_patch_section(L, 2, fn, {}, true);
  const int rows = field_count(L, 2, "rows", fn, 0, 0, meshing::kMaxProjectionRows);
  const int rings = field_count(L, 2, "rings", fn, 1, 1, meshing::kMaxTubeRings);
  const std::vector<ParticleId> ends = field_particles(L, 2, "between", s, fn);
  if (ends.size() != 2) key_error(fn, "between", "must hold two particles, got " + std::to_string(ends.size()));
  const auto t = as_method(fn, "tube", [&] {
    return meshing::tube_between_patches(s.model, ends[0], ends[1], rows, sec, rings);
  });
  for (ParticleId q : t.removed) record_command(s, "remove_from_patch", {command::Value::of_id(q)});
  record_patch(s, t.tube, sec);
  push_block(L, s, t.tube.patch);
  push_particle_list(L, s, t.rim_a);
  push_particle_list(L, s, t.rim_b);
  record.done();
  return 3;
}

// m:subdivide_patch(patch [, {EA =, prestress =, line_mass =}]): rule 25, a
// new patch one Catmull-Clark step finer. The old patch stays alive until the
// model can delete patches (see meshing/catmull_clark_rules.hpp).
int l_subdivide_patch(lua_State* L) {
  const char* fn = "subdivide_patch";
  Scene& s = check_scene(L, fn);
  command::Entry record(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  const BlockId b = check_block(L, 2, s, fn);
  if (s.model.blocks[b].kind != BlockKind::Patch)
    arg_error(fn, 2, std::string("expected a patch, got a ") + block_kind_name(s.model.blocks[b].kind));
  Section sec = s.model.blocks[b].section;
  if (!lua_isnoneornil(L, 3)) {
    check_table(L, 3, fn);
    check_keys(L, 3, fn, {"EA", "E", "A", "prestress", "line_mass"});
    sec = read_patch_section(L, 3, fn, sec, false);
  }
  const auto c = as_method(fn, fn, [&] { return meshing::subdivide_patch(s.model, b, sec); });
  record_patch(s, c, sec);
  push_block(L, s, c.patch);
  record.done();
  return 1;
}

// m:quality(patch) -> {quads, jacobian_min, jacobian_mean, angle_min,
// angle_max, irregular, irregular_vertices, interior_vertices}.
int l_quality(lua_State* L) {
  const char* fn = "quality";
  Scene& s = check_scene(L, fn);
  const BlockId b = check_block(L, 2, s, fn);
  const meshing::Quality q = as_method(fn, fn, [&] { return meshing::quality(s.model, b); });
  lua_createtable(L, 0, 8);
  auto set = [&](const char* k, double v) {
    lua_pushnumber(L, v);
    lua_setfield(L, -2, k);
  };
  auto set_int = [&](const char* k, std::size_t v) {
    lua_pushinteger(L, lua_Integer(v));
    lua_setfield(L, -2, k);
  };
  set_int("quads", q.quads);
  set("jacobian_min", q.jacobian_min);
  set("jacobian_mean", q.jacobian_mean);
  set("angle_min", q.angle_min);
  set("angle_max", q.angle_max);
  set("irregular", q.irregular_fraction);
  set_int("irregular_vertices", q.irregular_vertices);
  set_int("interior_vertices", q.interior_vertices);
  return 1;
}

void push_particle_tuples(lua_State* L, Scene& s, const auto& tuples) {
  lua_createtable(L, int(tuples.size()), 0);
  for (std::size_t k = 0; k < tuples.size(); ++k) {
    lua_createtable(L, int(tuples[k].size()), 0);
    for (std::size_t i = 0; i < tuples[k].size(); ++i) {
      push_particle(L, s, tuples[k][i]);
      lua_rawseti(L, -2, lua_Integer(i + 1));
    }
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

// m:triangulation(patch [, {seams = false, warp = {x, y, z}}]) -> {triangles
// = {{a, b, c}, ...}, seams = {{p, q}, ...}, flips = {...}, warp_edges,
// weft_edges}: the CST triangulation by edge classification (fig. 5.30),
// side a-b of every triangle along the warp. Changes nothing.
int l_triangulation(lua_State* L) {
  const char* fn = "triangulation";
  Scene& s = check_scene(L, fn);
  const BlockId b = check_block(L, 2, s, fn);
  meshing::ClassifyOptions o;
  if (!lua_isnoneornil(L, 3)) {
    check_table(L, 3, fn);
    check_keys(L, 3, fn, {"seams", "warp"});
    o.allow_seams = field_bool(L, 3, "seams", fn, false);
    if (has_field(L, 3, "warp")) o.warp = field_vec3(L, 3, "warp", fn);
  }
  const meshing::PatchTriangulation t =
      as_method(fn, "edge classification", [&] { return meshing::cst_triangulation(s.model, b, o); });
  lua_createtable(L, 0, 5);
  push_particle_tuples(L, s, t.triangles);
  lua_setfield(L, -2, "triangles");
  push_particle_tuples(L, s, t.seams);
  lua_setfield(L, -2, "seams");
  push_particle_tuples(L, s, t.flips);
  lua_setfield(L, -2, "flips");
  lua_pushinteger(L, lua_Integer(t.warp_edges));
  lua_setfield(L, -2, "warp_edges");
  lua_pushinteger(L, lua_Integer(t.weft_edges));
  lua_setfield(L, -2, "weft_edges");
  return 1;
}

}  // namespace

void add_meshing_methods(lua_State* L) {
  set_fn<l_pave>(L, "pave");
  set_fn<l_catmull_clark>(L, "catmull_clark");
  set_fn<l_project>(L, "project");
  set_fn<l_tube>(L, "tube");
  set_fn<l_subdivide_patch>(L, "subdivide_patch");
  set_fn<l_quality>(L, "quality");
  set_fn<l_triangulation>(L, "triangulation");
}

}  // namespace tendril::lua
