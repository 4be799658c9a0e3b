// m:import and tendril.import: geometry drawn in a CAD tool runs like a
// built model (a polyline imported as a beam relaxes to the very numbers of
// the same beam built with m:beam); tendril's OBJ and PLY import back to the
// same particles and blocks; the import is one production that replays;
// unmapped or unmappable geometry is refused naming the group.
#include <doctest/doctest.h>

#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

TEST_CASE("Lua: a polyline from a CAD tool imported as a beam runs like the beam built in Lua") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-import-beam";
  const std::string scene = R"lua(
-- A cantilever drawn as a polyline (what Rhino writes for a curve: o, v, l)
-- and a cable from a second object.
local lines = { "# Rhino", "o rod" }
for i = 0, 10 do lines[#lines + 1] = string.format("v %.17g 0 0", 0.4 * i) end
lines[#lines + 1] = "l 1 2 3 4 5 6 7 8 9 10 11"
lines[#lines + 1] = "o stay"
lines[#lines + 1] = "v 0 0 2"
lines[#lines + 1] = "l 12 11"
tendril.write_file(tendril.out("frame.obj"), table.concat(lines, "\n") .. "\n")

local geo = tendril.import(tendril.out("frame.obj"))
assert(#geo.vertices == 12 and #geo.groups == 2 and geo.groups[1].name == "rod" and #geo.groups[1].lines[1] == 11)

local function finish(m, rod, stay_top)
  local ps = m:particles(rod)
  m:lock(ps[1], "xyz")
  m:clamp(ps[1], rod, { 1, 0, 0 })
  m:lock(stay_top, "xyz")
  for _, p in ipairs(ps) do m:lock(p, "y") end
  m:load(ps[6], { 0, 0, -500 })
  local r = m:run{ tolerance = 1e-8, max_steps = 1000000 }
  assert(r.converged)
  return m:position(ps[#ps]), m:position(ps[6]), r.steps
end

local a = tendril.model()
local made = a:import(tendril.out("frame.obj"), { groups = { rod = { kind = "beam", EA = 1e7, EI = 2000 },
                                                            stay = { kind = "cable", EA = 1e6 } } })
assert(#made.particles == 12 and #made.blocks == 2 and a:kind(made.groups.rod[1]) == "beam")
assert(a:kind(made.groups.stay[1]) == "cable")
local tip_a, mid_a, steps_a = finish(a, made.groups.rod[1], made.particles[12])

local b = tendril.model()
local pts = {}
for i = 0, 10 do pts[#pts + 1] = { 0.4 * i, 0, 0 } end
local ps = {}
for _, x in ipairs(pts) do ps[#ps + 1] = b:particle(x) end
local top = b:particle{ 0, 0, 2 }                  -- the import makes every vertex first
local rod = b:beam{ particles = ps, EA = 1e7, EI = 2000 }
b:cable(top, b:particles(rod)[11], { EA = 1e6 })
local tip_b, mid_b, steps_b = finish(b, rod, top)
print(string.format("imported: tip z %.12f, %d steps; built: tip z %.12f, %d steps", tip_a[3], steps_a, tip_b[3], steps_b))
assert(steps_a == steps_b)
for k = 1, 3 do assert(tip_a[k] == tip_b[k] and mid_a[k] == mid_b[k], "imported and built differ") end
assert(mid_a[3] < -1e-3, "the load bent it")
a:save(tendril.out("live.xml"))
a:save_journal(tendril.out("journal.txt"))
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
}

TEST_CASE("Lua: tendril's OBJ and PLY import back to the same particles and blocks") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-import-round-trip";
  const std::string scene = R"lua(
local m = tendril.model()
local rod = m:beam{ points = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } }, EA = 1e6, EI = 100 }
m:cable(m:particle{ 0, 0, 2 }, m:particles(rod)[4], { EA = 1e5 })
m:bar(m:particle{ 1, 0, 2 }, m:particles(rod)[2], { EA = 1e5 })
m:beam{ centre = { 5, 0, 0 }, normal = { 0, 0, 1 }, radius = 1, segments = 8, EA = 1e6, EI = 10 }
local g = {}
for i = 0, 2 do for j = 0, 2 do g[#g + 1] = m:particle{ 8 + i, j, 0 } end end
m:quad_grid{ particles = g, rows = 3, cols = 3, EA = 1e4, prestress = 10 }
m:particle{ 0, 5, 5 }                                     -- isolated: a vertex of nothing
m:save_obj(tendril.out("a.obj"))
m:save_ply(tendril.out("a.ply"))
local sections = { beam = { kind = "beam", EA = 1e6, EI = 100 }, cable = { kind = "cable", EA = 1e5 },
                   bar = { kind = "bar", EA = 1e5 }, patch = { kind = "patch", EA = 1e4, prestress = 10 } }
-- OBJ: groups named by kind and id (beam-0, cable-1, ...)
local groups = {}
for _, grp in ipairs(tendril.import(tendril.out("a.obj")).groups) do groups[grp.name] = sections[grp.name:match("^(%a+)")] end
local n = tendril.model()
n:import(tendril.out("a.obj"), { groups = groups })
n:save_obj(tendril.out("b.obj"))
-- PLY: groups by block id; the kinds as the model had them
local p = tendril.model()
local ply_groups = {}
for _, b in ipairs(m:blocks()) do ply_groups["block-" .. b.id] = sections[m:kind(b)] end
p:import(tendril.out("a.ply"), { groups = ply_groups })
p:save_obj(tendril.out("c.obj"))
local c, d, e = m:count(), n:count(), p:count()
for _, key in ipairs{ "particles", "beams", "cables", "two_way_bars", "patches" } do
  assert(c[key] == d[key] and c[key] == e[key], key)
end
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  const std::string original = slurp(dir / "a.obj");
  CHECK(slurp(dir / "b.obj") == original);
  CHECK(slurp(dir / "c.obj") == original);
}

TEST_CASE("Lua: geometry an import cannot map is refused naming the group, and nothing is made") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-import-refused";
  const std::string scene = R"lua(
tendril.write_file(tendril.out("t.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\ng rods\nl 1 2\ng skin\nf 1 2 3\n")
tendril.write_file(tendril.out("bad.obj"), "v 0 0 0\nl 1 7\n")
local m = tendril.model()
local function fails(pattern, file, mapping)
  local ok, err = pcall(m.import, m, tendril.out(file), mapping)
  assert(not ok, "expected an error matching " .. pattern)
  assert(err:find(pattern), err)
  assert(m:count().particles == 0, "a refused import left particles")
end
fails("import: group 'rods' has polylines: map them", "t.obj", {})
fails("import: group 'skin' has faces: map them", "t.obj", { lines = { kind = "beam", EA = 1, EI = 1 } })
fails("import: group 'skin' has a face of 3 vertices: a patch is made of quads", "t.obj",
      { lines = { kind = "cable", EA = 1 }, faces = { kind = "patch", EA = 1 } })
fails("import: 'lines': 'kind' must be", "t.obj", { lines = { kind = "rope", EA = 1 } })
fails("import: group 'rods' has polylines: they become", "t.obj", { groups = { rods = { kind = "patch", EA = 1 } } })
fails("bad.obj:2: vertex 7 is not among the 1 vertices so far", "bad.obj", {})
fails("import: unknown key", "t.obj", { line = {} })
-- skipping both groups makes the particles only
local made = m:import(tendril.out("t.obj"), { lines = { kind = "skip" }, faces = { kind = "skip" } })
assert(#made.particles == 4 and #made.blocks == 0)
)lua";
  std::string error;
  CHECK(run_scene_in(dir, scene, &error) == 0);
  CHECK(error == "");
}
