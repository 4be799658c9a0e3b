// m:formulation on patches (thesis 5.5.2.2) from Lua: bars -> CST form-finding
// -> CST analysis -> bars while the solver runs; the journal replays it bit
// for bit, the model database round-trips it, bad options are refused with
// the model unchanged.
#include <doctest/doctest.h>

#include <sstream>

#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::slurp;

namespace {

const char* kTube = R"(
local m = tendril.model()
local function ring(z, n)
  local ps = {}
  for i = 0, n - 1 do
    local t = 2 * math.pi * i / n
    ps[#ps + 1] = m:particle{ math.cos(t), math.sin(t), z }
    m:lock(ps[#ps], "xyz")
  end
  return ps
end
local tube = m:project{ from = ring(-0.5, 12), to = ring(0.5, 12), rows = 3, closed = true, EA = 10, prestress = 1 }
)";

}  // namespace

TEST_CASE("lua: switching a patch bars -> CST -> bars replays and round-trips bit for bit") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-patch-formulation";
  std::string scene = kTube;
  scene += R"(
m:step(20)
m:formulation(tube, "cst", { stress = { 2, 1 }, warp = { 0, 0, 1 } })
m:step(200)
m:save(tendril.out("form.xml"))
m:formulation(tube, "cst", { stress = { 2, 1 }, analysis = { dxx = 300, dyy = 200, dxy = 40, dyx = 30, G = 10 } })
m:load(m:particles(tube)[30], { 0.01, 0.02, 0 })
m:step(200)
m:save(tendril.out("analysis.xml"))
m:formulation(tube, "bars")
m:step(30)
m:formulation(tube, "cst", { stress = { 1, 1 }, warp = { 1, 0, 0 } })
m:step(30)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)";
  std::string error;
  REQUIRE(test::run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  // Replay.
  const Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
  CHECK(replayed.model.csts.size() == 2u * 12 * 4);
  // The database: each saved state loads into a valid model that saves the same bytes.
  for (const char* name : {"form.xml", "analysis.xml", "live.xml"}) {
    CAPTURE(name);
    const std::string text = slurp(dir / name);
    CHECK(text.find("<triangle") != std::string::npos);
    Model loaded;
    SolverSettings settings;
    load_model_xml_string(text, loaded, settings, name);
    CHECK(loaded.check() == "");
    CHECK(loaded.csts.size() == 2u * 12 * 4);
    CHECK(model_xml_string(loaded, settings) == text);
  }
  CHECK(slurp(dir / "analysis.xml").find("membrane=\"analysis\"") != std::string::npos);
  CHECK(slurp(dir / "analysis.xml").find(" l1=\"") != std::string::npos);
}

TEST_CASE("lua: bad patch formulations are refused and change nothing") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-patch-formulation-bad";
  std::string scene = kTube;
  scene += R"(
m:step(10)
m:save(tendril.out("before.xml"))
local function refused(words, ...)
  local ok, err = pcall(m.formulation, m, tube, ...)
  assert(not ok, "accepted: " .. words)
  assert(err:find(words, 1, true), err)
  assert(m:formulation(tube) == "bars")
end
refused("a patch's formulation is \"bars\" or \"cst\"", 6)
refused("not \"membrane\"", "membrane")
refused("stress", "cst", {})
refused("unknown key 'sigma'", "cst", { sigma = 1 })
refused("must be a table of two numbers", "cst", { stress = 1 })
refused("the warp and weft stresses must be finite numbers >= 0", "cst", { stress = { -1, 1 } })
refused("needs dxx and dyy", "cst", { analysis = { dxy = 1 } })
refused("dxx dyy must exceed dxy dyx", "cst", { analysis = { dxx = 1, dyy = 1, dxy = 5 } })
refused("\"bars\" takes no options", "bars", { stress = { 1, 1 } })
m:save(tendril.out("after.xml"))
m:formulation(tube, "cst", { stress = { 1, 1 } })
local kind, options = m:formulation(tube)
assert(kind == "cst" and options.stress[2] == 1)
local ok, err = pcall(m.remove_from_patch, m, m:particles(tube)[30])
assert(not ok and err:find("back to bars first", 1, true), err)
print("refused as expected")
)";
  std::string error;
  CHECK(test::run_scene_in(dir, scene, &error) == 0);
  CHECK(error == "");
  CHECK(slurp(dir / "before.xml") == slurp(dir / "after.xml"));
}
