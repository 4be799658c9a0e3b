// m:strip: a bending strip (thesis 6.1) built as one production of the
// members of its grillage (model/strip_grillage.hpp): the particles of a
// grid, a 3-DOF beam along every row and column, two crossed bars in every
// quad and a planarity goal on every quad for the twist.
#include "lua_strip.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "command/registry.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"
#include "lua_section_args.hpp"
#include "model/strip_grillage.hpp"

namespace tendril::lua {

namespace {

using command::Value;

// The grid of particles given as `particles = {{...}, {...}, ...}`: a list
// of rows, each a list of particles along the strip.
std::vector<std::vector<ParticleId>> field_particle_grid(lua_State* L, int idx, Scene& s, const char* fn) {
  lua_getfield(L, idx, "particles");
  const int t = lua_gettop(L);
  std::vector<std::vector<ParticleId>> grid;
  try {
    if (!lua_istable(L, t)) key_error(fn, "particles", "must be a list of rows, each a list of particles");
    for (lua_Integer r = 1; r <= lua_Integer(lua_rawlen(L, t)); ++r) {
      lua_rawgeti(L, t, r);
      if (!lua_istable(L, -1)) key_error(fn, "particles", "row " + std::to_string(r) + " must be a list of particles");
      grid.push_back(check_particle_list(L, lua_gettop(L), s, fn));
      lua_pop(L, 1);
    }
  } catch (...) {
    lua_settop(L, t - 1);
    throw;
  }
  lua_pop(L, 1);
  return grid;
}

std::size_t field_count(lua_State* L, int idx, const char* key, const char* fn, std::size_t min) {
  if (!has_field(L, idx, key)) key_error(fn, key, "is required");
  const double n = field_number(L, idx, key, fn, 0);
  if (!(n == std::floor(n) && n >= double(min) && n <= 100000))
    key_error(fn, key, "must be a whole number >= " + std::to_string(min));
  return std::size_t(n);
}

double field_positive(lua_State* L, int idx, const char* key, const char* fn) {
  if (!has_field(L, idx, key)) key_error(fn, key, "is required");
  const double x = field_number(L, idx, key, fn, 0);
  if (!(x > 0 && std::isfinite(x))) key_error(fn, key, "must be > 0");
  return x;
}

// Pushes a list of handles: particles, blocks or goals.
void push_list(lua_State* L, Scene& s, command::Returns kind, const std::vector<std::uint64_t>& items) {
  lua_createtable(L, int(items.size()), 0);
  for (std::size_t k = 0; k < items.size(); ++k) {
    command::Result r;
    r.kind = kind;
    if (kind == command::Returns::Goal) r.index = std::size_t(items[k]);
    else r.ids = {std::uint32_t(items[k])};
    push_result(L, s, r);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

// m:strip{origin =, length =, width =, segments =, across =, E =, t =, nu =, density =}
// or m:strip{particles = {{...}, ...}, E =, t =, nu =, density =}.
int l_strip(lua_State* L) {
  const char* fn = "strip";
  Scene& s = check_scene(L, fn);
  command::Entry entry(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"origin", "length", "width", "segments", "across", "particles", "E", "t", "nu", "density"});
  StripMaterial mat;
  mat.E = field_positive(L, 2, "E", fn);
  mat.t = field_positive(L, 2, "t", fn);
  mat.nu = field_number(L, 2, "nu", fn, 0);
  if (!(mat.nu >= 0 && mat.nu < 0.5)) key_error(fn, "nu", "must be in [0, 0.5)");
  mat.density = field_number(L, 2, "density", fn, 0);
  if (!(mat.density >= 0 && std::isfinite(mat.density))) key_error(fn, "density", "must be >= 0");

  const bool given = has_field(L, 2, "particles");
  if (given) {
    for (const char* key : {"origin", "length", "width", "segments", "across"})
      if (has_field(L, 2, key)) key_error(fn, key, "belongs to a strip made of new particles: not with 'particles'");
  } else if (!has_field(L, 2, "origin")) {
    throw LuaArgError("strip: give 'origin', 'length', 'width', 'segments' and 'across', or 'particles' (a grid)");
  }
  std::vector<std::vector<ParticleId>> ids;
  std::vector<std::vector<Vec3>> points;
  if (given) {
    ids = field_particle_grid(L, 2, s, fn);
    for (const auto& row : ids) {
      points.emplace_back();
      for (ParticleId p : row) points.back().push_back(s.model.particles.position[p]);
    }
  } else {
    const Vec3 origin = field_vec3(L, 2, "origin", fn);
    const Vec3 along = field_vec3(L, 2, "length", fn), across = field_vec3(L, 2, "width", fn);
    const std::size_t n = field_count(L, 2, "segments", fn, 1), k = field_count(L, 2, "across", fn, 1);
    if ((n + 1) * (k + 1) > 1000000) throw LuaArgError("strip: more than a million particles");
    if (!(along.cross(across).norm() > 1e-12 * along.squaredNorm() + 1e-300))
      key_error(fn, "width", "must not be parallel to 'length' (nor zero)");
    for (std::size_t r = 0; r <= k; ++r) {
      points.emplace_back();
      for (std::size_t c = 0; c <= n; ++c) points.back().push_back(origin + (double(c) / n) * along + (double(r) / k) * across);
    }
  }
  StripGrillage g;
  try {
    g = strip_grillage(points, mat);
  } catch (const std::invalid_argument& e) {
    throw LuaArgError(std::string("strip: ") + e.what());
  }
  const std::size_t rows = points.size();

  // Each member a journaled command, the whole strip one production.
  struct Commands : StripMaker {
    lua_State* L;
    Scene& s;
    const char* fn;
    Commands(lua_State* L, Scene& s, const char* fn) : L(L), s(s), fn(fn) {}
    BlockId beam(const StripMember& m, const std::vector<ParticleId>& ps) override {
      command::Args args = {Value::of_id(0)};  // open
      append_section(args, Section{m.EA, m.EI, 0, m.line_mass});
      args.push_back(Value::of_ids({ps.begin(), ps.end()}));
      return apply_command(L, s, "beam", std::move(args), fn).ids[0];
    }
    BlockId bar(ParticleId a, ParticleId b, double EA) override {
      command::Args args = {Value::of_id(a), Value::of_id(b)};
      append_section(args, Section{EA, 0, 0, 0});
      args.push_back(Value::of_number(0));  // rest length: as built
      return apply_command(L, s, "bar", std::move(args), fn).ids[0];
    }
    std::size_t planarity(double w, const std::vector<ParticleId>& c) override {
      return apply_command(L, s, "planarity", {Value::of_number(w), Value::of_ids({c.begin(), c.end()})}, fn).index;
    }
  } commands(L, s, fn);
  StripMembers made;
  all_or_nothing(s, [&] {
    if (!given) {
      ids.assign(rows, {});
      for (std::size_t r = 0; r < rows; ++r)
        for (const Vec3& x : points[r]) ids[r].push_back(apply_command(L, s, "particle", {Value::of_vector(x)}, fn).ids[0]);
    }
    made = make_strip(ids, g, commands);
  });
  entry.done();

  lua_createtable(L, 0, 6);
  lua_createtable(L, int(rows), 0);
  for (std::size_t r = 0; r < rows; ++r) {
    push_list(L, s, command::Returns::Particle, {ids[r].begin(), ids[r].end()});
    lua_rawseti(L, -2, lua_Integer(r + 1));
  }
  lua_setfield(L, -2, "particles");
  push_list(L, s, command::Returns::Block, {made.rows.begin(), made.rows.end()});
  lua_setfield(L, -2, "rows");
  push_list(L, s, command::Returns::Block, {made.columns.begin(), made.columns.end()});
  lua_setfield(L, -2, "columns");
  push_list(L, s, command::Returns::Block, {made.bars.begin(), made.bars.end()});
  lua_setfield(L, -2, "bars");
  push_list(L, s, command::Returns::Goal, {made.twist.begin(), made.twist.end()});
  lua_setfield(L, -2, "twist");
  lua_pushnumber(L, mat.D());
  lua_setfield(L, -2, "D");
  return 1;
}

}  // namespace

void add_strip_methods(lua_State* L) { set_fn<l_strip>(L, "strip"); }

}  // namespace tendril::lua
