#include "command/check.hpp"

#include <cmath>
#include <cstdio>

#include "model/model.hpp"

namespace tendril::command {

namespace {

// "must be > 0", "must be from 1 to 1000", ... or "" when there is no bound.
std::string bounds(const Range& r, bool whole) {
  const bool low = std::isfinite(r.min), high = std::isfinite(r.max);
  const std::string kind = whole ? "a whole number " : "";
  if (low && high) return "must be " + kind + "from " + shown(r.min) + " to " + shown(r.max);
  if (low) return "must be " + kind + (r.above ? "> " : ">= ") + shown(r.min);
  if (high) return "must be " + kind + "<= " + shown(r.max);
  return whole ? "must be a whole number" : "";
}

bool within(const Range& r, double x) { return (r.above ? x > r.min : x >= r.min) && x <= r.max; }

void check_number(const Param& p, std::size_t k, double x) {
  if (!std::isfinite(x)) throw ArgumentError(k, "must be a finite number");
  if (!within(p.range, x)) throw ArgumentError(k, bounds(p.range, false));
}

void check_particle(const Model& m, std::size_t k, std::uint64_t id) {
  if (id > kNone - 1 || !m.particle_valid(ParticleId(id)))
    throw ArgumentError(k, "particle " + std::to_string(id) + " does not exist");
}

}  // namespace

std::string shown(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

void check_args(const Command& c, const Args& a, const Model& m) {
  if (a.size() != c.params.size())
    throw ArgumentError(c.params.size(),
                        "takes " + std::to_string(c.params.size()) + " arguments, got " + std::to_string(a.size()));
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Param& p = c.params[k];
    const Value& v = a[k];
    if (!v.given) {
      if (!p.optional) throw ArgumentError(k, "is required");
      continue;
    }
    switch (p.type) {
      case Type::Particle: check_particle(m, k, v.id); break;
      case Type::Block:
        if (v.id > kNone - 1 || !m.block_valid(BlockId(v.id)))
          throw ArgumentError(k, "block " + std::to_string(v.id) + " does not exist");
        break;
      case Type::Goal:
        if (v.id >= m.goals.size()) throw ArgumentError(k, "goal " + std::to_string(v.id) + " does not exist");
        break;
      case Type::Joint:
        if (v.id >= m.joints.size()) throw ArgumentError(k, "joint " + std::to_string(v.id) + " does not exist");
        break;
      case Type::Count:
        if (!within(p.range, double(v.id)) || v.id > (1ull << 53)) throw ArgumentError(k, bounds(p.range, true));
        break;
      case Type::Flag:
        if (v.id > 1) throw ArgumentError(k, "must be 0 or 1");
        break;
      case Type::Number: check_number(p, k, v.number); break;
      case Type::Vector:
        for (int i = 0; i < 3; ++i) check_number(p, k, v.vector[i]);
        break;
      case Type::Word:
        if (!p.choices.empty()) {
          bool known = false;
          std::string all;
          for (const char* choice : p.choices) {
            known |= v.word == choice;
            all += std::string(all.empty() ? "" : ", ") + "\"" + choice + "\"";
          }
          if (!known) throw ArgumentError(k, "must be one of " + all + ", got \"" + v.word + "\"");
        } else if (v.word.empty() || v.word.find_first_of(" \t\r\n") != std::string::npos) {
          throw ArgumentError(k, "must be one word");
        }
        break;
      case Type::Particles:
        for (std::uint32_t id : v.ids) check_particle(m, k, id);
        break;
      case Type::Path:
        if (v.word.empty() || v.word.find_first_of("\r\n") != std::string::npos)
          throw ArgumentError(k, "must be a file name on one line");
        break;
    }
  }
}

std::string describe(const Command& c, const ArgumentError& e) {
  const std::string param = e.param < c.params.size() ? std::string(" '") + c.params[e.param].name + "'" : "";
  return std::string(c.name) + ":" + param + " " + e.what();
}

}  // namespace tendril::command
