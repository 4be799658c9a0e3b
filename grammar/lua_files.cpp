#include "lua_files.hpp"

#include <string_view>

#include "io/atomic_file.hpp"
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

}  // namespace

void add_file_functions(lua_State* L) { set_fn<l_write_file>(L, "write_file"); }

}  // namespace tendril::lua
