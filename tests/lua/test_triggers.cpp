// Triggers between solver steps (docs/rules.md): a rule `every = N` steps
// fires also when the run starts at equilibrium, and the run ends at rest
// once every such trigger has had its turn there.
#include <doctest/doctest.h>

#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("an every-N trigger fires on a model that starts at rest, and the run then ends at rest") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-triggers";
  const std::string scene = R"(
local m = tendril.model()
local a, b = m:particle{ 0, 0, 0 }, m:particle{ 1, 0, 0 }
m:cable(a, b, { EA = 1e4 })
m:lock(a, "all")
m:lock(b, "all")                                   -- at rest from the first step
local fired = {}
local grow = tendril.rule{ name = "add a cable", production = function(m)
  fired[#fired + 1] = m:steps()
  local ps = m:particles()
  local p = m:particle{ #ps, 1, 0 }
  m:cable(ps[#ps], p, { EA = 1e4 })
  m:lock(p, "all")
end }
m:trigger{ rule = grow, every = 25, max = 3 }
local r = m:run{ tolerance = 1e-6, max_steps = 10000 }
assert(r.converged, "the run did not end at rest")
assert(#fired == 3 and fired[1] == 25 and fired[2] == 50 and fired[3] == 75, table.concat(fired, " "))
assert(m:count().cables == 4)
assert(m:steps() == 76, m:steps())                -- the step after the last application: at rest, nothing due
-- A trigger whose rule changes nothing lets the run end at its first turn at rest.
local quiet = tendril.rule{ name = "look", production = function(m) fired[#fired + 1] = m:steps() end }
m:trigger{ rule = quiet, every = 40 }
local r2 = m:run{ tolerance = 1e-6, max_steps = 10000 }
assert(r2.converged and fired[4] == 80 and m:steps() == 80, m:steps())
)";
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error);
  INFO(error);
  CHECK(rc == 0);
}
