#include "command/listing.hpp"

#include <cctype>
#include <cmath>
#include <cstdio>

#include "command/check.hpp"
#include "command/registry.hpp"

namespace tendril::command {

namespace {

std::string upper(const char* s) {
  std::string out = s;
  for (char& c : out) c = char(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

const char* effect_name(Effect e) {
  switch (e) {
    case Effect::Topology: return "production";
    case Effect::Setting: return "setting";
    case Effect::Steps: return "solver steps";
  }
  return "?";
}

const char* returns_name(Returns r) {
  switch (r) {
    case Returns::Nothing: return "nothing";
    case Returns::Particle: return "a particle";
    case Returns::Block: return "a block";
    case Returns::Particles: return "a list of particles";
    case Returns::ParticleAndBlock: return "a particle and a block";
    case Returns::Goal: return "a goal";
    case Returns::Joint: return "a joint";
    case Returns::Number: return "a number";
    case Returns::Vector: return "a vector";
    case Returns::Flag: return "true or false";
    case Returns::Word: return "a word";
  }
  return "?";
}

std::string range_text(const Param& p) {
  std::string out;
  if (std::isfinite(p.range.min)) out += (p.range.above ? "> " : ">= ") + shown(p.range.min);
  if (std::isfinite(p.range.max)) out += (out.empty() ? "<= " : ", <= ") + shown(p.range.max);
  for (const char* c : p.choices) out += (out.empty() ? "" : ", ") + std::string("`") + c + "`";
  return out;
}

}  // namespace

std::string journal_form(const Command& c) {
  std::string out = c.name;
  for (const Param& p : c.params) {
    const std::string word = c.keyed ? std::string(p.name) + "=" + upper(type_name(p.type)) : upper(p.name);
    out += " " + (p.optional ? "[" + word + "]" : word);
    if (p.type == Type::Particles) out += "...";
  }
  return out;
}

std::string lua_method(const Command& c) {
  if (c.lua) return *c.lua ? std::string("m:") + c.lua : "";
  return std::string("m:") + c.name;
}

std::string markdown_listing() {
  std::string out =
      "# Commands\n\n"
      "Every operation a scene, a journal, the studio or a C++ caller applies to a model, declared once in\n"
      "`command/` (see docs/architecture.md). This page is generated from the declarations by\n"
      "`tendril commands`; a test fails when it differs.\n\n"
      "A production creates, deletes or reconnects and is an entry of the journal of its own; a setting\n"
      "changes a value. The journal form is the command's line in a saved journal (ids and counts in\n"
      "decimal, numbers exact in `%a`, lists to the end of the line); the JSON form is\n"
      "`{\"command\": NAME, \"args\": {PARAMETER: VALUE, ...}}`.\n";
  for (const Command& c : commands()) {
    out += "\n## " + std::string(c.name) + "\n\n" + c.summary + ".\n\n";
    out += std::string("- kind: ") + effect_name(c.effect) + "\n";
    const std::string lua = lua_method(c);
    out += "- Lua: " + (lua.empty() ? std::string("none (see docs/lua-api.md)") : "`" + lua + "`") + "\n";
    out += "- journal: `" + journal_form(c) + "`\n";
    out += std::string("- returns: ") + returns_name(c.returns) + "\n";
    if (c.query) out += std::string("- without its last argument, returns ") + returns_name(c.query_returns) + "\n";
    out += "\n| parameter | type | meaning | values |\n|---|---|---|---|\n";
    for (const Param& p : c.params)
      out += "| " + std::string(p.name) + (p.optional ? " (optional)" : "") + " | " + type_name(p.type) + " | " + p.doc +
             " | " + range_text(p) + " |\n";
  }
  return out;
}

}  // namespace tendril::command
