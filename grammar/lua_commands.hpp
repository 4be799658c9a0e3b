#pragma once
// The Lua side of the command layer (command/): one generic binding reads a
// command's declaration to check Lua's arguments, apply it through the
// scene's session and push what it returns. The methods that take Lua
// shapes of their own (option tables, axes strings, degrees) build Args
// and call apply_command.
#include <lua.hpp>

#include <functional>

#include "command/session.hpp"
#include "lua_scene.hpp"

namespace tendril::lua {

// Sets m:NAME for every command with a Lua method of its own on the table
// on top of the stack (lua_model.cpp overrides those that take Lua shapes).
void add_command_methods(lua_State* L);

// Applies c through the scene's session (journaled). A production's
// journal entry describes the Lua arguments from `first_arg` on (0: the
// journal line's words). A refused argument raises "fn: 'param' why", or
// "fn: argument N: why" when the parameters are the Lua arguments from
// `first_arg` on, in order (`positional`).
command::Result apply_command(lua_State* L, Scene& s, const command::Command& c, command::Args args, const char* fn,
                              int first_arg = 0, bool positional = false);
command::Result apply_command(lua_State* L, Scene& s, const char* name, command::Args args, const char* fn,
                              int first_arg = 0);
// Runs f (which applies commands) as a whole: when it throws outside a
// rule's transaction, the model and the trace are as before (inside one,
// the rule's rollback does it).
void all_or_nothing(Scene& s, const std::function<void()>& f);
// Records a command a composite operation (meshing, multi-resolution) did.
void record_command(Scene& s, const char* name, const command::Args& args);

// Records the patch a composite operation made from these quads.
void record_patch_command(Scene& s, const Section& sec, const std::vector<Model::Quad>& quads);

// Pushes a result as Lua values; returns how many.
int push_result(lua_State* L, Scene& s, const command::Result& r);

}  // namespace tendril::lua
