#include "lua_files.hpp"

#include <string_view>

#include "io/atomic_file.hpp"
#include "io/ccx.hpp"
#include "lua_args.hpp"

namespace tendril::lua {

namespace {

// tendril.write_file(path, text): the whole text or nothing (io/atomic_file.hpp).
int l_write_file(lua_State* L) {
  const char* fn = "tendril.write_file";
  if (lua_type(L, 1) != LUA_TSTRING) arg_error(fn, 1, "expected a file name");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error(fn, 2, "expected the text to write (a string)");
  std::size_t size = 0;
  const char* text = lua_tolstring(L, 2, &size);
  write_file_atomically(lua_tostring(L, 1), std::string_view(text, size));
  return 0;
}

// tendril.ccx_displacements(dat) -> {[id] = {ux, uy, uz}}: the last nodal
// displacements of a ccx .dat file, keyed by node - 1 (the particle id of a
// deck m:export_ccx wrote).
int l_ccx_displacements(lua_State* L) {
  const char* fn = "tendril.ccx_displacements";
  if (lua_type(L, 1) != LUA_TSTRING) arg_error(fn, 1, "expected the name of a ccx .dat file");
  const std::vector<CcxDisplacement> us = read_ccx_displacements(lua_tostring(L, 1));
  lua_createtable(L, 0, static_cast<int>(us.size()));
  for (const CcxDisplacement& u : us) {
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
      lua_pushnumber(L, u.u[k]);
      lua_rawseti(L, -2, k + 1);
    }
    lua_rawseti(L, -2, u.node - 1);
  }
  return 1;
}

}  // namespace

void add_file_functions(lua_State* L) {
  set_fn<l_write_file>(L, "write_file");
  set_fn<l_ccx_displacements>(L, "ccx_displacements");
}

}  // namespace tendril::lua
