#pragma once
// Graph-grammar rules in Lua (thesis 4.2.7, DESIGN principle 2): a rule has a
// name, an axiom and a production; applying it runs a transaction that is
// validated, journaled, or rolled back exactly. Triggers apply rules between
// solver steps.
#include <lua.hpp>

#include <string>

#include "lua_scene.hpp"

namespace tendril::lua {

// Adds tendril.rule to the table on top of the stack.
void add_rule_constructor(lua_State* L);
// Adds apply, trigger, journal, assembly and save_journal to the methods
// table on top of the stack.
void add_rule_methods(lua_State* L);

// A readable list of the Lua values at [first, last], for the journal.
std::string describe_args(lua_State* L, int first, int last);

// Runs the scene's triggers after a solver step; returns true when a rule
// changed the model. The model userdata must be at stack index 1.
bool fire_triggers(lua_State* L, Scene& s, bool converged);

// Whether every trigger fires on equilibrium alone (none counts steps or
// watches the motion), so that a run may take the static Newton solver's
// steps between them (integrator "auto").
bool triggers_only_at_equilibrium(const Scene& s);

// Whether every `every = N` trigger that may still apply was due at a step
// >= `since` (the step the model came to rest): a run ends at equilibrium
// only once each has had its turn there, so a rule every N steps also fires
// on a model that starts at rest.
bool every_triggers_had_their_turn(const Scene& s, std::uint64_t since);

}  // namespace tendril::lua
