// Issue 13: what a scene does cannot crash tendril. Each case is the smallest
// scene that crashed (under ASan: a use-after-free or a stack overflow) or
// mis-reported before its fix.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "scene_files.hpp"

using namespace tendril;

namespace {

std::filesystem::path folder(const std::string& name) {
  return std::filesystem::temp_directory_path() / "tendril-test-safety" / name;
}

// Runs `code` in its own folder; returns the error ("" when it ran).
std::string run(const std::string& name, const std::string& code, SceneOptions options = {}) {
  std::string error;
  const int status = test::run_scene_in(folder(name), code, &error, options);
  CHECK((status == 0) == error.empty());
  return error;
}

const char* const kTwoParticles = R"(
local m = tendril.model()
local a, b = m:particle{0, 0, 0}, m:particle{1, 0, 0}
m:cable(a, b, {EA = 1e3})
m:lock(a, "xyz") m:lock(b, "xyz")
)";

}  // namespace

TEST_CASE("a rule that registers triggers while triggers fire: they join at the next step") {
  // Used to push into the vector fire_triggers was iterating (heap use after free).
  const std::string error = run("trigger-in-trigger", std::string(kTwoParticles) + R"(
count = 0
local counting = tendril.rule{name = "count", production = function(m) count = count + 1 end}
local spawn = tendril.rule{name = "spawn", production = function(m)
  for k = 1, 40 do m:trigger{rule = counting, every = 1} end
end}
m:trigger{rule = spawn, every = 1, max = 1}
local seen = 0
m:trigger{rule = tendril.rule{name = "watch", production = function(m) seen = seen + 1 end},
          when = function(m) for k = 1, 5 do m:trigger{rule = counting, every = 1000} end return true end}
m:step(5)
-- spawn ran at step 1; its 40 triggers fire at steps 2 to 5.
assert(count == 160, "count " .. count)
assert(seen == 5)
)");
  CHECK(error == "");
}

TEST_CASE("a trigger's select list longer than Lua's stack is an error, not a stack overflow") {
  const std::string error = run("select-huge", std::string(kTwoParticles) + R"(
local r = tendril.rule{name = "many", production = function(m, ...) end}
local list = {}
for k = 1, 200000 do list[k] = k end
m:trigger{rule = r, every = 1, select = function(m) return {list} end}
m:step(1)
)");
  CHECK(error.find("trigger 'select': argument list 1 has 200000 values, more than a rule takes (100000)") !=
        std::string::npos);
  // 5000 values are fine (they overflowed the C stack's 20 free slots).
  CHECK(run("select-5000", std::string(kTwoParticles) + R"(
local got = 0
local r = tendril.rule{name = "many", production = function(m, ...) got = select("#", ...) end}
local list = {}
for k = 1, 5000 do list[k] = k end
m:trigger{rule = r, every = 1, max = 1, select = function(m) return {list} end}
m:step(1)
assert(got == 5000, got)
)") == "");
}

TEST_CASE("a trigger's every and max beyond 2^53 are refused with their own message") {
  const std::string every = run("every-huge", std::string(kTwoParticles) + R"(
m:trigger{rule = tendril.rule{name = "r", production = function(m) end}, every = 1e300}
)");
  CHECK(every.find("trigger: 'every' must be a whole number of steps up to 2^53") != std::string::npos);
  const std::string max = run("max-huge", std::string(kTwoParticles) + R"(
m:trigger{rule = tendril.rule{name = "r", production = function(m) end}, every = 1, max = -1e300}
)");
  CHECK(max.find("trigger: 'max' must be a whole number of applications from 0 to 2^53") != std::string::npos);
}

TEST_CASE("every loop the rule library makes saves and loads back to the same file") {
  // m:save wrote beams that visit a particle twice; tendril.load refused
  // them ("particle N appears twice in the beam").
  for (const char* rule : {"ring_loop", "drop_single", "drop_double"}) {
    CAPTURE(rule);
    const std::string error = run(std::string("loop-") + rule, std::string(R"(
local m = tendril.model()
local pts = {}
for k = 0, 7 do pts[#pts + 1] = {math.cos(k * 0.8), math.sin(k * 0.8), 0.1 * k} end
local beam = m:beam{points = pts, EA = 1e4, EI = 10}
local ok, why = m:apply(tendril.rules.)") + rule + R"(, beam)
assert(ok, why)
m:step(20)
m:formulation(beam, 6)
m:step(3)
assert(m:check() == true)
m:save(tendril.out("a.xml"))
local back = tendril.load(tendril.out("a.xml"))
back:save(tendril.out("b.xml"))
local function slurp(p) local f = assert(io.open(p)) local s = f:read("a") f:close() return s end
assert(slurp(tendril.out("a.xml")) == slurp(tendril.out("b.xml")))
assert(back:count().particles == m:count().particles)
)");
    CHECK(error == "");
  }
}

TEST_CASE("merging two diagonal corners of a patch quad is refused") {
  // It passed m:check() but could be neither saved nor replayed.
  const std::string error = run("patch-diagonal", R"(
local m = tendril.model()
local ps = {}
for r = 0, 1 do for c = 0, 1 do ps[#ps + 1] = m:particle{c, r, 0} end end
m:quad_grid{particles = ps, rows = 2, cols = 2, EA = 1e3}
local ok, err = pcall(m.merge, m, {ps[1], ps[4]})
assert(not ok)
assert(err:find("merge: particles 0 and 3 are diagonal corners of a patch quad; merging them would collapse it"), err)
assert(m:count().particles == 4)
)");
  CHECK(error == "");
}

TEST_CASE("a beam may come back to a particle, but not in a row or two apart") {
  const std::string error = run("beam-repeats", R"(
local m = tendril.model()
local p = {}
for k = 1, 5 do p[k] = m:particle{math.cos(k), math.sin(k), 0} end
local ok, err = pcall(m.beam, m, {particles = {p[1], p[2], p[1]}, EA = 1, EI = 1})
assert(err:find("beam: particle 0 appears twice two apart; the beam would fold onto itself"), err)
ok, err = pcall(m.beam, m, {particles = {p[1], p[2], p[3]}, closed = true, EA = 1, EI = 1})
assert(ok, err)
ok, err = pcall(m.beam, m, {particles = {p[1], p[2], p[3], p[4], p[1]}, EA = 1, EI = 1})
assert(ok, err)  -- a drop: both ends on one particle
assert(m:check() == true)
)");
  CHECK(error == "");
}

// --- --sandbox ------------------------------------------------------------------

namespace {

SceneOptions sandboxed() {
  SceneOptions o;
  o.sandbox = true;
  return o;
}

}  // namespace

TEST_CASE("--sandbox: no programs, no libraries, no bytecode, files only in the output folder") {
  const std::string error = run("sandbox-libraries", R"(
assert(os.execute == nil and os.exit == nil and os.remove == nil and os.getenv == nil)
assert(io.popen == nil and io.output == nil and require == nil and package == nil and debug == nil)
assert(dofile == nil and loadfile == nil and type(os.clock()) == "number")
local chunk, why = load(string.dump(function() return 1 end))
assert(chunk == nil and why:find("attempt to load a binary chunk"), why)
assert(load("return 2")() == 2)
local ok, err = pcall(io.open, "/etc/hostname")
assert(not ok and err:find("--sandbox: reading /etc/hostname is refused", 1, true), err)
ok, err = pcall(io.open, tendril.out("../escaped.txt"), "w")
assert(not ok and err:find("writing .*escaped.txt is refused"), err)
local m = tendril.model()
m:particle{0, 0, 0}
ok, err = pcall(m.save, m, "/tmp/tendril-sandbox-elsewhere.xml")
assert(not ok and err:find("--sandbox: writing /tmp/tendril-sandbox-elsewhere.xml is refused", 1, true), err)
m:save(tendril.out("inside.xml"))
local f = assert(io.open(tendril.out("inside.xml")))
assert(f:read("a"):find("<tendril"))
f:close()
assert(tendril.load(tendril.out("inside.xml")):count().particles == 1)
)", sandboxed());
  CHECK(error == "");
  CHECK(!std::filesystem::exists("/tmp/tendril-sandbox-elsewhere.xml"));
}

TEST_CASE("--sandbox: a scene that allocates without bound stops at its memory limit") {
  SceneOptions o = sandboxed();
  o.limits.memory_mb = 16;
  const std::string error = run("sandbox-memory", R"(
local t = {}
for k = 1, 1e9 do t[k] = string.rep("x", 1000) .. k end
)", o);
  CHECK(error == "--sandbox: the scene's Lua memory reached its limit of 16 MB");
}

TEST_CASE("--sandbox: an endless loop in a rule is rolled back at the instruction limit") {
  SceneOptions o = sandboxed();
  o.limits.production_instructions = 1'000'000;
  const std::string error = run("sandbox-production", std::string(kTwoParticles) + R"(
local endless = tendril.rule{name = "endless", production = function(m)
  m:particle{5, 5, 5}
  while true do end
end}
local ok, why = m:apply(endless)
assert(not ok and why:find("rule 'endless' failed and was rolled back: .*a rule application ran more than 1000000 Lua instructions"), why)
assert(m:count().particles == 2)
-- the scene goes on: its own loops are not productions
local n = 0
for k = 1, 3000000 do n = n + 1 end
)", o);
  CHECK(error == "");
}

TEST_CASE("--sandbox: the scene's wall time is limited, in Lua and in the solver's steps") {
  SceneOptions o = sandboxed();
  o.limits.seconds = 0.3;
  CHECK(run("sandbox-time-lua", "while true do end", o).find("the scene ran longer than its time limit of 0.3") !=
        std::string::npos);
  const std::string steps = run("sandbox-time-steps", std::string(kTwoParticles) + "m:step(1e12)", o);
  CHECK(steps.find("the scene ran longer than its time limit of 0.3") != std::string::npos);
}

TEST_CASE("extreme numbers give their message, not a signed overflow") {
  const std::string error = run("extreme-numbers", std::string(kTwoParticles) + R"(
local ok, err = pcall(m.joint_angle, m, math.mininteger)
assert(not ok and err:find("joint_angle: argument 2: no such joint"), err)
local near = m:neighbours({1e300, 0, 0}, 1)
assert(#near == 0)
near = m:neighbours({-1e300, 0, 0}, 1e-300)
assert(#near == 0)
assert(#m:neighbours({0.5, 0, 0}, 1) == 2)
ok, err = pcall(m.particle, m, {1e155, 0, 0})
assert(not ok and err:find("beyond 1e%+12 m from the origin"), err)
)");
  CHECK(error == "");
}

TEST_CASE("argument tables that refer to themselves, nest deep or fan out are described within bounds") {
  // The journal's description of a call recursed for ever into a table that
  // refers to itself, and pushed past Lua's stack for one 1000 deep.
  const std::string error = run("describe-bounded", std::string(kTwoParticles) + R"(
local self = {} self[1] = self
local ok, err = pcall(m.particle, m, self)
assert(not ok and err:find("particle: argument 2: expected"), err)
local deep = {} local d = deep
for k = 1, 1000 do d[1] = {} d = d[1] end
ok, err = pcall(m.particle, m, deep)
assert(not ok and err:find("particle: argument 2: expected"), err)
-- 100 keys that each refer back: 100^4 values at depth 4 without a budget.
local wide = {} for k = 1, 100 do wide["k" .. k] = wide end
local clock = os.clock()
ok, err = pcall(m.particle, m, wide)
assert(not ok and os.clock() - clock < 1, os.clock() - clock)
-- What is journaled shows the cut, four tables deep.
local r = tendril.rule{name = "takes", production = function(m, t) m:particle{0, 0, 2} end}
assert(m:apply(r, self))
local j = m:journal()
assert(j[#j].rule == "takes" and j[#j].args == "{{{{{...}}}}}", j[#j].args)
assert(m:apply(r, {x = {{1, 2}}}, 3))
j = m:journal()
assert(j[#j].args == "{x={{1 2}}} 3", j[#j].args)
)");
  CHECK(error == "");
}
