#include "lua_rules.hpp"

#include <cstdio>
#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "io/atomic_file.hpp"
#include "lua_args.hpp"
#include "lua_sandbox.hpp"

namespace tendril::lua {

struct Trigger {
  int rule_ref = LUA_NOREF;
  int select_ref = LUA_NOREF;  // fn(m) -> list of argument lists
  int when_ref = LUA_NOREF;    // fn(m) -> boolean
  std::int64_t every = 0;      // steps
  bool on_equilibrium = false;
  std::int64_t max = -1;       // applications, -1: unlimited
  std::int64_t applied = 0;
  int failures = 0;  // in a row
  std::uint64_t last_due = 0;  // the step an `every` trigger was last due at
};

namespace {

const char* const kRuleMeta = "tendril.Rule";
// The most values one application of a rule is given (a select list).
constexpr int kMaxRuleArguments = 100000;


int traceback(lua_State* L) {
  const char* msg = lua_tostring(L, 1);
  luaL_traceback(L, L, msg ? msg : "(error object is not a string)", 1);
  return 1;
}

std::string rule_name(lua_State* L, int idx) {
  lua_getfield(L, idx, "name");
  std::string name = lua_tostring(L, -1) ? lua_tostring(L, -1) : "?";
  lua_pop(L, 1);
  return name;
}

// Calls fn(m, args...) protected; returns "" or the error with traceback.
// Leaves `nresults` values on the stack on success.
std::string call(lua_State* L, int fn_idx, int first_arg, int nargs, int nresults) {
  fn_idx = lua_absindex(L, fn_idx);
  first_arg = lua_absindex(L, first_arg);
  // The handler, the function, the model and a copy of every argument.
  if (!lua_checkstack(L, nargs + 3)) return "too many arguments (" + std::to_string(nargs) + ") for Lua's stack";
  lua_pushcfunction(L, traceback);
  const int handler = lua_gettop(L);
  lua_pushvalue(L, fn_idx);
  lua_pushvalue(L, 1);  // the model
  for (int k = 0; k < nargs; ++k) lua_pushvalue(L, first_arg + k);
  if (lua_pcall(L, nargs + 1, nresults, handler) != LUA_OK) {
    std::string msg = lua_tostring(L, -1) ? lua_tostring(L, -1) : "error";
    lua_pop(L, 2);
    return msg;
  }
  lua_remove(L, handler);
  return {};
}

struct Outcome {
  bool applied = false;
  std::string message;
  int results = 0;  // values the production returned, left on the stack
  bool changed = false;  // the production changed the model (not just ran)
};

// The transaction around one rule application (DESIGN principle 2).
Outcome apply_rule(lua_State* L, Scene& s, int rule_idx, int first_arg, int nargs) {
  const Sandbox::Production budget(L);  // --sandbox: the application's instruction limit
  rule_idx = lua_absindex(L, rule_idx);
  first_arg = lua_absindex(L, first_arg);
  const std::string name = rule_name(L, rule_idx);
  Model& m = s.model;
  if (m.in_transaction()) {
    // A rule applied from inside another rule's production joins its
    // transaction: any failure rolls back the outer application as a whole.
    lua_getfield(L, rule_idx, "production");
    const int base = lua_gettop(L);
    std::string err = call(L, base, first_arg, nargs, LUA_MULTRET);
    if (!err.empty()) {
      lua_pop(L, 1);
      throw LuaArgError("rule '" + name + "' failed: " + err);
    }
    lua_remove(L, base);
    return {true, "", lua_gettop(L) - base + 1, true};
  }
  JournalEntry entry;
  entry.step = s.solver.steps();
  entry.time = s.solver.time();
  entry.rule = name;
  entry.args = describe_args(L, first_arg, first_arg + nargs - 1);
  const Trace::Mark mark = s.trace.mark();
  m.begin_transaction();
  m.changes = &entry.changes;
  auto abandon = [&](std::string message) {
    m.rollback_transaction();
    s.trace.rewind(mark);
    m.changes = nullptr;
    return Outcome{false, std::move(message)};
  };
  lua_getfield(L, rule_idx, "axiom");
  if (!lua_isnil(L, -1)) {
    std::string err = call(L, -1, first_arg, nargs, 2);
    if (!err.empty()) {
      lua_pop(L, 1);
      return abandon("rule '" + name + "': the axiom failed: " + err);
    }
    const bool holds = lua_toboolean(L, -2);
    std::string reason = lua_tostring(L, -1) ? lua_tostring(L, -1) : "the axiom does not hold";
    lua_pop(L, 3);
    if (!holds) return abandon("rule '" + name + "' is not applicable: " + reason);
  } else {
    lua_pop(L, 1);
  }
  lua_getfield(L, rule_idx, "production");
  const int base = lua_gettop(L);
  std::string err = call(L, base, first_arg, nargs, LUA_MULTRET);
  if (!err.empty()) {
    lua_pop(L, 1);
    return abandon("rule '" + name + "' failed and was rolled back: " + err);
  }
  lua_remove(L, base);
  const int results = lua_gettop(L) - base + 1;
  // Validate around what the production created and what it was given.
  std::vector<ParticleId> near = entry.changes.created_particles;
  for (int k = 0; k < nargs; ++k) {
    auto* h = static_cast<Handle*>(luaL_testudata(L, first_arg + k, kParticleMeta));
    if (h) near.push_back(h->id);
  }
  if (std::string broken = m.check_near(near); !broken.empty()) {
    lua_pop(L, results);
    return abandon("rule '" + name + "' broke an invariant and was rolled back: " + broken);
  }
  m.commit_transaction();
  m.changes = nullptr;
  const bool changed = !entry.changes.empty() || s.trace.mark().lines != mark.lines;
  if (changed) s.journal.entries.push_back(std::move(entry));  // an application that changed nothing is no production
  return {true, "", results, changed};
}

// --- tendril.rule{name =, axiom =, production =} --------------------------------

int l_rule(lua_State* L) {
  const char* fn = "tendril.rule";
  check_table(L, 1, fn);
  check_keys(L, 1, fn, {"name", "axiom", "production"});
  if (field_string(L, 1, "name", fn, "").empty()) key_error(fn, "name", "is required (a string naming the rule)");
  lua_getfield(L, 1, "production");
  const bool prod = lua_isfunction(L, -1);
  lua_getfield(L, 1, "axiom");
  const bool axiom_ok = lua_isnil(L, -1) || lua_isfunction(L, -1);
  lua_pop(L, 2);
  if (!prod) key_error(fn, "production", "is required (a function(m, ...))");
  if (!axiom_ok) key_error(fn, "axiom", "must be a function(m, ...) returning true or false, reason");
  lua_createtable(L, 0, 3);
  for (const char* k : {"name", "axiom", "production"}) {
    lua_getfield(L, 1, k);
    lua_setfield(L, -2, k);
  }
  luaL_setmetatable(L, kRuleMeta);
  return 1;
}

void check_rule(lua_State* L, int idx, const char* fn) {
  bool ok = false;
  if (lua_istable(L, idx) && lua_getmetatable(L, idx)) {
    luaL_getmetatable(L, kRuleMeta);
    ok = lua_rawequal(L, -1, -2);
    lua_pop(L, 2);
  }
  if (!ok) arg_error(fn, idx, "expected a rule made by tendril.rule{...}");
}

// --- m:apply(rule, ...) -> true | false, message ----------------------------------

int l_apply(lua_State* L) {
  Scene& s = check_scene(L, "apply");
  check_rule(L, 2, "apply");
  Outcome out = apply_rule(L, s, 2, 3, lua_gettop(L) - 2);
  if (out.applied) {  // true, then what the production returned
    lua_pushboolean(L, 1);
    lua_insert(L, -out.results - 1);
    return out.results + 1;
  }
  lua_pushboolean(L, 0);
  lua_pushstring(L, out.message.c_str());
  return 2;
}

// --- m:trigger{rule =, every = | on = "equilibrium" | when =, select =, max =} ---

int l_trigger(lua_State* L) {
  const char* fn = "trigger";
  Scene& s = check_scene(L, fn);
  check_table(L, 2, fn);
  check_keys(L, 2, fn, {"rule", "every", "on", "when", "select", "max"});
  lua_getfield(L, 2, "rule");
  check_rule(L, lua_gettop(L), fn);
  auto t = std::make_unique<Trigger>();
  t->rule_ref = luaL_ref(L, LUA_REGISTRYINDEX);
  // Whole numbers up to 2^53 (every double above is whole, and a cast of
  // one beyond 2^63 to an integer is undefined).
  constexpr double kLargestWhole = 9007199254740992.0;
  const double every = field_number(L, 2, "every", fn, 0);
  if (!(every >= 0 && every <= kLargestWhole) || every != std::floor(every))
    key_error(fn, "every", "must be a whole number of steps up to 2^53");
  t->every = std::int64_t(every);
  const std::string on = field_string(L, 2, "on", fn, "");
  if (!on.empty() && on != "equilibrium") key_error(fn, "on", "must be \"equilibrium\"");
  t->on_equilibrium = on == "equilibrium";
  const double max = field_number(L, 2, "max", fn, -1);
  if (max != -1 && (!(max >= 0 && max <= kLargestWhole) || max != std::floor(max)))
    key_error(fn, "max", "must be a whole number of applications from 0 to 2^53");
  t->max = std::int64_t(max);
  for (auto [key, ref] : {std::pair{"when", &t->when_ref}, std::pair{"select", &t->select_ref}}) {
    lua_getfield(L, 2, key);
    if (lua_isnil(L, -1)) {
      lua_pop(L, 1);
      continue;
    }
    if (!lua_isfunction(L, -1)) {
      lua_pop(L, 1);
      key_error(fn, key, "must be a function(m)");
    }
    *ref = luaL_ref(L, LUA_REGISTRYINDEX);
  }
  if ((t->every > 0) + t->on_equilibrium + (t->when_ref != LUA_NOREF) != 1)
    throw LuaArgError("trigger: give exactly one of 'every', 'on' or 'when'");
  s.triggers.push_back(t.release());
  return 0;
}

// --- journal -------------------------------------------------------------------

void push_ids(lua_State* L, const std::vector<std::uint32_t>& ids) {
  lua_createtable(L, int(ids.size()), 0);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    lua_pushinteger(L, ids[k]);
    lua_rawseti(L, -2, lua_Integer(k + 1));
  }
}

int l_journal(lua_State* L) {
  Scene& s = check_scene(L, "journal");
  lua_createtable(L, int(s.journal.entries.size()), 0);
  lua_Integer n = 0;
  for (const JournalEntry& e : s.journal.entries) {
    lua_createtable(L, 0, 8);
    lua_pushinteger(L, lua_Integer(e.step));
    lua_setfield(L, -2, "step");
    lua_pushnumber(L, e.time);
    lua_setfield(L, -2, "time");
    lua_pushstring(L, e.rule.c_str());
    lua_setfield(L, -2, "rule");
    lua_pushstring(L, e.args.c_str());
    lua_setfield(L, -2, "args");
    push_ids(L, e.changes.created_particles);
    lua_setfield(L, -2, "created_particles");
    push_ids(L, e.changes.deleted_particles);
    lua_setfield(L, -2, "deleted_particles");
    push_ids(L, e.changes.created_blocks);
    lua_setfield(L, -2, "created_blocks");
    push_ids(L, e.changes.deleted_blocks);
    lua_setfield(L, -2, "deleted_blocks");
    push_ids(L, e.changes.changed_blocks);
    lua_setfield(L, -2, "changed_blocks");
    lua_rawseti(L, -2, ++n);
  }
  return 1;
}

int l_assembly(lua_State* L) {
  Scene& s = check_scene(L, "assembly");
  lua_pushstring(L, s.journal.assembly_sequence().c_str());
  return 1;
}

int l_save_journal(lua_State* L) {
  Scene& s = check_scene(L, "save_journal");
  if (lua_type(L, 2) != LUA_TSTRING) arg_error("save_journal", 2, "expected a file name");
  // The assembly sequence as comments, then the replayable trace; written
  // whole or not at all, so a full disk is an error and the old journal stays.
  // Format 2: the default integrator is "auto" (format 1: Leapfrog, command/replay.cpp).
  std::string text = "# tendril journal 2: replay with `tendril replay FILE`\n";
  std::istringstream table(s.journal.assembly_sequence());
  for (std::string line; std::getline(table, line);) text += "# " + line + "\n";
  for (const std::string& line : s.trace.lines(s.solver)) text += line + "\n";
  write_file_atomically(lua_tostring(L, 2), text);
  return 0;
}

}  // namespace

Scene::~Scene() {
  for (Trigger* t : triggers) delete t;
}

namespace {

// Tables nested deeper than kDescribeDepth are written "{...}", and values
// after the first kDescribeValues "...": a table that refers to itself (a
// config with a back-reference) recursed for ever, a deep one pushed past
// Lua's stack, and a wide one that refers to itself n^depth times would hang
// (issue 13).
constexpr int kDescribeDepth = 4;
constexpr int kDescribeValues = 256;

std::string describe(lua_State* L, int first, int last, int depth, int& budget) {
  std::string out;
  // Each level holds at most two values (a key and its value) on the stack.
  if (!lua_checkstack(L, 2)) throw std::runtime_error("out of Lua stack describing the arguments");
  for (int k = first; k <= last; ++k) {
    if (budget-- <= 0) {
      out += out.empty() ? "..." : " ...";
      break;
    }
    std::string item;
    if (auto* h = static_cast<Handle*>(luaL_testudata(L, k, kParticleMeta))) item = "p" + std::to_string(h->id);
    else if (auto* b = static_cast<Handle*>(luaL_testudata(L, k, kBlockMeta))) item = "b" + std::to_string(b->id);
    else if (lua_type(L, k) == LUA_TNUMBER || lua_type(L, k) == LUA_TSTRING) {
      item = luaL_tolstring(L, k, nullptr);  // a copy: lua_tostring would turn the argument itself into a string
      lua_pop(L, 1);
    }
    else if (lua_istable(L, k) && depth >= kDescribeDepth) item = "{...}";
    else if (lua_istable(L, k) && lua_rawlen(L, k) > 0) {
      item = "{";
      const lua_Integer n = lua_Integer(lua_rawlen(L, k));
      for (lua_Integer i = 1; i <= n && i <= 8; ++i) {
        lua_rawgeti(L, k, i);
        item += (i > 1 ? " " : "") + describe(L, lua_gettop(L), lua_gettop(L), depth + 1, budget);
        lua_pop(L, 1);
      }
      item += n > 8 ? " ...}" : "}";
    } else if (lua_istable(L, k)) {  // options: name=value, sorted by name
      std::vector<std::string> fields;
      lua_pushnil(L);
      while (lua_next(L, k)) {
        if (lua_type(L, -2) == LUA_TSTRING) {
          std::string key = lua_tostring(L, -2);
          fields.push_back(key + "=" + describe(L, lua_gettop(L), lua_gettop(L), depth + 1, budget));
        }
        lua_pop(L, 1);
      }
      std::sort(fields.begin(), fields.end());
      item = "{";
      for (const std::string& f : fields) item += (item.size() > 1 ? " " : "") + f;
      item += "}";
    } else item = luaL_typename(L, k);
    out += (out.empty() ? "" : " ") + item;
  }
  return out;
}

}  // namespace

std::string describe_args(lua_State* L, int first, int last) {
  int budget = kDescribeValues;
  return describe(L, first, last, 0, budget);
}

bool fire_triggers(lua_State* L, Scene& s, bool converged) {
  bool changed = false;
  // A rule or predicate may register triggers (m:trigger) while these fire:
  // they join at the next step, and the loop runs over a copy that the push
  // cannot invalidate. Triggers are never removed while the scene lives.
  const std::vector<Trigger*> firing = s.triggers;
  for (Trigger* t : firing) {
    if (t->max >= 0 && t->applied >= t->max) continue;
    bool due = false;
    if (t->every > 0) {
      due = s.solver.steps() % std::uint64_t(t->every) == 0;
      if (due) t->last_due = s.solver.steps();
    }
    else if (t->on_equilibrium) due = converged;
    else {
      lua_rawgeti(L, LUA_REGISTRYINDEX, t->when_ref);
      std::string err = call(L, -1, 1, 0, 1);
      if (!err.empty()) {
        lua_pop(L, 1);
        throw LuaArgError("trigger 'when' failed: " + err);
      }
      due = lua_toboolean(L, -1);
      lua_pop(L, 2);
    }
    if (!due) continue;
    lua_rawgeti(L, LUA_REGISTRYINDEX, t->rule_ref);
    const int rule = lua_gettop(L);
    // Argument lists: from select(m), or one application without arguments.
    int lists = 0;
    if (t->select_ref != LUA_NOREF) {
      lua_rawgeti(L, LUA_REGISTRYINDEX, t->select_ref);
      std::string err = call(L, -1, 1, 0, 1);
      if (!err.empty()) {
        lua_settop(L, rule - 1);
        throw LuaArgError("trigger 'select' failed: " + err);
      }
      lua_remove(L, -2);
      if (!lua_istable(L, -1)) {
        lua_settop(L, rule - 1);
        throw LuaArgError("trigger 'select' must return a list of argument lists");
      }
      lists = int(lua_rawlen(L, -1));
    }
    const int selected = lua_gettop(L);
    for (int k = 1; k <= std::max(lists, t->select_ref == LUA_NOREF ? 1 : 0); ++k) {
      if (t->max >= 0 && t->applied >= t->max) break;
      int nargs = 0;
      const int base = lua_gettop(L);
      if (t->select_ref != LUA_NOREF) {
        lua_rawgeti(L, selected, k);
        const int list = lua_gettop(L);
        if (lua_istable(L, list)) {
          const lua_Unsigned n = lua_rawlen(L, list);
          // Lua's stack holds at most LUAI_MAXSTACK (a million) values.
          if (n > lua_Unsigned(kMaxRuleArguments) || !lua_checkstack(L, int(n) + 8)) {
            lua_settop(L, rule - 1);
            throw LuaArgError("trigger 'select': argument list " + std::to_string(k) + " has " + std::to_string(n) +
                              " values, more than a rule takes (" + std::to_string(kMaxRuleArguments) + ")");
          }
          nargs = int(n);
          for (int a = 1; a <= nargs; ++a) lua_rawgeti(L, list, a);
        }
        lua_remove(L, list);
      }
      Outcome out = apply_rule(L, s, rule, base + 1, nargs);
      lua_settop(L, base);
      if (out.applied) {
        ++t->applied;
        t->failures = 0;
        changed |= out.changed;
      } else if (out.message.find("is not applicable") == std::string::npos) {
        // A failing production is reported once; after ten failures in a row
        // the trigger is switched off rather than failing at every step.
        if (t->failures++ == 0) std::fprintf(stderr, "[tendril] %s\n", out.message.c_str());
        if (t->failures >= 10) {
          std::fprintf(stderr, "[tendril] rule '%s' failed 10 times in a row; its trigger is off\n", rule_name(L, rule).c_str());
          t->max = t->applied;
        }
      }
    }
    lua_settop(L, rule - 1);
  }
  return changed;
}

bool triggers_only_at_equilibrium(const Scene& s) {
  for (const Trigger* t : s.triggers)
    if (!t->on_equilibrium) return false;
  return true;
}

bool every_triggers_had_their_turn(const Scene& s, std::uint64_t since) {
  for (const Trigger* t : s.triggers)
    if (t->every > 0 && !(t->max >= 0 && t->applied >= t->max) && t->last_due < since) return false;
  return true;
}

void add_rule_constructor(lua_State* L) {
  luaL_newmetatable(L, kRuleMeta);
  lua_pop(L, 1);
  set_fn<l_rule>(L, "rule");
}

void add_rule_methods(lua_State* L) {
  set_fn<l_apply>(L, "apply");
  set_fn<l_trigger>(L, "trigger");
  set_fn<l_journal>(L, "journal");
  set_fn<l_assembly>(L, "assembly");
  set_fn<l_save_journal>(L, "save_journal");
}

}  // namespace tendril::lua
