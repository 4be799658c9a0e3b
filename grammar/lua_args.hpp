#pragma once
// Argument helpers for the Lua bindings. They throw LuaArgError instead of
// calling lua_error, so no longjmp crosses C++ frames; the guard turns the
// exception into a Lua error at the binding's boundary.
#include <lua.hpp>

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/types.hpp"

namespace tendril::lua {

struct LuaArgError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

[[noreturn]] void arg_error(const char* fn, int arg, const std::string& msg);
[[noreturn]] void key_error(const char* fn, const char* key, const std::string& msg);

double check_number(lua_State* L, int idx, const char* fn);
std::int64_t check_integer(lua_State* L, int idx, const char* fn);
Vec3 check_vec3(lua_State* L, int idx, const char* fn);
void check_table(lua_State* L, int idx, const char* fn);
// Throws when the option table at idx has a key outside `allowed`.
void check_keys(lua_State* L, int idx, const char* fn, std::initializer_list<const char*> allowed);
// Field accessors on the option table at idx; `has_field` pushes nothing.
bool has_field(lua_State* L, int idx, const char* key);
double field_number(lua_State* L, int idx, const char* key, const char* fn, double fallback);
bool field_bool(lua_State* L, int idx, const char* key, const char* fn, bool fallback);
std::string field_string(lua_State* L, int idx, const char* key, const char* fn, const std::string& fallback);
Vec3 field_vec3(lua_State* L, int idx, const char* key, const char* fn);
void push_vec3(lua_State* L, const Vec3& v);

// Runs binding f. Returns its result count, or -1 when it threw: the stack
// then holds only the error message, with the caller's file and line, as a
// Lua string, and the exception is destroyed, so raising it leaks nothing.
// (The guard used to keep the message in a std::string that lua_error
// longjmped over: every refused call leaked it, issue 13.)
int call_binding(lua_State* L, lua_CFunction f) noexcept;

// Wraps a binding so that C++ exceptions become Lua errors with the caller's
// file and line. lua_error longjmps: this frame holds nothing to destroy.
template <lua_CFunction F>
int guarded(lua_State* L) {
  const int results = call_binding(L, F);
  return results >= 0 ? results : lua_error(L);
}

// Sets field `name` of the table on top of the stack to the guarded F.
template <lua_CFunction F>
void set_fn(lua_State* L, const char* name) {
  lua_pushcfunction(L, guarded<F>);
  lua_setfield(L, -2, name);
}

}  // namespace tendril::lua
