#pragma once
// Applying commands to a model: every caller — a Lua scene, a journal
// replay, the studio's messages, a C++ test — goes through apply(), so every
// change is checked the same way, recorded in the replayable trace and, for
// productions, in the journal (the assembly sequence).
#include <string>
#include <string_view>

#include "command/command.hpp"
#include "io/trace.hpp"
#include "model/journal.hpp"

namespace tendril::command {

struct Session {
  Model& model;
  Solver& solver;
  Trace* trace = nullptr;      // nullptr: nothing recorded (a replay)
  Journal* journal = nullptr;  // nullptr: no assembly sequence
};

// A refused argument: the command, the parameter, the message
// "name: 'param' why".
struct CommandError : ModelError {
  CommandError(const Command& c, std::size_t param, const std::string& message, const std::string& why)
      : ModelError(message), command(&c), param(param), why(why) {}
  const Command* command;
  std::size_t param;  // c.params.size(): the call as a whole
  std::string why;    // the message without command and parameter
};

// Checks the arguments, runs the model call and records the line. A refused
// argument throws CommandError before anything changed; a model call that
// fails throws its ModelError and records nothing. `description` is the
// journal entry's arguments as the caller wrote them (Lua: its values);
// default: the journal line's words.
Result apply(Session& s, const Command& c, Args args, const std::string& description = {});
Result apply(Session& s, std::string_view name, Args args, const std::string& description = {});

// Records a command that a composite operation (meshing, multi-resolution)
// has already carried out: its journal line only (not checked against the
// model: the particles a removal names are gone by now).
void record(Session& s, const Command& c, const Args& args);
void record(Session& s, std::string_view name, const Args& args);

// A journal entry that gathers the commands applied while it lives (a Lua
// beam from points: its particles, the beam, its formulation) as one
// production. Inside a rule's transaction it does nothing: the rule is the entry.
class Entry {
 public:
  Entry(Session& s, std::string name, std::string description);
  ~Entry();
  void done() { done_ = true; }  // keep it (an entry whose work failed is dropped)
  void describe(std::string args) { entry_.args = std::move(args); }
  Entry(const Entry&) = delete;
  Entry& operator=(const Entry&) = delete;

 private:
  Session& session_;
  bool owner_;
  bool done_ = false;
  JournalEntry entry_;
};

}  // namespace tendril::command
