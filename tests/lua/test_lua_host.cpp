// The Lua host: errors name the scene's file and line and the function and
// argument at fault; refused calls leave the model unchanged; same seed, same
// numbers.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "lua_host.hpp"

using namespace tendril;

namespace {

std::filesystem::path work_dir() {
  auto dir = std::filesystem::temp_directory_path() / "tendril-test-lua";
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `code` as scene `name`; returns the error text ("" on success).
std::string run(const std::string& name, const std::string& code, SceneOptions options = {}) {
  auto path = work_dir() / name;
  std::ofstream(path) << code;
  if (options.out_dir == "out") options.out_dir = (work_dir() / "out").string();
  options.progress = false;
  std::string error;
  int rc = run_scene(path.string(), options, &error);
  CHECK((rc == 0) == error.empty());
  return error;
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("a Lua error names the file and line and carries a traceback") {
  std::string err = run("syntax.lua", "local m = tendril.model()\nlocal x = = 1\n");
  CHECK(err.find("syntax.lua:2:") != std::string::npos);

  err = run("runtime.lua", "local m = tendril.model()\n\nerror('boom')\n");
  CHECK(err.find("runtime.lua:3: boom") != std::string::npos);
  CHECK(err.find("stack traceback") != std::string::npos);
}

TEST_CASE("wrong arguments are Lua errors naming the function and the argument") {
  struct Case {
    const char* code;
    const char* expect;
  };
  const Case cases[] = {
      {"m:beam{ points = {{0,0,0},{1,0,0}}, EAx = 1, EI = 1 }", "beam: unknown key 'EAx'"},
      {"m:beam{ from = m:particle{0,0,0}, direction = {1,0,0}, segments = -3, EA = 1, EI = 1 }",
       "beam: 'segments' must be an integer >= 1"},
      {"local p = m:particle{0,0,0}; m:delete_particle(p); m:lock(p, 'x')", "lock: argument 2: particle 0 was deleted"},
      {"m:particle{0, 0}", "particle: argument 2: expected a table of 3 finite numbers"},
      {"m:cable(m:particle{0,0,0}, m:particle{1,0,0}, { EA = -1 })", "cable: 'EA' must be >= 0"},
      {"m:run{ tolerance = 0 }", "run: 'tolerance' must be > 0"},
      {"tendril.model{ damping = 'sticky' }",
       "tendril.model: 'damping' must be one of \"kinetic\", \"viscous\", \"none\", got \"sticky\""},
      {"local a, b = m:particle{0,0,0}, m:particle{1,0,0}; m:insert(a, b)",
       "insert_particle: particles 0 and 1 are not consecutive on a beam"},
      {"m.run(42)", "run: argument 1: expected a model"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.code);
    std::string err = run("args.lua", std::string("local m = tendril.model()\n") + c.code + "\n");
    CHECK(err.find("args.lua:2:") != std::string::npos);
    CHECK(err.find(c.expect) != std::string::npos);
  }
}

TEST_CASE("a refused operation leaves the model as it was") {
  std::string err = run("refused.lua", R"(
local m = tendril.model()
local b = m:beam{ points = {{0,0,0},{1,0,0},{2,0,0}}, EA = 1e6, EI = 10 }
local before = m:count()
local ps = m:particles(b)
assert(not pcall(m.merge, m, { ps[1], ps[2] }))          -- would collapse an edge
assert(not pcall(m.explode, m, ps[2]))                   -- not shared
assert(not pcall(m.beam, m, { points = {{0,0,0}}, EA = 1, EI = 1 }))
local after = m:count()
for k, v in pairs(before) do assert(after[k] == v, k) end
m:check()
)");
  CHECK(err == "");
}

TEST_CASE("same scene, same seed: same numbers; another seed: other numbers") {
  const std::string scene = R"(
local m = tendril.model()
local ps = {}
for i = 0, 10 do ps[#ps + 1] = m:particle{ i, math.random() * 0.1, 0 } end
m:beam{ particles = ps, EA = 1e6, EI = 100 }
m:lock(ps[1], "all"); m:lock(ps[11], "all")
m:load(ps[6], { 0, 0, -100 })
m:run{ tolerance = 1e-6, max_steps = 100000 }
m:save(tendril.out("model.xml"))
)";
  auto out = [&](const std::string& name, std::int64_t seed) {
    SceneOptions o;
    o.seed = seed;
    o.out_dir = (work_dir() / name).string();
    CHECK(run("seeded.lua", scene, o) == "");
    return read(work_dir() / name / "model.xml");
  };
  const std::string a = out("seed-a", 7), b = out("seed-b", 7), c = out("seed-c", 8);
  CHECK(a.size() > 1000);
  CHECK(a == b);
  CHECK(a != c);
}

TEST_CASE("--steps caps every run") {
  SceneOptions o;
  o.max_steps = 5;
  std::string err = run("capped.lua", R"(
local m = tendril.model()
local b = m:beam{ points = {{0,0,0},{1,0,0},{2,0,0}}, EA = 1e6, EI = 10 }
m:lock(m:particles(b)[1], "all")
m:load(m:particles(b)[3], { 0, 0, -1 })
local r = m:run{ tolerance = 1e-9, max_steps = 1000 }
assert(r.steps == 5 and not r.converged, r.steps)
)", o);
  CHECK(err == "");
}
