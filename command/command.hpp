#pragma once
// One operation on a model, declared once (DESIGN principle 8): its name,
// its typed parameters with their ranges, what it returns and the model
// call. Argument checks, the journal line and its replay, the Lua binding,
// the JSON form and the listing in docs/commands.md are all derived from
// the declaration (registry.cpp holds them all).
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "command/value.hpp"

namespace tendril {
class Model;
class Solver;
}  // namespace tendril

namespace tendril::command {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Bounds of a Number, Vector (each component), or Count parameter.
struct Range {
  double min = -kInf;
  double max = kInf;
  bool above = false;  // min excluded
  const char* unit = "";
};

struct Param {
  const char* name;
  Type type;
  const char* doc;  // what it is, its unit
  Range range = {};
  std::vector<const char*> choices = {};  // a Word's allowed values (empty: any)
  bool optional = false;  // may be absent (its Value not given)
};

// What a command hands back to its caller.
enum class Returns { Nothing, Particle, Block, Particles, ParticleAndBlock, Goal, Joint, Number, Vector, Flag, Word };

struct Result {
  Returns kind = Returns::Nothing;
  std::vector<std::uint32_t> ids;  // Particle, Block, Particles; ParticleAndBlock: {p, b}
  std::size_t index = 0;           // Goal, Joint
  double number = 0;
  Vec3 vector = Vec3::Zero();
  bool flag = false;
  std::string word;
};

// What a command acts on.
struct Target {
  Model& model;
  Solver& solver;
};

enum class Effect {
  Topology,  // a production: creates, deletes or reconnects (a journal entry of its own)
  Setting,   // changes a value of the model or the solver
  Steps,     // advances the solver (journaled as the steps before the next line)
};

// A refused argument: which parameter, and why (without the command's name).
struct ArgumentError : std::runtime_error {
  ArgumentError(std::size_t param, const std::string& why) : std::runtime_error(why), param(param) {}
  std::size_t param;
};

struct Command {
  const char* name;  // also its journal word
  const char* summary;
  Effect effect;
  std::vector<Param> params;
  Returns returns = Returns::Nothing;
  Result (*apply)(Target&, Args&) = nullptr;  // may canonicalise its Args: they are what the journal records
  // A getter for the Lua call without its trailing value (m:mass(p)):
  // called with the leading parameters the getter takes.
  std::size_t query_params = 0;
  Returns query_returns = Returns::Nothing;
  Result (*query)(Target&, const Args&) = nullptr;
  // Journal form KEY=VALUE for every given parameter (settings).
  bool keyed = false;
  // Which optional parameters a journal line carries after the ones read
  // (goal, formulation): given the Args read so far and the index of the
  // next parameter, whether it is on the line. Default: every parameter.
  bool (*on_line)(const Args& so_far, std::size_t next) = nullptr;
  const char* lua = nullptr;  // the Lua method when it differs (set_position), "" for none

  std::size_t param_index(const std::string& name) const;  // params.size() when unknown
};

}  // namespace tendril::command
