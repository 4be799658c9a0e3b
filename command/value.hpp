#pragma once
// The typed arguments of a command (command.hpp): one Value per declared
// parameter, in declaration order. A value knows nothing of where it came
// from (Lua, a journal line, a JSON message, C++).
#include <cstdint>
#include <string>
#include <vector>

#include "model/types.hpp"

namespace tendril::command {

enum class Type {
  Particle,   // a live particle id
  Block,      // a live block id
  Goal,       // a goal index (0-based; Lua counts from 1)
  Joint,      // a rotational joint index (0-based; Lua counts from 1)
  Count,      // a whole number (decimal in the journal)
  Flag,       // true or false (1 or 0 in the journal)
  Number,     // a finite real (exact hexadecimal in the journal)
  Vector,     // three finite reals
  Word,       // one of the parameter's choices, or any token without spaces
  Particles,  // a list of live particle ids (the rest of a journal line)
  Path,       // a file name (the rest of a journal line)
};

const char* type_name(Type t);  // "particle", "number", ...

struct Value {
  bool given = true;  // optional parameters and the keys of a keyed command
  std::uint64_t id = 0;  // Particle, Block, Goal, Joint, Count, Flag
  double number = 0;
  Vec3 vector = Vec3::Zero();
  std::string word;               // Word, Path
  std::vector<std::uint32_t> ids;  // Particles

  static Value of_id(std::uint64_t i) { Value v; v.id = i; return v; }
  static Value of_number(double x) { Value v; v.number = x; return v; }
  static Value of_vector(const Vec3& x) { Value v; v.vector = x; return v; }
  static Value of_word(std::string w) { Value v; v.word = std::move(w); return v; }
  static Value of_ids(std::vector<std::uint32_t> ids) { Value v; v.ids = std::move(ids); return v; }
  static Value absent() { Value v; v.given = false; return v; }
};

using Args = std::vector<Value>;

}  // namespace tendril::command
