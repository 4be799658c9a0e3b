// Save and load keep the run (issue 14): a model saved at equilibrium and
// loaded again has its step count and simulated time, its reactions at
// once, and is still converged in its first step; its counters go on from
// there; a database without them (written before) loads with 0.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::run_scene_in;
using test::slurp;

TEST_CASE("Lua: a model saved and loaded keeps its steps, time and reactions, and is converged in one step") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-save-load-run";
  const std::string scene = R"lua(
-- a 3 m rod of 1 kg/m pinned at both ends, sagging under its weight
local m = tendril.model()
local rod = m:beam{ points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } }, EA = 1e6, EI = 100, line_mass = 1 }
local ps = m:particles(rod)
m:lock(ps[1], "xyz")
m:lock(ps[4], "xyz")
m:gravity{ 0, 0, -9.81 }
local r = m:run{ tolerance = 1e-6, max_steps = 100000 }
assert(r.converged and m:steps() == r.steps and m:steps() > 100)
local steps, time, reaction = m:steps(), m:time(), m:reaction(ps[1])[3]
assert(math.abs(time - steps * m:settings().dt) < 1e-12 * time, "time = steps dt with a fixed dt")
assert(math.abs(reaction - 3 * 9.81 / 2) < 1e-4, "each pin carries half the weight: " .. reaction)
m:save(tendril.out("rod.xml"))

local n = tendril.load(tendril.out("rod.xml"))
assert(n:steps() == steps and n:time() == time, "the counters come back")
assert(n:reaction(n:particles()[1])[3] == reaction, "reactions at once")
local again = n:run{ tolerance = 1e-6, max_steps = 100000 }
assert(again.converged and again.steps == 1, "converged in " .. again.steps .. " steps")
assert(n:steps() == steps + 1 and n:summary().steps == steps + 1, "counting goes on")
n:step(10)
assert(n:steps() == steps + 11)
print(string.format("saved after %d steps (%.6g s); loaded: converged in %d step, reaction %.6f N", steps, time,
                    again.steps, reaction))
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  CHECK(slurp(dir / "rod.xml").find("<tendril version=\"1\" steps=\"") != std::string::npos);
}

TEST_CASE("A model database without steps and time (written before them) loads with 0; bad counters are refused") {
  Model m;
  SolverSettings s;
  load_model_xml_string("<tendril version=\"1\"><particles><particle id=\"0\" x=\"0\" y=\"0\" z=\"0\"/></particles></tendril>", m,
                        s);
  CHECK(m.steps == 0);
  CHECK(m.time == 0);
  for (const char* bad : {"steps=\"-1\"", "steps=\"1.5\"", "time=\"-2\""}) {
    CAPTURE(bad);
    Model k;
    CHECK_THROWS_AS(load_model_xml_string(std::string("<tendril version=\"1\" ") + bad + "/>", k, s), ModelFormatError);
  }
}
