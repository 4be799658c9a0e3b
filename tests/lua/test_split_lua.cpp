// Rules 16-17, m:rest_length and the sliding joint agent replay from the
// journal bit for bit.
#include <doctest/doctest.h>

#include <sstream>

#include "scene_files.hpp"

using namespace tendril;

TEST_CASE("split, rest_length and a sliding joint replay from the journal") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-split-replay";
  const std::string scene = R"(
local m = tendril.model()
local pts = {}
for i = 0, 8 do pts[#pts + 1] = { 0.5 * i, 0, 0 } end
local beam = m:beam{ points = pts, EA = 1e6, EI = 10, line_mass = 1 }
local ps = m:particles(beam)
m:lock(ps[1], "all")
m:lock(ps[9], "all")
local anchor = m:particle{ 1, 1, 0 }
m:lock(anchor, "all")
local cable = m:cable(anchor, ps[3], { EA = 1e4 })
local joint = tendril.agents.sliding_joint{ model = m, beam = beam, at = ps[3], connection = cable }
joint:slide(0.8)
assert(m:state(joint:particle()) == "volatile")
m:step(10)
joint:slide(0.2)
assert(m:state(joint:particle()) == "shared" and math.abs(joint:position() - 2.0) < 1e-9)
m:step(10)
local q, other = m:split(beam, ps[7])
assert(m:count().beams == 2 and #m:particles(other) == 3)
m:rest_length(ps[1], ps[2], 0.45)
local ok = m:apply(tendril.rules.break_shared, beam, joint:particle())
assert(ok and m:count().beams == 3)
m:step(10)
m:check()
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  SceneOptions options;
  for (const char* name : {"vector.lua", "joints.lua"}) {  // the agents the scene needs
    std::ifstream src(std::filesystem::path(TENDRIL_SOURCE_DIR) / "agents" / name);
    std::stringstream text;
    text << src.rdbuf();
    options.preload.push_back({std::string("agents/") + name, text.str()});
  }
  std::string error;
  const int rc = test::run_scene_in(dir, scene, &error, options);
  INFO(error);
  REQUIRE(rc == 0);
  INFO(error);
  REQUIRE(error == "");
  const test::Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  CHECK(replayed.xml() == test::slurp(dir / "live.xml"));
  CHECK(replayed.model.block_count(BlockKind::Beam) == 3);
}
