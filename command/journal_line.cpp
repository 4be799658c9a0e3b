#include "command/journal_line.hpp"

#include <cstdlib>

#include "io/trace.hpp"

namespace tendril::command {

namespace {

void append(std::string& line, const Param& p, const Value& v) {
  switch (p.type) {
    case Type::Particle: case Type::Block: case Type::Goal: case Type::Joint: case Type::Count: case Type::Flag:
      line += " " + std::to_string(v.id);
      break;
    case Type::Number: line += " " + Trace::number(v.number); break;
    case Type::Vector: line += " " + Trace::vec(v.vector); break;
    case Type::Word: case Type::Path: line += " " + v.word; break;
    case Type::Particles:
      for (std::uint32_t id : v.ids) line += " " + std::to_string(id);
      break;
  }
}

double number_of(const std::string& w, std::size_t k) {
  char* end = nullptr;
  const double x = std::strtod(w.c_str(), &end);
  if (w.empty() || end == w.c_str() || *end) throw ArgumentError(k, "'" + w + "' is not a number");
  return x;
}

// Ids and counts: whole numbers (written in decimal; "%a" and 1e3 read too).
std::uint64_t whole_of(const std::string& w, std::size_t k) {
  const double x = number_of(w, k);
  if (!(x >= 0 && x <= 9007199254740992.0) || x != std::uint64_t(x)) throw ArgumentError(k, "'" + w + "' is not a whole number");
  return std::uint64_t(x);
}

std::string word(std::istringstream& in, std::size_t k) {
  std::string w;
  if (!(in >> w)) throw ArgumentError(k, "is missing: the line ends too early");
  return w;
}

Value read(const Param& p, std::size_t k, std::istringstream& in) {
  switch (p.type) {
    case Type::Particle: case Type::Block: case Type::Goal: case Type::Joint: case Type::Count: case Type::Flag:
      return Value::of_id(whole_of(word(in, k), k));
    case Type::Number: return Value::of_number(number_of(word(in, k), k));
    case Type::Vector: {
      Vec3 x;
      for (int i = 0; i < 3; ++i) x[i] = number_of(word(in, k), k);
      return Value::of_vector(x);
    }
    case Type::Word: return Value::of_word(word(in, k));
    case Type::Path: {
      std::string rest;
      std::getline(in >> std::ws, rest);
      return Value::of_word(rest);
    }
    case Type::Particles: {
      std::vector<std::uint32_t> ids;
      for (std::string w; in >> w;) {
        const std::uint64_t id = whole_of(w, k);
        if (id >= kNone) throw ArgumentError(k, "'" + w + "' is not a particle id");
        ids.push_back(std::uint32_t(id));
      }
      return Value::of_ids(std::move(ids));
    }
  }
  return {};
}

Args decode_keyed(const Command& c, std::istringstream& in) {
  Args a(c.params.size(), Value::absent());
  for (std::string kv; in >> kv;) {
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw ArgumentError(c.params.size(), "expected key=value, got '" + kv + "'");
    const std::size_t k = c.param_index(kv.substr(0, eq));
    if (k == c.params.size()) throw ArgumentError(k, "unknown key '" + kv.substr(0, eq) + "'");
    std::istringstream value(kv.substr(eq + 1));
    a[k] = read(c.params[k], k, value);
  }
  return a;
}

}  // namespace

std::string encode(const Command& c, const Args& a) {
  std::string line = c.name;
  for (std::size_t k = 0; k < c.params.size(); ++k) {
    if (!a[k].given) continue;
    if (c.keyed) {
      std::string value;
      append(value, c.params[k], a[k]);
      line += " " + std::string(c.params[k].name) + "=" + value.substr(1);
    } else {
      append(line, c.params[k], a[k]);
    }
  }
  return line;
}

Args decode(const Command& c, std::istringstream& in) {
  if (c.keyed) return decode_keyed(c, in);
  Args a(c.params.size(), Value::absent());
  for (std::size_t k = 0; k < c.params.size(); ++k) {
    const Param& p = c.params[k];
    if (p.optional && c.on_line && !c.on_line(a, k)) continue;
    a[k] = read(p, k, in);
  }
  std::string extra;
  if (in >> extra) throw ArgumentError(c.params.size(), "unexpected '" + extra + "' at the end of the line");
  return a;
}

}  // namespace tendril::command
