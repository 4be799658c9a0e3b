// Two-way elastic bars (m:bar, rule 6 of kind "bar"): a two-bar truss whose
// horizontal bar is in compression carries the statically determinate bar
// forces; the bars replay bit for bit from the journal and survive the
// model database; a cable in the same place goes slack.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

// A bracket: supports A = (0, 0, 0) and B = (0, 0, h) on a wall, the node C
// at (a, 0, 0), bars A-C (horizontal) and B-C (diagonal), a load P down at
// C. Statics at C (small displacement): N_BC = P L / h (tension), N_AC =
// -P a / h (compression), L = sqrt(a^2 + h^2). The same statics in the
// deformed geometry (C where the solver put it, both bars slightly turned)
// is exact: the bar forces must satisfy it to the solver's tolerance,
// whatever the strain.
TEST_CASE("Lua: a two-bar truss with one bar in compression (m:bar) against its statics") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-bar-lua";
  const std::string scene = R"lua(
local a, h, P, EA = 2, 1, 1000, 1e7
local m = tendril.model()
local A, B, C = m:particle{ 0, 0, 0 }, m:particle{ 0, 0, h }, m:particle{ a, 0, 0 }
local ac = m:bar(A, C, { EA = EA })
local ok, bc = m:apply(tendril.rules.cable, B, C, { EA = EA }, "bar")  -- rule 6, kind "bar"
assert(ok and m:kind(bc) == "bar" and m:kind(ac) == "bar")
m:lock(A, "xyz")
m:lock(B, "xyz")
m:lock(C, "y")
m:load(C, { 0, 0, -P })
local r = m:run{ tolerance = 1e-6, max_steps = 400000 }
assert(r.converged, "not converged")
local n_ac, n_bc = m:forces(ac).segments[1].axial, m:forces(bc).segments[1].axial
local L = math.sqrt(a * a + h * h)
-- small-displacement statics: strains are ~2e-4, so 1e-3
assert(math.abs(n_ac / (-P * a / h) - 1) < 1e-3, "N_AC " .. n_ac)
assert(math.abs(n_bc / (P * L / h) - 1) < 1e-3, "N_BC " .. n_bc)
assert(not m:forces(ac).segments[1].slack)
-- exact statics in the deformed geometry: N_AC uA + N_BC uB = (0, P) in
-- the x-z plane, uA and uB the unit vectors from C to A and to B
local x = m:position(C)
local lA, lB = math.sqrt(x[1]^2 + x[3]^2), math.sqrt(x[1]^2 + (h - x[3])^2)
local uAx, uAz, uBx, uBz = -x[1] / lA, -x[3] / lA, -x[1] / lB, (h - x[3]) / lB
local det = uAx * uBz - uBx * uAz
assert(math.abs(n_bc / (uAx * P / det) - 1) < 1e-6, "deformed N_BC " .. n_bc)
assert(math.abs(n_ac / (-uBx * P / det) - 1) < 1e-6, "deformed N_AC " .. n_ac)
assert(m:count().two_way_bars == 2 and m:count().cables == 0)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
-- rule 7 deletes a bar too
local ok7 = m:apply(tendril.rules.delete_cable, ac)
assert(ok7 and m:count().two_way_bars == 1)
print(string.format("N_AC %.6f N (exact -2000), N_BC %.6f N (exact %.6f)", n_ac, n_bc, P * L / h))
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  const std::string live = slurp(dir / "live.xml");
  CHECK(replayed.xml() == live);
  CHECK(live.find("<bar id=\"0\"") != std::string::npos);
  Model loaded;
  SolverSettings settings;
  load_model_xml((dir / "live.xml").string(), loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(loaded.block_count(BlockKind::Bar) == 2);
  CHECK(loaded.bars.size() == 2);
  for (const Bar& b : loaded.bars.items) CHECK(b.tension_only == 0);
  CHECK(model_xml_string(loaded, settings) == live);
}

TEST_CASE("Lua: a cable where the truss needs a strut goes slack; bad bars are errors naming 'bar'") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-bar-lua-slack";
  const std::string scene = R"lua(
local m = tendril.model()
local A, B, C = m:particle{ 0, 0, 0 }, m:particle{ 0, 0, 1 }, m:particle{ 2, 0, 0 }
local ac = m:cable(A, C, { EA = 1e7 })
m:bar(B, C, { EA = 1e7 })
m:lock(A, "xyz")
m:lock(B, "xyz")
m:lock(C, "y")
m:load(C, { 0, 0, -1000 })
m:step(2000)
assert(m:forces(ac).segments[1].slack, "a cable cannot push")
local function fails(pattern, f, ...)
  local ok, err = pcall(f, m, ...)
  assert(not ok, "expected an error matching " .. pattern)
  assert(err:find(pattern), err)
end
fails("bar: .*EA", m.bar, A, C, { EA = 0 })
fails("bar: both ends are particle", m.bar, A, A, { EA = 1 })
fails("bar: unknown key", m.bar, A, C, { EA = 1, EI = 2 })
assert(not m:apply(tendril.rules.cable, A, C, { EA = 1 }, "strut"))
)lua";
  std::string error;
  CHECK(run_scene_in(dir, scene, &error) == 0);
  CHECK(error == "");
}
