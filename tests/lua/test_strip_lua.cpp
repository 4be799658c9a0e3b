// Bending strips (m:strip, model/strip_grillage.hpp) against exact
// solutions of plate theory: a wide strip under a tip load is Mattiasson's
// elastica with EI = D W; an end moment M rolls it into a cylinder of
// radius D W / M; corner forces +-P twist it uniformly, w = tau x y with
// tau = P / (2 D (1 - nu)) (Kirchhoff's corner forces of pure twist). The
// strip is one production that replays and survives the model database.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

namespace {

// A strip 1 m long, W = 0.2 m wide, t = 10 mm, nu = 0.3, with E chosen so
// that D W = 1 N m^2; n segments along, `across` quads across.
std::string strip_scene(int n, int across) {
  return "local n, across = " + std::to_string(n) + ", " + std::to_string(across) + R"lua(
local W, t, nu = 0.2, 0.01, 0.3
local E = (1 / W) * 12 * (1 - nu * nu) / t^3
local m = tendril.model()
local s = m:strip{ origin = { 0, 0, 0 }, length = { 1, 0, 0 }, width = { 0, W, 0 },
                   segments = n, across = across, E = E, t = t, nu = nu }
assert(math.abs(s.D * W - 1) < 1e-9)
assert(#s.particles == across + 1 and #s.particles[1] == n + 1)
assert(#s.rows == across + 1 and #s.columns == n + 1)
assert(#s.bars == 2 * n * across and #s.twist == n * across)
local function share(r) return (r == 1 or r == across + 1) and 0.5 / across or 1 / across end
)lua";
}

}  // namespace

TEST_CASE("Lua: a wide strip under a tip load is Mattiasson's elastica with EI = D W (0.5 %)") {
  for (int across : {1, 2, 4}) {
    CAPTURE(across);
    const auto dir = std::filesystem::temp_directory_path() / ("tendril-strip-elastica-" + std::to_string(across));
    const std::string scene = strip_scene(20, across) + R"lua(
for r, row in ipairs(s.particles) do
  m:lock(row[1], "xyz")
  m:clamp(row[1], s.rows[r], { 1, 0, 0 })
end
-- Mattiasson (1981): PL^2/EI -> tip u/L, w/L
local exact = { [2] = { 0.16064, 0.49346 }, [5] = { 0.38763, 0.71379 }, [10] = { 0.55500, 0.81061 } }
local applied = 0
for _, k in ipairs{ 2, 5, 10 } do
  for r, row in ipairs(s.particles) do m:load(row[#row], { 0, 0, -k * share(r) }) end
  local res = m:run{ tolerance = 1e-8, max_steps = 2000000 }
  assert(res.converged, "PL^2/EI = " .. k .. ": not converged, residual " .. res.residual)
  for r, row in ipairs(s.particles) do
    local x = m:position(row[#row])
    local eu, ew = (1 - x[1]) / exact[k][1] - 1, -x[3] / exact[k][2] - 1
    print(string.format("across %d PL2/EI %2d row %d: u/L %.5f (%+.3f %%), w/L %.5f (%+.3f %%), %d steps",
                        across, k, r, 1 - x[1], 100 * eu, -x[3], 100 * ew, res.steps))
    assert(math.abs(eu) < 0.005 and math.abs(ew) < 0.005, "off the elastica")
    assert(math.abs(x[2] - (r - 1) * W / across) < 1e-4 * W, "the strip stays straight across: y " .. x[2])
  end
end
)lua";
    std::string error;
    CHECK(run_scene_in(dir, scene, &error) == 0);
    CHECK(error == "");
  }
}

TEST_CASE("Lua: an end moment rolls a strip into a cylinder of radius D W / M (0.5 %)") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-strip-roll";
  const std::string scene = strip_scene(20, 2) + R"lua(
for r, row in ipairs(s.particles) do
  m:lock(row[1], "xyz")
  m:clamp(row[1], s.rows[r], { 1, 0, 0 })
end
local M = 1.5 * math.pi   -- D W = 1: R = 1 / M, three quarters of a circle
for r, row in ipairs(s.particles) do m:torque(row[#row], { 0, -M * share(r), 0 }) end
local res = m:run{ tolerance = 1e-8, max_steps = 2000000 }
assert(res.converged, "not converged, residual " .. res.residual)
-- every particle of every row on the circle through the root with its
-- centre at (0, 0, R): the rows bend as one, the strip a cylinder
local R = 1 / M
local worst = 0
for _, row in ipairs(s.particles) do
  for _, p in ipairs(row) do
    local x = m:position(p)
    worst = math.max(worst, math.abs(math.sqrt(x[1]^2 + (x[3] - R)^2) / R - 1))
  end
end
print(string.format("roll-up: largest radius error %.4f %%", 100 * worst))
assert(worst < 0.005, "off the cylinder by " .. worst)
)lua";
  std::string error;
  CHECK(run_scene_in(dir, scene, &error) == 0);
  CHECK(error == "");
}

TEST_CASE("Lua: corner forces twist a strip uniformly, tau = P / (2 D (1 - nu)) (0.5 %)") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-strip-twist";
  const std::string scene = strip_scene(10, 2) + R"lua(
for _, row in ipairs(s.particles) do m:lock(row[1], "xyz") end
local tau = 1e-3                                  -- small: the linear theory
local P = 2 * (1 / W) * (1 - nu) * tau            -- D = 1 / W
local first, last = s.particles[1], s.particles[#s.particles]
m:load(first[#first], { 0, 0, -P })
m:load(last[#last], { 0, 0, P })
local res = m:run{ tolerance = 1e-10, max_steps = 2000000 }
assert(res.converged, "not converged, residual " .. res.residual)
-- w = tau x (y - W/2) everywhere
local worst = 0
for r, row in ipairs(s.particles) do
  for c, p in ipairs(row) do
    local x = m:position(p)
    local exact = tau * ((c - 1) / n) * ((r - 1) * W / across - W / 2)
    worst = math.max(worst, math.abs(x[3] - exact))
  end
end
local tip = tau * 1 * W / 2
print(string.format("twist: tip corner %.6e (exact %.6e), largest error %.3f %% of it",
                    m:position(last[#last])[3], tip, 100 * worst / tip))
assert(worst < 0.005 * tip, "off the uniform twist by " .. worst)
)lua";
  std::string error;
  CHECK(run_scene_in(dir, scene, &error) == 0);
  CHECK(error == "");
}

TEST_CASE("Lua: a strip is one production: replayed, saved and loaded; bad strips are errors naming the key") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-strip-replay";
  const std::string scene = R"lua(
local m = tendril.model()
local grid = {}
for r = 1, 3 do
  grid[r] = {}
  for c = 1, 5 do grid[r][c] = m:particle{ 0.25 * (c - 1), 0.1 * (r - 1), 0 } end
end
local s = m:strip{ particles = grid, E = 70e9, t = 0.002, nu = 0.3, density = 1550 }
assert(s.particles[2][3] == grid[2][3])
for _, row in ipairs(grid) do m:lock(row[1], "xyz") end
m:settings{ gravity = { 0, 0, -9.81 } }
m:step(200)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
local before = m:count()
local function fails(pattern, options)
  local ok, err = pcall(m.strip, m, options)
  assert(not ok, "expected an error matching " .. pattern)
  assert(err:find(pattern), err)
  local after = m:count()
  assert(after.particles == before.particles and after.beams == before.beams, "a refused strip left members")
end
fails("strip: 'E' is required", { particles = grid, t = 0.01 })
fails("strip: 'nu' must be in", { particles = grid, E = 1, t = 0.01, nu = 0.5 })
fails("strip: every row of a strip needs the same number", { particles = { grid[1], { grid[2][1] } }, E = 1, t = 0.01 })
fails("strip: 'segments' must be a whole number", { origin = { 0, 0, 0 }, length = { 1, 0, 0 }, width = { 0, 1, 0 },
                                                   segments = 0, across = 1, E = 1, t = 0.01 })
fails("strip: 'width' must not be parallel", { origin = { 0, 0, 0 }, length = { 1, 0, 0 }, width = { 2, 0, 0 },
                                               segments = 2, across = 1, E = 1, t = 0.01 })
fails("strip: 'origin' belongs to a strip made of new particles", { particles = grid, origin = { 0, 0, 0 }, E = 1, t = 0.01 })
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  const std::string live = slurp(dir / "live.xml");
  CHECK(replayed.xml() == live);
  Model loaded;
  SolverSettings settings;
  load_model_xml((dir / "live.xml").string(), loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(loaded.block_count(BlockKind::Beam) == 3 + 5);
  CHECK(loaded.block_count(BlockKind::Bar) == 2 * 4 * 2);
  CHECK(loaded.goals.size() == 4 * 2);
  CHECK(model_xml_string(loaded, settings) == live);
}
