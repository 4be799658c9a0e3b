#include "lua_csv.hpp"

#include <string>
#include <vector>

#include "io/csv.hpp"
#include "lua_args.hpp"

namespace tendril::lua {

namespace {

// tendril.csv_line{ v1, v2, ... }: numbers as Lua prints them (%.14g),
// booleans as true/false, the rest as strings.
int l_csv_line(lua_State* L) {
  const char* fn = "tendril.csv_line";
  check_table(L, 1, fn);
  std::vector<std::string> fields;
  const lua_Integer n = luaL_len(L, 1);
  for (lua_Integer k = 1; k <= n; ++k) {
    lua_geti(L, 1, k);
    const int type = lua_type(L, -1);
    if (type != LUA_TSTRING && type != LUA_TNUMBER && type != LUA_TBOOLEAN)
      arg_error(fn, 1, "field " + std::to_string(k) + " is a " + luaL_typename(L, -1) +
                           "; a CSV field is a string, a number or a boolean");
    fields.push_back(luaL_tolstring(L, -1, nullptr));
    lua_pop(L, 2);
  }
  const std::string line = csv_line(fields);
  lua_pushlstring(L, line.data(), line.size());
  return 1;
}

}  // namespace

void add_csv(lua_State* L) { set_fn<l_csv_line>(L, "csv_line"); }

}  // namespace tendril::lua
