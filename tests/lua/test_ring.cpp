// The ring constructor (thesis 6.3.2: "a center point, a plane, a radius and
// a particle resolution"): m:beam{centre =, normal =, radius =, segments =}
// and tendril.rules.ring; its particles lie on the circle, in the plane,
// evenly spaced; it journals and replays like any beam.
#include <doctest/doctest.h>

#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("a ring from a centre, a plane normal, a radius and segments") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-ring";
  const std::string scene = R"(
local m = tendril.model()
local n = { 1, 2, 2 }                                 -- |n| = 3
local ring = m:beam{ centre = { 1, -2, 0.5 }, normal = n, radius = 1.5, segments = 24, EA = 1e6, EI = 10 }
assert(m:closed(ring) and #m:particles(ring) == 24 and m:count().hinges == 24)
local ps = m:particles(ring)
for i, p in ipairs(ps) do
  local x = m:position(p)
  local d = { x[1] - 1, x[2] + 2, x[3] - 0.5 }
  assert(math.abs(math.sqrt(d[1]^2 + d[2]^2 + d[3]^2) - 1.5) < 1e-12, "off the circle")
  assert(math.abs((d[1] * n[1] + d[2] * n[2] + d[3] * n[3]) / 3) < 1e-12, "off the plane")
  local y = m:position(ps[i % 24 + 1])
  local chord = math.sqrt((x[1]-y[1])^2 + (x[2]-y[2])^2 + (x[3]-y[3])^2)
  assert(math.abs(chord - 2 * 1.5 * math.sin(math.pi / 24)) < 1e-12, "uneven")
end
-- Counter-clockwise about the normal, the first particle towards 'start'.
local flat = m:beam{ centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = 2, segments = 4, start = { 0, 1, 5 }, EA = 1e6, EI = 10 }
local q = m:particles(flat)
local x1, x2 = m:position(q[1]), m:position(q[2])
assert(math.abs(x1[2] - 2) < 1e-12 and math.abs(x2[1] + 2) < 1e-12)
local ok, r3 = m:apply(tendril.rules.ring, { centre = { 0, 0, 3 }, normal = { 0, 0, 1 }, radius = 1, segments = 8, EA = 1e6, EI = 10, dofs = 6 })
assert(ok and m:formulation(r3) == 6)
for _, bad in ipairs{
  { { centre = { 0, 0, 0 }, radius = 1, segments = 8, EA = 1, EI = 1 }, "'normal' is required" },
  { { centre = { 0, 0, 0 }, normal = { 0, 0, 0 }, radius = 1, segments = 8, EA = 1, EI = 1 }, "'normal' must be a non-zero vector" },
  { { centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = -1, segments = 8, EA = 1, EI = 1 }, "'radius' must be" },
  { { centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = 1, segments = 2, EA = 1, EI = 1 }, "'segments' must be a whole number >= 3" },
  { { centre = { 0, 0, 0 }, normal = { 0, 0, 1 }, radius = 1, segments = 8, closed = false, EA = 1, EI = 1 }, "'closed' cannot be false" },
  { { points = { { 0, 0, 0 }, { 1, 0, 0 } }, radius = 1, EA = 1, EI = 1 }, "'radius' belongs to a ring" },
} do
  local before = m:count().particles
  local ok, err = pcall(m.beam, m, bad[1])
  assert(not ok and err:find(bad[2], 1, true), err)
  assert(m:count().particles == before)
end
m:save_journal(tendril.out("journal.txt"))
m:save(tendril.out("live.xml"))
)";
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error);
  INFO(error);
  REQUIRE(rc == 0);
  CHECK(test::replays_to_live(dir));
}
