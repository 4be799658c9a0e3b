// m:assembly() lists every production, also those that create or delete
// nothing (thesis 6.2, 6.3.1: the assembly sequence): rule 9 growing a beam
// onto an existing particle, a rule that only tightens a cable; and names the
// blocks a production connected or disconnected.
#include <doctest/doctest.h>

#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("the assembly sequence lists productions that create nothing, with the blocks they changed") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-assembly";
  const std::string scene = R"(
local m = tendril.model()
local R = tendril.rules
local rod = m:beam{ points = {{0,0,0}, {1,0,0}, {2,0,0}}, EA = 1e6, EI = 10 }
local post = m:beam{ points = {{3,0,0}, {3,0,1}}, EA = 1e6, EI = 10 }
local ps, top = m:particles(rod), m:particles(post)
assert(m:apply(R.grow, rod, ps[3], top[1]))           -- rule 9 onto the post: nothing created
local anchor = m:particle{ 1, 0, 2 }
local tie = m:cable(anchor, ps[2], { EA = 1e4 })
local tighten = tendril.rule{ name = "tighten", production = function(m, c)
  local q = m:particles(c)
  m:rest_length(q[1], q[2], 0.9 * m:rest_length(q[1], q[2]))
end }
assert(m:apply(tighten, tie))                          -- only a rest length changes
local joined = m:merge{ top[2], anchor }               -- rule 3: connects post and cable
m:explode(joined)                                      -- rule 4: disconnects them again
local lines = {}
for line in m:assembly():gmatch("[^\n]+") do lines[#lines + 1] = line end
local function row(n) local f = {} for x in lines[n + 1]:gmatch("[^\t]+") do f[#f + 1] = x end return f end
assert(lines[1] == "#  step  time  rule  arguments  created  deleted  changed", lines[1])
-- 1, 2: the beams (3 + 2 particles each, then the beam); then grow, particle, cable, tighten, merge, explode
local rule9 = row(3)
assert(rule9[4] == "rule 9: grow a spline beam from its end particle to a particle", rule9[4])
assert(rule9[6] == "-" and rule9[7] == "-" and rule9[8] == "b0", table.concat(rule9, "|"))
local t = row(6)
assert(t[4] == "tighten" and t[6] == "-" and t[7] == "-" and t[8] == "-", table.concat(t, "|"))
local merge, explode = row(7), row(8)
assert(merge[4] == "merge" and merge[8] == "b1 b2", table.concat(merge, "|"))
assert(explode[4] == "explode" and explode[8] == "b1 b2", table.concat(explode, "|"))
assert(#lines == 9)
local j = m:journal()
assert(#j == 8 and j[3].changed_blocks[1] == 0)
m:save_journal(tendril.out("journal.txt"))
m:save(tendril.out("live.xml"))
)";
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error);
  INFO(error);
  REQUIRE(rc == 0);
  const std::string journal = test::slurp(dir / "journal.txt");
  CHECK(journal.find("# 3\t0\t0\trule 9: grow") != std::string::npos);
  CHECK(test::replays_to_live(dir));
}
