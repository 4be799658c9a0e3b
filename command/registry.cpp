#include "command/registry.hpp"

#include <stdexcept>
#include <string>

#include "command/declare.hpp"

namespace tendril::command {

const std::vector<Command>& commands() {
  static const std::vector<Command> all = [] {
    std::vector<Command> out;
    declare_topology(out);
    declare_members(out);
    declare_particle_settings(out);
    declare_goals(out);
    declare_solver(out);
    return out;
  }();
  return all;
}

const Command* find(std::string_view name) {
  for (const Command& c : commands())
    if (name == c.name) return &c;
  return nullptr;
}

const Command& get(std::string_view name) {
  if (const Command* c = find(name)) return *c;
  throw std::logic_error("no command '" + std::string(name) + "'");
}

std::size_t Command::param_index(const std::string& param) const {
  for (std::size_t k = 0; k < params.size(); ++k)
    if (param == params[k].name) return k;
  return params.size();
}

const char* type_name(Type t) {
  switch (t) {
    case Type::Particle: return "particle";
    case Type::Block: return "block";
    case Type::Goal: return "goal";
    case Type::Joint: return "joint";
    case Type::Count: return "count";
    case Type::Flag: return "flag";
    case Type::Number: return "number";
    case Type::Vector: return "vector";
    case Type::Word: return "word";
    case Type::Particles: return "particles";
    case Type::Path: return "path";
  }
  return "?";
}

}  // namespace tendril::command
