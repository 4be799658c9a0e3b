#include "lua_host.hpp"

#include <lua.hpp>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <optional>

#include "io/file_policy.hpp"
#include "lua_model.hpp"
#include "lua_params.hpp"
#include "lua_sandbox.hpp"
#include "lua_scene.hpp"

namespace tendril {

namespace lua {
extern const char* const kRuleLibrary;  // rule_library.cpp, generated
}

namespace {
int traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  if (!msg) msg = luaL_tolstring(L, 1, nullptr);
  luaL_traceback(L, L, msg, 1);
  return 1;
}
}  // namespace

int run_scene(const std::string& path, const SceneOptions& given, std::string* error, SceneReport* report) {
  // --sandbox: the scene's own allocator, hook and libraries, its files in
  // its folders, and its time checked after every solver step too.
  std::optional<lua::Sandbox> sandbox;
  std::optional<ScopedFilePolicy> files;
  SceneOptions options = given;
  if (options.sandbox) {
    sandbox.emplace(options.limits);
    const auto scene_folder = std::filesystem::absolute(path).parent_path();
    files.emplace(FilePolicy{{options.out_dir}, {scene_folder}});
    options.after_step = [&sandbox, inner = given.after_step](lua_State* L) {
      sandbox->check_time();
      return inner ? inner(L) : false;
    };
  }
  SceneReport own_report;
  if (!report) report = &own_report;
  *report = SceneReport{};
  lua::g_report = report;
  auto fail = [&](const char* message) {
    // A --param the scene does not take is the caller's mistake, not the
    // scene's: the message alone, without the scene's traceback.
    const bool usage = !report->usage_error.empty();
    if (usage) message = report->usage_error.c_str();
    // Lua says "not enough memory" when the sandbox's allocator refused.
    if (sandbox && !sandbox->stopped().empty() && std::strcmp(message ? message : "", "not enough memory") == 0)
      message = sandbox->stopped().c_str();
    if (error) *error = message;
    else std::fprintf(stderr, "tendril: %s%s\n", usage ? "" : "error: ", message);
    return usage ? 2 : 1;
  };
  std::unique_ptr<lua_State, decltype(&lua_close)> state(sandbox ? sandbox->new_state() : luaL_newstate(), &lua_close);
  lua_State* L = state.get();
  if (!L) return fail("cannot create a Lua state");
  luaL_openlibs(L);
  if (sandbox) lua::Sandbox::restrict_libraries(L);
  // Deterministic: the scene's random numbers depend on --seed only.
  lua_getglobal(L, "math");
  lua_getfield(L, -1, "randomseed");
  lua_pushinteger(L, options.seed);
  lua_call(L, 1, 0);
  lua_pop(L, 1);
  lua::open_tendril(L, options);
  lua_setglobal(L, "tendril");
  if (luaL_loadbuffer(L, lua::kRuleLibrary, std::strlen(lua::kRuleLibrary), "=rules/library.lua") != LUA_OK ||
      lua_pcall(L, 0, 0, 0) != LUA_OK)
    return fail(lua_tostring(L, -1));
  for (const auto& [name, source] : options.preload)
    if (luaL_loadbuffer(L, source.data(), source.size(), ("=" + name).c_str()) != LUA_OK || lua_pcall(L, 0, 0, 0) != LUA_OK)
      return fail(lua_tostring(L, -1));

  // The scene's own modules: require("lib.name") finds lib/name.lua beside it.
  const std::string dir = std::filesystem::path(path).parent_path().string();
  // (--sandbox has no package library: nothing to extend there.)
  if (lua_getglobal(L, "package") == LUA_TTABLE) {
    lua_pushstring(L, ((dir.empty() ? std::string(".") : dir) + "/?.lua;").c_str());
    lua_getfield(L, -2, "path");
    lua_concat(L, 2);
    lua_setfield(L, -2, "path");
  }
  lua_pop(L, 1);

  lua_pushcfunction(L, traceback);
  if (luaL_loadfile(L, path.c_str()) != LUA_OK) return fail(lua_tostring(L, -1));
  if (lua_pcall(L, 0, 0, -2) != LUA_OK) {
    if (options.declarations_only && report->stepped) return 0;
    return fail(lua_tostring(L, -1));
  }
  if (!report->stepped) report->usage_error = lua::undeclared_param(options, *report);
  if (!report->usage_error.empty()) return fail("");
  if (options.after_scene) {
    lua_settop(L, 0);
    options.after_scene(L);
  }
  return 0;
}

}  // namespace tendril
