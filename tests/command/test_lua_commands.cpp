// The same random commands applied from C++ through the registry and from a
// Lua scene through the generic binding give the same journal and the same
// model, bit for bit.
#include <doctest/doctest.h>

#include <random>
#include <sstream>

#include "command/listing.hpp"
#include "every_command.hpp"
#include "lua_host.hpp"

using namespace tendril;
using namespace tendril::test;

namespace {

// Commands whose Lua method takes their parameters in order (the generic
// binding of grammar/lua_commands.cpp).
const char* const kGeneric[] = {"particle", "delete_particle", "merge", "explode", "explode_from", "delete",
                                "extend", "remove_from_beam", "insert", "split", "remove_from_patch",
                                "merge_patches", "torque", "rest_length", "load", "mass", "passive", "position",
                                "gravity", "goal_weight", "remove_goal"};

std::string lua_value(const command::Param& p, const Value& v) {
  switch (p.type) {
    case command::Type::Particle: return "P[" + std::to_string(v.id) + "]";
    case command::Type::Block: return "B[" + std::to_string(v.id) + "]";
    case command::Type::Goal: return std::to_string(v.id + 1);
    case command::Type::Flag: return v.id ? "true" : "false";
    case command::Type::Number: return "(" + Trace::number(v.number) + ")";
    case command::Type::Vector:
      return "{" + Trace::number(v.vector.x()) + ", " + Trace::number(v.vector.y()) + ", " + Trace::number(v.vector.z()) + "}";
    case command::Type::Particles: {
      std::string out = "{";
      for (std::uint32_t id : v.ids) out += "P[" + std::to_string(id) + "], ";
      return out + "}";
    }
    default: FAIL("no Lua form for " << command::type_name(p.type)); return "";
  }
}

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("random commands from C++ and from Lua: the same journal and model") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-lua-commands";
  std::filesystem::create_directories(dir);
  {
    Recorded start;
    apply_every_command(start, dir / "every-base.xml");
    save_model_xml(start.model, start.solver.settings, (dir / "start.xml").string());
  }
  Recorded r;
  r.run("open", {word((dir / "start.xml").string().c_str())});
  std::string scene = "local m = tendril.load('" + (dir / "start.xml").string() + "')\n"
                      "local P, B = {}, {}\n"
                      "local function refresh()\n"
                      "  for _, p in ipairs(m:particles()) do P[p.id] = p end\n"
                      "  for _, b in ipairs(m:blocks()) do B[b.id] = b end\n"
                      "end\nrefresh()\n";
  std::mt19937 random(7);
  auto pick = [&](std::size_t n) { return std::size_t(std::uniform_int_distribution<std::size_t>(0, n - 1)(random)); };
  auto real = [&] { return std::uniform_real_distribution<double>(-2, 2)(random); };
  int applied = 0;
  for (int call = 0; call < 400; ++call) {
    const command::Command& c = command::get(kGeneric[pick(std::size(kGeneric))]);
    std::vector<ParticleId> particles;
    for (ParticleId p = 0; p < r.model.particles.capacity(); ++p)
      if (r.model.particles.valid(p)) particles.push_back(p);
    const std::vector<BlockId> blocks = r.model.live_blocks();
    Args args;
    bool possible = true;
    for (const command::Param& p : c.params)
      possible &= !(p.type == command::Type::Block && blocks.empty()) &&
                  !((p.type == command::Type::Particle || p.type == command::Type::Particles) && particles.empty());
    if (!possible) continue;
    for (const command::Param& p : c.params) {
      switch (p.type) {
        case command::Type::Particle: args.push_back(id(particles[pick(particles.size())])); break;
        case command::Type::Block: args.push_back(id(blocks[pick(blocks.size())])); break;
        case command::Type::Goal: args.push_back(id(r.model.goals.empty() ? 0 : pick(r.model.goals.size()))); break;
        case command::Type::Flag: args.push_back(id(pick(2))); break;
        case command::Type::Number: args.push_back(num(std::abs(real()) + 0.1)); break;
        case command::Type::Vector: args.push_back(vec(real(), real(), real())); break;
        case command::Type::Particles: {
          std::vector<std::uint32_t> list;
          for (std::size_t k = 0, n = 2 + pick(2); k < n; ++k) list.push_back(particles[pick(particles.size())]);
          args.push_back(ids(list));
          break;
        }
        default: FAIL("unexpected parameter type");
      }
    }
    try {
      command::apply(r.session, c, args);
    } catch (const ModelError&) {
      continue;  // refused: nothing changed, and the scene does not make the call
    }
    ++applied;
    std::string call_text = command::lua_method(c) + "(";
    for (std::size_t k = 0; k < c.params.size(); ++k) call_text += (k ? ", " : "") + lua_value(c.params[k], args[k]);
    scene += call_text + ")\nrefresh()\n";
  }
  scene += "m:save(tendril.out('model.xml'))\nm:save_journal(tendril.out('journal.txt'))\n";
  std::ofstream(dir / "scene.lua") << scene;
  SceneOptions options;
  options.progress = false;
  options.out_dir = dir.string();
  std::string error;
  REQUIRE(run_scene((dir / "scene.lua").string(), options, &error) == 0);
  CHECK(error == "");
  CHECK(applied > 100);
  std::string lua_trace;
  std::istringstream journal(slurp(dir / "journal.txt"));
  for (std::string line; std::getline(journal, line);)
    if (!line.empty() && line[0] != '#') lua_trace += line + "\n";
  CHECK(lua_trace == r.journal_text());
  CHECK(slurp(dir / "model.xml") == r.xml());
}
