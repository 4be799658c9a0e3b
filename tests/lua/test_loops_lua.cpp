// The looped typologies of thesis fig. 6.10 are disconnected again by rules 4
// and 5 (tendril.rules), and an erroneous connection is reverted (thesis
// 6.2): two rods connected by rule 3 and relaxed, then exploded by rule 4 and
// relaxed, stand where they stood before the connection.
#include <doctest/doctest.h>

#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("rules 4 and 5 open the loops of ring_loop, drop_single and drop_double") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-loops-lua";
  const std::string scene = R"(
local R = tendril.rules
local function rod(m, n)
  local pts = {}
  for i = 0, n - 1 do
    local a = 1.7 * math.pi * i / (n - 1)
    pts[#pts + 1] = { math.sin(a), 0, 1 - math.cos(a) }
  end
  return m:beam{ points = pts, EA = 1e6, EI = 10 }
end
for _, loop in ipairs{ "ring_loop", "drop_single", "drop_double" } do
  local m = tendril.model()
  local beam = rod(m, 16)
  local ok, j1, j2 = m:apply(R[loop], beam)
  assert(ok, loop)
  assert(m:state(j1) == "shared" and #m:references(j1) == 2 and #m:blocks(j1) == 1, loop)
  local ok4, parts = m:apply(R.explode, j1)
  assert(ok4 and #parts == 2, loop .. ": rule 4 refused")
  if j2 then
    local ok5, q = m:apply(R.explode_from, j2, beam)
    assert(ok5 and m:state(q) == "simple" and m:state(j2) == "simple", loop .. ": rule 5 refused")
  end
  assert(m:count().particles == 16 and not m:closed(beam), loop)
  for _, p in ipairs(m:particles(beam)) do assert(m:state(p) == "simple", loop) end
  m:check()
end
)";
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error);
  INFO(error);
  CHECK(rc == 0);
}

TEST_CASE("an erroneous connection reverted: the rods return to their equilibrium before it") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-revert-lua";
  const std::string scene = R"(
local m = tendril.model()
local R = tendril.rules
-- Two 3 m GFRP cantilevers (d 12 mm) side by side, a third rod pinned on the floor.
local E, d = 25e9, 0.012
local section = { E = E, A = math.pi * d^2 / 4, I = math.pi * d^4 / 64 }
local function cantilever(y)
  local b = m:beam{ from = m:particle{ 0, y, 0 }, direction = { 0, 0, 3 }, segments = 12, E = section.E, A = section.A, I = section.I }
  local ps = m:particles(b)
  m:lock(ps[1], "xyz")
  m:lock(ps[2], "xy")
  return ps
end
local a, b = cantilever(0), cantilever(1.2)
local before, tip_a, tip_b = {}, m:position(a[13]), m:position(b[13])
for _, p in ipairs(m:particles()) do before[#before + 1] = { p, m:position(p) } end
local ok, joint = m:apply(R.merge, { a[13], b[13] })    -- the tips pulled together: a bad connection
assert(ok)
assert(m:run{ tolerance = 1e-6, max_steps = 200000 }.converged)
local bent = m:position(a[7])
assert(bent[2] > 0.05, "the connection bends the rods")
local ok4, tips = m:apply(R.explode, joint)            -- reverted
assert(ok4 and #tips == 2)
assert(m:run{ tolerance = 1e-6, max_steps = 200000 }.converged)
local worst = 0
local function off(x, y) worst = math.max(worst, math.sqrt((x[1]-y[1])^2 + (x[2]-y[2])^2 + (x[3]-y[3])^2)) end
for _, pair in ipairs(before) do
  local p, y = pair[1], pair[2]
  if p ~= a[13] and p ~= b[13] then off(m:position(p), y) end
end
off(m:position(tips[1]), tip_a)                          -- rod a's tip: the first reference (block order)
off(m:position(tips[2]), tip_b)
print(string.format("after the revert the rods are within %.2e m of where they stood", worst))
assert(worst < 1e-6, worst)
)";
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error);
  INFO(error);
  CHECK(rc == 0);
}
