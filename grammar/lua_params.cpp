#include "lua_params.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "lua_args.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

namespace {

// A usage error is kept in the report as well, so that run_scene exits with
// 2 and the bare message instead of a traceback.
[[noreturn]] void usage_error(const std::string& message) {
  g_report->usage_error = message;
  throw std::runtime_error(message);
}

std::string as_text(lua_State* L, int idx) {
  if (lua_type(L, idx) == LUA_TNUMBER) {
    char buf[32];
    if (lua_isinteger(L, idx)) std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(lua_tointeger(L, idx)));
    else std::snprintf(buf, sizeof buf, "%.14g", lua_tonumber(L, idx));
    return buf;
  }
  if (lua_isnoneornil(L, idx)) return "nil";
  std::string text = luaL_tolstring(L, idx, nullptr);
  lua_pop(L, 1);
  return text;
}

// tendril.param(name, default): the --param value (a number when the default
// is one, else a string), or the default.
int l_param(lua_State* L) {
  const char* fn = "tendril.param";
  if (lua_type(L, 1) != LUA_TSTRING) arg_error(fn, 1, "expected a parameter name");
  const std::string name = lua_tostring(L, 1);
  lua_settop(L, 2);
  auto& declared = g_report->params;
  if (std::none_of(declared.begin(), declared.end(), [&](const SceneReport::Param& p) { return p.name == name; }))
    declared.push_back({name, as_text(L, 2)});
  for (const auto& [key, value] : g_options->params) {
    if (key != name) continue;
    if (lua_stringtonumber(L, value.c_str()) != 0) return 1;
    if (lua_type(L, 2) == LUA_TNUMBER)
      usage_error("--param " + key + "=" + value + ": not a number, and the scene's default for " + name + " is " +
                  as_text(L, 2));
    lua_pushstring(L, value.c_str());
    return 1;
  }
  return 1;
}

}  // namespace

void add_param(lua_State* L) { set_fn<l_param>(L, "param"); }

void begin_stepping() {
  const bool first = !g_report->stepped;
  g_report->stepped = true;
  if (g_options->declarations_only) throw std::runtime_error("stopped at the first step: the declarations are read");
  if (!first) return;
  const std::string undeclared = undeclared_param(*g_options, *g_report);
  if (!undeclared.empty()) usage_error(undeclared);
}

std::string undeclared_param(const SceneOptions& options, const SceneReport& report) {
  for (const auto& entry : options.params) {
    const std::string& key = entry.first;  // a structured binding, clang 14 (the sanitizer build) cannot capture
    const auto& declared = report.params;
    if (std::any_of(declared.begin(), declared.end(), [&](const SceneReport::Param& p) { return p.name == key; }))
      continue;
    std::string known;
    for (const SceneReport::Param& p : declared) known += (known.empty() ? "" : ", ") + p.name;
    return "--param " + key + ": the scene declares no such parameter (" +
           (known.empty() ? std::string("it declares none") : "it declares " + known) +
           "; tendril.param(name, default) declares one, before the first m:run or m:step)";
  }
  return "";
}

}  // namespace tendril::lua
