// Beams curved at rest, clamps and moments on 3-DOF beams from Lua
// (m:beam{rest =}, m:rest_shape, m:clamp, m:torque): the journal replays
// them bit for bit, the model database keeps them, bad arguments are
// errors naming the function.
#include <doctest/doctest.h>

#include <sstream>

#include "io/model_xml.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

TEST_CASE("Lua: rest shapes, clamps and 3-DOF moments replay bit for bit and survive save and load") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-beam-shape-lua";
  const std::string scene = R"(
local m = tendril.model()
local arc = {}
for i = 0, 12 do
  local a = math.pi / 2 * i / 12
  arc[#arc + 1] = { math.cos(a), math.sin(a), 0 }
end
local b = m:beam{ points = arc, EA = 1e5, EI = 1, rest = "current" }
assert(m:rest_shape(b) == "current")
local ps = m:particles(b)
m:lock(ps[1], "xyz")
m:clamp(ps[1], b)                                   -- along the first segment
local t = m:clamped(ps[1], b)
assert(math.abs(t[1]^2 + t[2]^2 + t[3]^2 - 1) < 1e-12)
assert(m:clamped(ps[13], b) == nil)
m:torque(ps[13], { 0, 0, 0.5 })                     -- a couple across the end segment
m:step(200)
m:insert(ps[5], ps[6])                              -- rule 13 on a curved beam
m:formulation(b, 6)
m:lock(ps[1], "full")
m:step(50)
m:formulation(b, 3)
m:rest_shape(b, "straight")
m:step(30)
m:rest_shape(b, "current")
local six = m:beam{ points = arc, EA = 1e5, EI = 1, dofs = 6, rest = "current" }
m:lock(m:particles(six)[1], "full")
m:step(20)
m:unclamp(ps[1], b)
m:clamp(ps[1], b, { 0, 1, 0 })
m:step(10)
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
  CHECK(live.find("rest=\"current\"") != std::string::npos);
  CHECK(live.find("curvature=") != std::string::npos);
  CHECK(live.find("tx=") != std::string::npos);
  // The model database keeps them: loaded and saved again, the same file.
  Model loaded;
  SolverSettings settings;
  load_model_xml((dir / "live.xml").string(), loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(model_xml_string(loaded, settings) == live);
}

TEST_CASE("Lua: bad rest shapes, clamps and moments are errors naming the function") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-beam-shape-lua-errors";
  const std::string scene = R"(
local m = tendril.model()
local function fails(pattern, f, ...)
  local ok, err = pcall(f, m, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(err:find(pattern), err)
end
local pts = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0.1 } }
fails("beam: 'rest' must be \"straight\" or \"current\", got \"curved\"", m.beam, { points = pts, EA = 1, EI = 1, rest = "curved" })
assert(m:count().particles == 0)                    -- nothing made
local b = m:beam{ points = pts, EA = 1, EI = 1 }
local ps = m:particles(b)
assert(m:rest_shape(b) == "straight")
fails("rest_shape: argument 3: must be one of \"straight\", \"current\", got \"bent\"", m.rest_shape, b, "bent")
local lone = m:particle{ 5, 5, 5 }
local c = m:cable(lone, ps[1], { EA = 10 })
fails("rest_shape: block %d+ is a cable; only beams have a rest shape", m.rest_shape, c, "current")
fails("torque: particle %d+ is in no beam", m.torque, lone, { 0, 0, 1 })
m:torque(lone, { 0, 0, 0 })                         -- clearing is always fine
fails("clamp: particle %d+ is not an end of beam", m.clamp, ps[2], b)
fails("clamp: particle %d+ is not on beam", m.clamp, lone, b)
fails("clamp: argument 4: the direction must not be zero", m.clamp, ps[1], b, { 0, 0, 0 })
m:clamp(ps[3], b)
fails("extend_beam: the end of beam %d+ at particle %d+ is clamped", m.extend, b, ps[3], m:particle{ 3, 0, 0 })
m:formulation(b, 6)
fails("clamp: beam %d+ has 6 DOF", m.clamp, ps[1], b)
)";
  std::string error;
  run_scene_in(dir, scene, &error);
  CHECK(error == "");
}
