// The integrator "auto" in a journal: a scene's runs to equilibrium take
// Newton's steps (between rules fired at equilibrium too; a run Newton
// stalls on goes on with Leapfrog's), its m:step Leapfrog's; the journal writes which ("newton_steps N" apart from
// "steps N") and replays to the same model bit for bit. A format-1 journal
// (written while Leapfrog was the default) replays with Leapfrog.
#include <doctest/doctest.h>

#include <sstream>

#include "scene_files.hpp"

using namespace tendril;
using namespace tendril::test;

TEST_CASE("auto: a journal names the steps taken as Newton's and replays them bit for bit") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-auto-journal";
  const std::string scene = R"lua(
local m, grid, n = tendril.model(), {}, 8
for r = 0, n - 1 do
  for c = 0, n - 1 do
    local p = m:particle{ c, r, 0 }
    grid[#grid + 1] = p
    if r == 0 or c == 0 or r == n - 1 or c == n - 1 then m:lock(p, "xyz") else m:load(p, { 0, 0, -1 }) end
  end
end
m:quad_grid{ particles = grid, rows = n, cols = n, EA = 1e5, prestress = 1e3 }
local first = m:run{ tolerance = 1e-8 }
assert(first.converged and first.steps < 10 and m:settings().phase == "newton")
m:step(5)
assert(m:settings().phase == "leapfrog")
m:load(grid[20], { 0, 0, -50 })
local second = m:run{ tolerance = 1e-8 }
assert(second.converged and m:settings().phase == "newton")
-- A rule at equilibrium (twice): the run takes Newton's steps between.
local heavier = tendril.rule{ name = "heavier", production = function(m) m:load(grid[28], { 0, 0, -20 }) end }
m:trigger{ rule = heavier, on = "equilibrium", max = 2 }
local grown = m:run{ tolerance = 1e-8 }
assert(grown.converged and grown.steps < 30 and m:settings().phase == "newton", grown.steps)
-- A chain of cables at rest length, loaded across: no transverse
-- stiffness, so Newton stalls and Leapfrog finishes the run.
local c0 = m:particle{ 0, -3, 0 }
local c1 = m:particle{ 1, -3, 0 }
local c2 = m:particle{ 2, -3, 0 }
m:lock(c0, "xyz"); m:lock(c2, "xyz")
m:cable(c0, c1, { EA = 1e4 }); m:cable(c1, c2, { EA = 1e4 })
m:load(c1, { 0, 0, -10 })
local third = m:run{ tolerance = 1e-6, max_steps = 200000 }
assert(third.converged and third.steps > 10 and m:settings().phase == "leapfrog", third.steps)
assert(m:position(c1)[3] < -0.01)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  const std::string journal = slurp(dir / "journal.txt");
  CHECK(journal.rfind("# tendril journal 2:", 0) == 0);
  // newton_steps, then Leapfrog's 5, then newton_steps again, and between
  // the rule's loads; the chain's run: one Newton step that stalled, then
  // Leapfrog's.
  std::istringstream lines(journal);
  std::vector<std::string> stepping;
  int loads = 0;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("steps ", 0) == 0 || line.rfind("newton_steps ", 0) == 0) stepping.push_back(line);
    loads += line.rfind("load ", 0) == 0;
  }
  REQUIRE(stepping.size() >= 6);
  CHECK(stepping[0].rfind("newton_steps ", 0) == 0);
  CHECK(stepping[1] == "steps 5");
  for (std::size_t k = 2; k + 2 < stepping.size(); ++k) CHECK(stepping[k].rfind("newton_steps ", 0) == 0);
  CHECK(stepping[stepping.size() - 2] == "newton_steps 1");
  CHECK(stepping.back().rfind("steps ", 0) == 0);
  CHECK(loads == 36 + 1 + 2 + 1);  // the net's interior, grid[20]'s, the rule's two, the chain's
  Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
  CHECK(std::string(integrator_name(replayed.solver.settings.integrator)) == "auto");
}

TEST_CASE("auto: a format-1 journal steps with Leapfrog, its default") {
  Model m1, m2;
  Solver s1(m1), s2(m2);
  const std::string body = "particle 0x0p+0 0x0p+0 0x0p+0\nparticle 0x1p+0 0x0p+0 0x0p+0\nlock 0 7\n"
                           "cable 0 1 0x1.388p+13 0x0p+0 0x0p+0 0x0p+0 0x0p+0\nload 1 0x1p+0 0x0p+0 0x0p+0\n"
                           "steps 20\n";
  std::istringstream v1("# tendril journal 1: replay with `tendril replay FILE`\n" + body), v2(body);
  replay_trace(v1, "v1", m1, s1);
  replay_trace(v2, "v2", m2, s2);
  CHECK(s1.settings.integrator == Integrator::Leapfrog);
  CHECK(s2.settings.integrator == Integrator::Auto);
  // Outside a run "auto" steps as Leapfrog: the same particles either way.
  CHECK(m1.particles.position[1] == m2.particles.position[1]);
  CHECK(m1.particles.position[1].x() != 1.0);
}
