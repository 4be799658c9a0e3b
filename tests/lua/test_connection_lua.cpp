// Joints between members from Lua (m:connection): rigid and pinned
// connections replay bit for bit from the journal, the model database keeps
// them (old files without them still load), and bad arguments are errors
// naming the function.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

TEST_CASE("Lua: rigid connections replay bit for bit and survive save and load") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-connection-lua";
  const std::string scene = R"(
local m = tendril.model()
local post = m:beam{ points = { { 0, 0, 0 }, { 0, 0.5, 0 }, { 0, 1, 0 } }, EA = 1e5, EI = 1 }
local ps = m:particles(post)
local far = m:particle{ 1, 1.1, 0 }
local lintel = m:beam{ particles = { ps[3], m:particle{ 0.5, 1.05, 0 }, far }, EA = 1e5, EI = 2 }
local brace = m:beam{ particles = { ps[2], m:particle{ 0.7, 0.6, 0.1 } }, EA = 1e5, EI = 1 }
assert(m:connection(ps[3], post, lintel) == "pinned")
m:connection(ps[3], post, lintel, "rigid")
m:connection(ps[2], brace, post, "rigid")             -- a beam end on another's interior
assert(m:connection(ps[3], lintel, post) == "rigid")
assert(m:connection(ps[2], post, brace) == "rigid")
m:lock(ps[1], "xyz")
m:clamp(ps[1], post)
m:lock(far, "xyz")
m:load(ps[3], { 0.01, -0.02, 0 })
m:step(300)
m:insert(ps[3], m:particles(lintel)[2])               -- rule 13 next to the joint
m:step(100)
m:check()
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  const std::string live = slurp(dir / "live.xml");
  CHECK(replayed.xml() == live);
  CHECK(live.find("<connections>") != std::string::npos);
  Model loaded;
  SolverSettings settings;
  load_model_xml((dir / "live.xml").string(), loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(loaded.rigid_joints.size() == 2);
  CHECK(model_xml_string(loaded, settings) == live);
}

TEST_CASE("Lua: bad connections are errors naming the function; what 6-DOF beams cannot honour is refused") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-connection-lua-errors";
  const std::string scene = R"(
local m = tendril.model()
local function fails(pattern, f, ...)
  local ok, err = pcall(f, m, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(err:find(pattern), err)
end
local a = m:beam{ points = { { 0, 0, 0 }, { 1, 0, 0 } }, EA = 1, EI = 1 }
local p = m:particles(a)[2]
local b = m:beam{ particles = { p, m:particle{ 1, 1, 0 } }, EA = 1, EI = 1 }
local lone = m:particle{ 5, 5, 5 }
local c = m:cable(lone, m:particles(a)[1], { EA = 10 })
fails("connection: .*must be one of", m.connection, p, a, b, "welded")
fails("connection: particle %d+ is not on beam", m.connection, lone, a, b, "rigid")
fails("connection: block %d+ is a cable", m.connection, m:particles(a)[1], a, c, "rigid")
fails("connection: beam %d+ does not have both its ends at particle", m.connection, p, a, a, "rigid")
m:formulation(b, 6)
fails("connection: beam %d+ has 3 DOF and beam %d+ 6", m.connection, p, a, b, "rigid")
assert(m:connection(p, a, b) == "pinned")
m:formulation(a, 6)
assert(m:connection(p, a, b) == "rigid")             -- a shared frame
fails("connection: beams %d+ and %d+ have 6 DOF", m.connection, p, a, b, "pinned")
)";
  std::string error;
  run_scene_in(dir, scene, &error);
  CHECK(error == "");
}

TEST_CASE("Lua: rule 3 takes the joint kind: merged beam ends become a rigid connection") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-connection-lua-merge";
  const std::string scene = R"(
local m = tendril.model()
local a = m:beam{ points = { { 0, 0, 0 }, { 1, 0, 0 } }, EA = 1, EI = 1 }
local b = m:beam{ points = { { 1, 0, 0 }, { 1, 1, 0 } }, EA = 1, EI = 1 }
local c = m:beam{ points = { { 3, 0, 0 }, { 4, 0, 0 } }, EA = 1, EI = 1 }
local d = m:beam{ points = { { 4, 0, 0 }, { 4, 1, 0 } }, EA = 1, EI = 1 }
local ok, p = m:apply(tendril.rules.merge, { m:particles(a)[2], m:particles(b)[1] }, "rigid")
assert(ok and m:connection(p, a, b) == "rigid")
local ok2, q = m:apply(tendril.rules.merge, { m:particles(c)[2], m:particles(d)[1] })
assert(ok2 and m:connection(q, c, d) == "pinned")
local ok3 = m:apply(tendril.rules.merge, { m:particles(a)[1], m:particles(c)[1] }, "welded")
assert(not ok3)
)";
  std::string error;
  run_scene_in(dir, scene, &error);
  CHECK(error == "");
}
