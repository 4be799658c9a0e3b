// The journal replays: a scene that grows its model with rules and triggers
// (including a production that fails and is rolled back) gives, replayed from
// its journal, the same model bit for bit.
#include <doctest/doctest.h>

#include <sstream>

#include "command/replay.hpp"

#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

TEST_CASE("replaying a journal rebuilds the final model bit for bit") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-replay";
  const std::string scene = R"(
local m = tendril.model{ damping = "kinetic" }
m:gravity{ 0, 0, -9.81 }
local beam = m:beam{ points = {{0,0,0}, {1,0,0}, {2,0,0}, {3,0,0}}, EA = 1e5, EI = 1, line_mass = 1 }
local ends = m:particles(beam)
m:lock(ends[1], "all")
m:lock(ends[4], "all")
local split = tendril.rule{ name = "split the longest segment", production = function(m)
  local ps, best, at = m:particles(beam), -1, nil
  for i = 1, #ps - 1 do
    local x, y = m:position(ps[i]), m:position(ps[i + 1])
    local d = (x[1]-y[1])^2 + (x[2]-y[2])^2 + (x[3]-y[3])^2
    if d > best then best, at = d, i end
  end
  m:insert(ps[at], ps[at + 1])
end }
local failing = tendril.rule{ name = "failing", production = function(m)
  m:insert(ends[1], m:particles(beam)[2])
  error("rolled back")
end }
m:trigger{ rule = split, on = "equilibrium", max = 6 }
m:trigger{ rule = failing, every = 300, max = 3 }
m:cable(ends[1], m:particles(beam)[3], { EA = 100, rest_length = 2.5 })
local mid = m:particles(beam)[2]
m:load(mid, { 0, 1, 0 })
m:run{ tolerance = 1e-5, max_steps = 200000 }
m:apply(tendril.rules.explode, ends[1])
m:step(25)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");

  Replayed replayed(dir / "journal.txt");
  const Model& model = replayed.model;
  CHECK(model.check() == "");
  const std::string live = slurp(dir / "live.xml");
  CHECK(live.size() > 2000);
  CHECK(replayed.xml() == live);
  CHECK(model.particle_count() == 11);  // 4 + 6 splits + 1 from the explode
}

TEST_CASE("a malformed journal names its line") {
  Model model;
  Solver solver(model);
  std::istringstream bad("particle 0 0 0\ninsert 0 7\n");
  CHECK_THROWS_WITH_AS(replay_trace(bad, "j.txt", model, solver), doctest::Contains("j.txt:2:"), ModelError);
  std::istringstream unknown("particle 0 0 0\nfly 3\n");
  Model other;
  Solver s2(other);
  CHECK_THROWS_WITH_AS(replay_trace(unknown, "j.txt", other, s2), doctest::Contains("j.txt:2: unknown operation 'fly'"),
                       ModelError);
}

TEST_CASE("a journal with 6-DOF beams, frames, moments and formulation switches replays bit for bit") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-replay6";
  const std::string scene = R"(
local m = tendril.model()
local ps = {}
for i = 0, 16 do ps[#ps + 1] = m:particle{ i * 0.25, 0, 0 } end
local b = m:beam{ particles = ps, EA = 1e7, EI = 100, GJ = 80, dofs = 6 }
m:lock(ps[1], "full")
m:torque(ps[17], { 0, 0, 2 * math.pi * 100 / 4 * 0.3 })
m:run{ tolerance = 1e-4, max_steps = 50000 }
m:formulation(b, 3)
m:step(100)
m:formulation(b, 6)
m:step(50)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  Replayed replayed(dir / "journal.txt");
  const Model& model = replayed.model;
  CHECK(model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
  CHECK(model.beam6s.size() == 16);
}

TEST_CASE("a journal with multi-resolution switches (thesis 5.5.2.3) replays bit for bit") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-replay-multires";
  const std::string scene = R"(
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local grid = {}
for r = 0, 3 do
  for c = 0, 3 do
    local p = m:particle{ c, r, 0 }
    if r == 0 or c == 0 or r == 3 or c == 3 then m:lock(p, "xyz") end
    grid[#grid + 1] = p
  end
end
local patch = m:quad_grid{ particles = grid, rows = 4, cols = 4, EA = 100, prestress = 500, line_mass = 1 }
local ok, mr = m:apply(tendril.rules.multires, patch, { factor = 3 })
assert(ok)
m:step(40)
assert(m:apply(tendril.rules.refine, mr))
m:step(40)
assert(m:apply(tendril.rules.coarsen, mr))
m:step(20)
assert(m:apply(tendril.rules.refine, mr))
m:step(10)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  Replayed replayed(dir / "journal.txt");
  const Model& model = replayed.model;
  CHECK(model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
  CHECK(model.particle_count() == 100);  // 10 x 10 after a factor-3 split of 3 x 3 quads
  CHECK(model.block_count() == 1);
}
