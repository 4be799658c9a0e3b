// Robustness (issue 4): random applications of the built-in rules, with
// valid and invalid arguments, on a live integrating model. The map stays
// valid, no NaN appears, and every failure leaves the model as it was.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "lua_host.hpp"

using namespace tendril;

TEST_CASE("10 000 random rule applications on an integrating model") {
  const auto path = std::filesystem::temp_directory_path() / "tendril-rules-fuzz.lua";
  std::ofstream(path) << R"(
local m = tendril.model()
local R = tendril.rules
local section = { EA = 1e5, EI = 10 }
for row = 0, 3 do
  local pts = {}
  for i = 0, 6 do pts[#pts + 1] = { i, row, 0 } end
  m:beam{ points = pts, EA = 1e5, EI = 10, closed = (row == 3) }
end
local all = m:particles()
m:lock(all[1], "all")
m:lock(all[7], "all")
m:gravity{ 0, 0, -1 }
m:mass(all[4], 1)

local function pick(list) return list[math.random(#list)] end
local function any_particle()
  local ps = m:particles()
  if #ps == 0 then return nil end
  return pick(ps)
end
local function any_block()
  local bs = m:blocks()
  if #bs == 0 then return nil end
  return pick(bs)
end
local counts = { applied = 0, refused = 0 }
local fingerprint = function()
  local c = m:count()
  local sum = 0
  for _, p in ipairs(m:particles()) do
    local x, v = m:position(p), m:velocity(p)
    sum = sum + p.id * (x[1] + 2 * x[2] + 3 * x[3] + v[1] + v[2] + v[3])
  end
  return string.format("%d %d %d %d %d %.17g", c.particles, c.blocks, c.darts, c.bars, c.hinges, sum)
end
local choices = {
  function() return R.add_particle, { math.random(), math.random(), math.random() } end,
  function() return R.delete_particle, any_particle() end,
  function() return R.merge, { any_particle(), any_particle() } end,
  function() return R.explode, any_particle() end,
  function() return R.explode_from, any_particle(), any_block() end,
  function() return R.cable, any_particle(), any_particle(), { EA = 1e3 } end,
  function() return R.delete_cable, any_block() end,
  function() return R.beam_from, any_particle(), { 0, 0, 1 }, math.random(-1, 3), section end,
  function() return R.remove_simple, any_particle() end,
  function() return R.remove_shared, any_particle(), any_block() end,
  function() return R.insert, any_particle(), any_particle() end,
  function() return R.subdivide, any_block() end,
  function() return R.unsubdivide, any_block() end,
  function() return R.delete_beam, any_block() end,
}
for n = 1, 10000 do
  local rule, a, b, c, d = pick(choices)()
  if a ~= nil then
    local before = fingerprint()
    local ok = m:apply(rule, a, b, c, d)
    if ok then counts.applied = counts.applied + 1
    else
      counts.refused = counts.refused + 1
      assert(fingerprint() == before, "a refused rule changed the model")
    end
  end
  if #m:particles() < 10 then
    m:beam{ points = { {0, 5, 0}, {1, 5, 0}, {2, 5, 0}, {3, 5, 0} }, EA = 1e5, EI = 10 }
  end
  m:step(1)
  if n % 500 == 0 then m:check() end
  for _, p in ipairs(m:particles()) do
    local x = m:position(p)
    assert(x[1] == x[1] and x[2] == x[2] and x[3] == x[3], "NaN at particle " .. p.id)
  end
end
m:check()
print(string.format("applied %d, refused %d, journal %d entries", counts.applied, counts.refused, #m:journal()))
assert(counts.applied > 2000 and counts.refused > 2000)
)";
  SceneOptions options;
  options.progress = false;
  options.out_dir = (std::filesystem::temp_directory_path() / "tendril-rules-fuzz").string();
  std::string error;
  CHECK(run_scene(path.string(), options, &error) == 0);
  CHECK(error == "");
}
