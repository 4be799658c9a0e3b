#include "command/json_form.hpp"

#include <cmath>

#include "command/check.hpp"
#include "command/listing.hpp"
#include "command/registry.hpp"
#include "command/session.hpp"

namespace tendril::command {

namespace {

using nlohmann::json;

json value_json(const Param& p, const Value& v) {
  switch (p.type) {
    case Type::Particle: case Type::Block: case Type::Goal: case Type::Joint: case Type::Count: return v.id;
    case Type::Flag: return v.id != 0;
    case Type::Number: return v.number;
    case Type::Vector: return json::array({v.vector.x(), v.vector.y(), v.vector.z()});
    case Type::Word: case Type::Path: return v.word;
    case Type::Particles: return v.ids;
  }
  return nullptr;
}

std::uint64_t whole(const json& j, std::size_t k) {
  if (j.is_number_unsigned()) return j.get<std::uint64_t>();
  if (j.is_number_float()) {
    const double x = j.get<double>();
    if (x >= 0 && x <= 9007199254740992.0 && x == std::floor(x)) return std::uint64_t(x);
  }
  throw ArgumentError(k, "must be a whole number >= 0");
}

double number(const json& j, std::size_t k) {
  if (!j.is_number()) throw ArgumentError(k, "must be a number");
  return j.get<double>();
}

Value value_of(const Param& p, std::size_t k, const json& j) {
  switch (p.type) {
    case Type::Particle: case Type::Block: case Type::Goal: case Type::Joint: case Type::Count:
      return Value::of_id(whole(j, k));
    case Type::Flag:
      if (!j.is_boolean()) throw ArgumentError(k, "must be true or false");
      return Value::of_id(j.get<bool>() ? 1 : 0);
    case Type::Number: return Value::of_number(number(j, k));
    case Type::Vector: {
      if (!j.is_array() || j.size() != 3) throw ArgumentError(k, "must be [x, y, z]");
      return Value::of_vector(Vec3(number(j[0], k), number(j[1], k), number(j[2], k)));
    }
    case Type::Word: case Type::Path:
      if (!j.is_string()) throw ArgumentError(k, "must be a string");
      return Value::of_word(j.get<std::string>());
    case Type::Particles: {
      if (!j.is_array()) throw ArgumentError(k, "must be an array of particle ids");
      std::vector<std::uint32_t> ids;
      for (const json& e : j) {
        const std::uint64_t id = whole(e, k);
        if (id >= kNone) throw ArgumentError(k, "holds " + std::to_string(id) + ", not a particle id");
        ids.push_back(std::uint32_t(id));
      }
      return Value::of_ids(std::move(ids));
    }
  }
  return {};
}

}  // namespace

json to_json(const Command& c, const Args& a) {
  json args = json::object();
  for (std::size_t k = 0; k < c.params.size(); ++k)
    if (a[k].given) args[c.params[k].name] = value_json(c.params[k], a[k]);
  return {{"command", c.name}, {"args", args}};
}

std::pair<const Command*, Args> from_json(const json& message) {
  if (!message.is_object() || !message.contains("command") || !message["command"].is_string())
    throw ModelError("a command message needs \"command\": NAME");
  const std::string name = message["command"].get<std::string>();
  const Command* c = find(name);
  if (!c) throw ModelError("unknown command '" + name + "'");
  Args a(c->params.size(), Value::absent());
  try {
    const json args = message.value("args", json::object());
    if (!args.is_object()) throw ArgumentError(c->params.size(), "\"args\" must be an object");
    for (const auto& [key, j] : args.items()) {
      const std::size_t k = c->param_index(key);
      if (k == c->params.size()) throw ArgumentError(k, "has no argument '" + key + "'");
      a[k] = value_of(c->params[k], k, j);
    }
  } catch (const ArgumentError& e) {
    throw CommandError(*c, e.param, describe(*c, e), e.what());
  }
  return {c, std::move(a)};
}

json result_json(const Result& r) {
  switch (r.kind) {
    case Returns::Nothing: return nullptr;
    case Returns::Particle: case Returns::Block: return r.ids.at(0);
    case Returns::Particles: case Returns::ParticleAndBlock: return r.ids;
    case Returns::Goal: case Returns::Joint: return r.index;
    case Returns::Number: return r.number;
    case Returns::Vector: return json::array({r.vector.x(), r.vector.y(), r.vector.z()});
    case Returns::Flag: return r.flag;
    case Returns::Word: return r.word;
  }
  return nullptr;
}

json declarations_json() {
  json out = json::array();
  for (const Command& c : commands()) {
    json params = json::array();
    for (const Param& p : c.params) {
      json d = {{"name", p.name}, {"type", type_name(p.type)}, {"doc", p.doc}, {"optional", p.optional}};
      if (std::isfinite(p.range.min)) d["min"] = p.range.min, d["above"] = p.range.above;
      if (std::isfinite(p.range.max)) d["max"] = p.range.max;
      if (!p.choices.empty()) d["choices"] = p.choices;
      params.push_back(d);
    }
    out.push_back({{"name", c.name},
                   {"summary", c.summary},
                   {"kind", c.effect == Effect::Topology ? "production" : c.effect == Effect::Setting ? "setting" : "steps"},
                   {"lua", lua_method(c)},
                   {"journal", journal_form(c)},
                   {"params", params}});
  }
  return out;
}

}  // namespace tendril::command
