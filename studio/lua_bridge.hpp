#pragma once
// The studio's calls into the watched scene: model methods and rules applied
// by name with arguments from the page's JSON, on the solver thread, through
// the same bindings a scene calls (so they are checked, journaled and, for
// rules, run in a transaction exactly as from Lua).
//
// Arguments in JSON: {"particle": id}, {"block": id}, {"particles": [ids]},
// numbers, strings, booleans, lists (Lua sequences, e.g. [x, y, z]) and
// objects (option tables). Results come back the same way.
#include <lua.hpp>

#include <string>

#include <nlohmann/json.hpp>

#include "lua_scene.hpp"

namespace tendril::studio {

using json = nlohmann::json;

struct CallResult {
  bool ok = false;
  std::string message;  // the error, or a refused rule's reason
  json value;           // what the call returned (a list)
};

// The scene behind the model referenced by model_ref (LUA_REGISTRYINDEX).
lua::Scene& scene_of(lua_State* L, int model_ref);
// m:method(args...).
CallResult call_method(lua_State* L, int model_ref, const std::string& method, const json& args);
// m:apply(rule, args...) for a palette key (tendril.studio.rule(key)); a
// rule whose axiom does not hold is not ok, with the axiom's reason.
CallResult apply_rule(lua_State* L, int model_ref, const std::string& key, const json& args);
// What tendril.studio.<function>() returns, as JSON (studio.lua): the
// palette ("palette") and the scene's parameters ("parameters").
json studio_list(lua_State* L, const char* function);

}  // namespace tendril::studio
