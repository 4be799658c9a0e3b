// tendril.import and m:import (lua_import.hpp). m:import is one production:
// a particle per vertex, then per polyline or face group the blocks its
// mapping asks for, each a journaled command, all or nothing.
#include "lua_import.hpp"

#include <string>
#include <vector>

#include "command/registry.hpp"
#include "io/input_file.hpp"
#include "io/mesh_import.hpp"
#include "lua_args.hpp"
#include "lua_commands.hpp"
#include "lua_rules.hpp"
#include "lua_scene.hpp"
#include "lua_section_args.hpp"
#include "ply_openmesh.hpp"

namespace tendril::lua {

namespace {

using command::Value;

// The file named by the argument at idx (its position in the call: arg).
ImportedMesh read_mesh(lua_State* L, int idx, int arg, const char* fn) {
  if (lua_type(L, idx) != LUA_TSTRING) arg_error(fn, arg, "expected a file name");
  const char* path = lua_tostring(L, idx);
  try {
    return meshing::import_mesh_file(path);  // binary PLY through OpenMesh
  } catch (const std::exception& e) {
    throw LuaArgError(std::string(fn) + ": " + e.what());
  }
}

void push_index_lists(lua_State* L, const std::vector<std::vector<std::size_t>>& lists) {
  lua_createtable(L, int(lists.size()), 0);
  for (std::size_t k = 0; k < lists.size(); ++k) {
    lua_createtable(L, int(lists[k].size()), 0);
    for (std::size_t i = 0; i < lists[k].size(); ++i) {
      lua_pushinteger(L, lua_Integer(lists[k][i] + 1));
      lua_rawseti(L, -2, lua_Integer(i + 1));
    }
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

// tendril.import(path) -> {vertices = {{x, y, z}, ...}, groups = {{name =,
// lines = {{i, j, ...}, ...}, faces = {...}}, ...}} (1-based indices).
int l_import(lua_State* L) {
  const ImportedMesh mesh = read_mesh(L, 1, 1, "tendril.import");
  lua_createtable(L, 0, 2);
  lua_createtable(L, int(mesh.vertices.size()), 0);
  for (std::size_t k = 0; k < mesh.vertices.size(); ++k) {
    push_vec3(L, mesh.vertices[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "vertices");
  lua_createtable(L, int(mesh.groups.size()), 0);
  for (std::size_t g = 0; g < mesh.groups.size(); ++g) {
    lua_createtable(L, 0, 3);
    lua_pushstring(L, mesh.groups[g].name.c_str());
    lua_setfield(L, -2, "name");
    push_index_lists(L, mesh.groups[g].lines);
    lua_setfield(L, -2, "lines");
    push_index_lists(L, mesh.groups[g].faces);
    lua_setfield(L, -2, "faces");
    lua_rawseti(L, -2, lua_Integer(g + 1));
  }
  lua_setfield(L, -2, "groups");
  return 1;
}

// What a group becomes: its kind and section.
struct Mapping {
  std::string kind;  // "beam", "cable", "bar", "patch" or "skip"
  Section section;
  bool given = false;
};

// The mapping {kind =, EA =, ...} on top of the stack (popped).
Mapping read_mapping(lua_State* L, const std::string& where) {
  const std::string fn = "import: " + where;
  Mapping m;
  const int t = lua_gettop(L);
  try {
    if (!lua_istable(L, t)) throw LuaArgError(fn + " must be a table {kind =, ...}");
    check_keys(L, t, fn.c_str(), {"kind", "EA", "EI", "E", "A", "I", "prestress", "line_mass"});
    m.kind = field_string(L, t, "kind", fn.c_str(), "");
    if (m.kind != "beam" && m.kind != "cable" && m.kind != "bar" && m.kind != "patch" && m.kind != "skip")
      key_error(fn.c_str(), "kind", "must be \"beam\", \"cable\", \"bar\", \"patch\" or \"skip\", got \"" + m.kind + "\"");
    if (m.kind != "skip") m.section = read_section(L, t, fn.c_str(), m.kind == "beam");
    m.given = true;
  } catch (...) {
    lua_settop(L, t - 1);
    throw;
  }
  lua_settop(L, t - 1);
  return m;
}

// m:import(path, {lines = {...}, faces = {...}, groups = {[name] = {...}}})
int l_model_import(lua_State* L) {
  const char* fn = "import";
  Scene& s = check_scene(L, fn);
  command::Entry entry(s.session, fn, describe_args(L, 2, lua_gettop(L)));
  const ImportedMesh mesh = read_mesh(L, 2, 1, fn);
  if (!lua_isnoneornil(L, 3)) check_table(L, 3, fn);
  if (!lua_isnoneornil(L, 3)) check_keys(L, 3, fn, {"lines", "faces", "groups"});
  auto default_mapping = [&](const char* key) {
    Mapping m;
    if (lua_isnoneornil(L, 3)) return m;
    lua_getfield(L, 3, key);
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      return m;
    }
    return read_mapping(L, std::string("'") + key + "'");
  };
  const Mapping lines = default_mapping("lines"), faces = default_mapping("faces");
  std::vector<std::pair<Mapping, Mapping>> by_group;  // (for its lines, for its faces)
  for (const ImportedGroup& g : mesh.groups) {
    Mapping own;
    if (!lua_isnoneornil(L, 3)) {
      lua_getfield(L, 3, "groups");
      if (!lua_isnil(L, -1)) {
        if (!lua_istable(L, -1)) {
          lua_pop(L, 1);
          key_error(fn, "groups", "must be a table {[name] = {kind =, ...}}");
        }
        lua_getfield(L, -1, g.name.c_str());
        if (!lua_isnil(L, -1)) own = read_mapping(L, "group '" + g.name + "'");
        else lua_pop(L, 1);
      }
      lua_pop(L, 1);
    }
    const Mapping& for_lines = own.given ? own : lines;
    const Mapping& for_faces = own.given ? own : faces;
    if (!g.lines.empty() && !for_lines.given)
      throw LuaArgError("import: group '" + g.name + "' has polylines: map them with 'lines' or 'groups'");
    if (!g.faces.empty() && !for_faces.given)
      throw LuaArgError("import: group '" + g.name + "' has faces: map them with 'faces' or 'groups'");
    if (!g.lines.empty() && for_lines.kind == "patch")
      throw LuaArgError("import: group '" + g.name + "' has polylines: they become a beam, cables, bars or are skipped");
    if (!g.faces.empty() && for_faces.kind != "patch" && for_faces.kind != "skip")
      throw LuaArgError("import: group '" + g.name + "' has faces: they become a patch or are skipped");
    if (for_faces.kind == "patch")
      for (const auto& f : g.faces)
        if (f.size() != 4)
          throw LuaArgError("import: group '" + g.name + "' has a face of " + std::to_string(f.size()) +
                            " vertices: a patch is made of quads");
    by_group.emplace_back(for_lines, for_faces);
  }

  std::vector<ParticleId> particles;
  std::vector<std::pair<std::string, BlockId>> blocks;  // group name, block, in file order
  all_or_nothing(s, [&] {
    for (const Vec3& x : mesh.vertices) particles.push_back(apply_command(L, s, "particle", {Value::of_vector(x)}, fn).ids[0]);
    for (std::size_t k = 0; k < mesh.groups.size(); ++k) {
      const ImportedGroup& g = mesh.groups[k];
      const Mapping& ml = by_group[k].first;
      for (const auto& line : g.lines) {
        if (ml.kind == "skip") continue;
        if (ml.kind == "beam") {
          const bool closed = line.size() > 3 && line.front() == line.back();  // a ring repeats its first vertex
          std::vector<std::uint32_t> ids;
          for (std::size_t i = 0; i + (closed ? 1 : 0) < line.size(); ++i) ids.push_back(particles[line[i]]);
          command::Args args = {Value::of_id(closed)};
          append_section(args, ml.section);
          args.push_back(Value::of_ids(std::move(ids)));
          blocks.emplace_back(g.name, apply_command(L, s, "beam", std::move(args), fn).ids[0]);
        } else {  // a cable or bar per segment
          for (std::size_t i = 0; i + 1 < line.size(); ++i) {
            command::Args args = {Value::of_id(particles[line[i]]), Value::of_id(particles[line[i + 1]])};
            append_section(args, ml.section);
            args.push_back(Value::of_number(0));  // rest length: as drawn
            blocks.emplace_back(g.name, apply_command(L, s, ml.kind.c_str(), std::move(args), fn).ids[0]);
          }
        }
      }
      const Mapping& mf = by_group[k].second;
      if (g.faces.empty() || mf.kind != "patch") continue;
      command::Args args;
      append_section(args, mf.section);
      std::vector<std::uint32_t> corners;
      for (const auto& f : g.faces)
        for (std::size_t v : f) corners.push_back(particles[v]);
      args.push_back(Value::of_ids(std::move(corners)));
      blocks.emplace_back(g.name, apply_command(L, s, "patch", std::move(args), fn).ids[0]);
    }
  });
  entry.done();

  lua_createtable(L, 0, 3);
  lua_createtable(L, int(particles.size()), 0);
  for (std::size_t k = 0; k < particles.size(); ++k) {
    push_particle(L, s, particles[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "particles");
  lua_createtable(L, int(blocks.size()), 0);
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    push_block(L, s, blocks[k].second);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
  lua_setfield(L, -2, "blocks");
  lua_newtable(L);  // groups: name -> its blocks
  for (const auto& [name, b] : blocks) {
    lua_getfield(L, -1, name.c_str());
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      lua_newtable(L);
      lua_pushvalue(L, -1);
      lua_setfield(L, -3, name.c_str());
    }
    push_block(L, s, b);
    lua_rawseti(L, -2, lua_Integer(lua_rawlen(L, -2) + 1));
    lua_pop(L, 1);
  }
  lua_setfield(L, -2, "groups");
  return 1;
}

}  // namespace

void add_import_function(lua_State* L) { set_fn<l_import>(L, "import"); }
void add_import_methods(lua_State* L) { set_fn<l_model_import>(L, "import"); }

}  // namespace tendril::lua
