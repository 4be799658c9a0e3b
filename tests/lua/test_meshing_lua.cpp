// The meshing layer from Lua (grammar/lua_meshing.cpp, the patch rules of
// grammar/rules/library.lua): a scene that paves, subdivides and projects is
// rebuilt bit for bit from its journal and its model database round-trips;
// bad input is an error naming the method and leaves the model as it was;
// the rules' axioms and productions; quality and triangulation figures.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene_files.hpp"

using namespace tendril;

namespace {

std::filesystem::path work_dir() {
  auto dir = std::filesystem::temp_directory_path() / "tendril-meshing-lua";
  std::filesystem::create_directories(dir);
  return dir;
}

using test::slurp;

// Runs `code` as scene `name` writing into work_dir(); returns the error text.
std::string run(const std::string& name, const std::string& code) {
  const auto path = work_dir() / name;
  std::ofstream(path) << code;
  SceneOptions options;
  options.progress = false;
  options.out_dir = work_dir().string();
  std::string error;
  const int rc = run_scene(path.string(), options, &error);
  CHECK((rc == 0) == error.empty());
  return error;
}

// A closed ring beam of n particles on a circle (wave: a saddle), in Lua.
const char* kRing = R"(
local function ring(m, n, r, wave, z)
  local pts = {}
  for i = 0, n - 1 do
    local t = 2 * math.pi * i / n
    pts[#pts + 1] = { r * math.cos(t), r * math.sin(t), (z or 0) + (wave or 0) * math.cos(2 * t) }
  end
  return m:beam{ points = pts, closed = true, EA = 1e6, EI = 50 }
end
)";

}  // namespace

TEST_CASE("a scene that paves, subdivides and projects replays bit for bit") {
  const std::string error = run("replay_paving.lua", std::string(kRing) + R"lua(
local m = tendril.model()
m:gravity{ 0, 0, -9.81 }
local rim = ring(m, 24, 3, 0.5)
local ps = m:particles(rim)
for i = 1, #ps, 6 do m:lock(ps[i], "xyz") end
m:step(40)                                   -- the loop is no longer where it was built
local patch = m:pave{ particles = ps, EA = 2e3, prestress = 20, line_mass = 0.1 }
assert(m:kind(patch) == "patch" and m:state(ps[2]) == "shared")
local failing = tendril.rule{ name = "pave then fail", production = function(m)
  m:pave{ particles = ps, EA = 1e3 }
  error("rolled back")
end }
assert(not m:apply(failing))
m:run{ tolerance = 1e-3, max_steps = 400 }
-- rule 19 on a four-particle loop, rule 25 on it (moves its interior)
local quad = { m:particle{ 4, 0, 0 }, m:particle{ 6, 0, 0 }, m:particle{ 6, 2, 0.5 }, m:particle{ 4, 2, 0 } }
local cc = m:catmull_clark{ particles = quad, levels = 1, EA = 1e3, line_mass = 0.5 }  -- sags
for _, p in ipairs(quad) do m:lock(p, "xyz") end
m:step(30)
local ok, finer = m:apply(tendril.rules.patch_refine, cc, { prestress = 3 })
assert(ok and #m:particles(finer) == 81)
-- rule 22: a tube between the rim and a smaller ring above it
local top = m:particles(ring(m, 24, 1.5, 0, 2))
local tube = m:project{ from = ps, to = top, rows = 2, closed = true, EA = 500 }
m:step(25)
-- rule 20 with a hole: an annulus between two rings above the tube
local outer = m:particles(ring(m, 24, 3, 0, 4))
local inner = m:particles(ring(m, 12, 1.5, 0.2, 4))
local annulus = m:pave{ particles = outer, holes = { inner }, EA = 500, prestress = 5 }
assert(m:state(inner[1]) == "shared")
m:step(25)
-- rule 22 between two patches' interiors: cuts both, then the tube
local function grid(z)
  local ps = {}
  for r = 0, 4 do for c = 0, 4 do ps[#ps + 1] = m:particle{ 20 + c, r, z } end end
  m:quad_grid{ particles = ps, rows = 5, cols = 5, EA = 1e3, prestress = 5 }
  for i = 1, 5 do m:lock(ps[i], "xyz") end
  return ps
end
local low, high = grid(0), grid(2)
local ok, between = m:apply(tendril.rules.patch_tube, { between = { low[13], high[13] }, rows = 2, EA = 50, prestress = 5 })
assert(ok and m:kind(between) == "patch")
m:step(25)
assert(m:count().patches == 7)   -- patch_refine deleted cc (rule 27)
m:check()
m:save(tendril.out("paving_live.xml"))
m:save_journal(tendril.out("paving_journal.txt"))
)lua");
  REQUIRE(error == "");
  const test::Replayed replayed(work_dir() / "paving_journal.txt");
  const Model& model = replayed.model;
  CHECK(model.check() == "");
  const std::string live = slurp(work_dir() / "paving_live.xml");
  CHECK(live.find("<quad ") != std::string::npos);  // the paved patch is not a grid
  const std::string lines = slurp(work_dir() / "paving_journal.txt");
  CHECK(lines.find("\nposition ") != std::string::npos);  // rule 25 moved the sagged interior
  CHECK(lines.find("\npatch ") != std::string::npos);
  CHECK(replayed.xml() == live);
  CHECK(lines.find("\ndelete ") != std::string::npos);  // patch_refine deleted the old patch
  CHECK(lines.find("\nremove_from_patch ") != std::string::npos);  // rule 22 cut both grids
  CHECK(model.block_count(BlockKind::Patch) == 7);

  // The model database holds any patch: load, save, same bytes.
  Model loaded;
  SolverSettings settings;
  load_model_xml((work_dir() / "paving_live.xml").string(), loaded, settings);
  CHECK(loaded.check() == "");
  CHECK(model_xml_string(loaded, settings) == live);
}

TEST_CASE("bad meshing input is an error naming the method; the model is left as it was") {
  const std::string error = run("bad_meshing.lua", std::string(kRing) + R"lua(
local m = tendril.model()
local rim = ring(m, 12, 2)
local ps = m:particles(rim)
local grid = m:project{ from = { ps[1], ps[2], ps[3] }, to = { ps[9], ps[8], ps[7] }, rows = 1, EA = 10 }
local small = { m:particle{ 0.5, 0, 0 }, m:particle{ 0, 0.5, 0 }, m:particle{ -0.5, 0, 0 }, m:particle{ 0, -0.5, 0 } }
local wide = { m:particle{ 1, 0, 0 }, m:particle{ 0, 1, 0 }, m:particle{ -1, 0, 0 }, m:particle{ 0, -1, 0 } }
m:save(tendril.out("bad_before.xml"))
local function fails(expect, f)
  local ok, err = pcall(f)
  assert(not ok, "should fail: " .. expect)
  assert(err:find("bad_meshing.lua:", 1, true), err)
  assert(err:find(expect, 1, true), "expected '" .. expect .. "' in: " .. err)
end
local crossed = { ps[1], ps[2], ps[3], ps[6], ps[5], ps[4], ps[7], ps[8], ps[9], ps[10] }
fails("pave: needs at least 8 particles, got 3", function() m:pave{ particles = { ps[1], ps[2], ps[3] }, EA = 1 } end)
fails("pave: needs an even number of particles", function()
  m:pave{ particles = { ps[1], ps[2], ps[3], ps[4], ps[5], ps[6], ps[7], ps[8], ps[9] }, EA = 1 }
end)
fails("pave: the loop, projected on its best-fit plane, intersects itself", function() m:pave{ particles = crossed, EA = 1 } end)
fails("pave: particle 0 appears twice in the loop", function()
  m:pave{ particles = { ps[1], ps[2], ps[3], ps[4], ps[5], ps[6], ps[7], ps[1] }, EA = 1 }
end)
fails("pave: 'EA' is required", function() m:pave{ particles = ps } end)
fails("pave: unknown key 'levels'", function() m:pave{ particles = ps, EA = 1, levels = 2 } end)
fails("pave: 'holes' must be a list of particle lists", function() m:pave{ particles = ps, holes = 3, EA = 1 } end)
fails("pave: 'holes' must be a list of particle lists (item 1 is not a list)", function()
  m:pave{ particles = ps, holes = { ps[1] }, EA = 1 }
end)
fails("pave: hole 2 and hole 1 are nested", function() m:pave{ particles = ps, holes = { small, wide }, EA = 1 } end)
fails("pave: particle 1 appears twice in the loops", function() m:pave{ particles = ps, holes = { { ps[2], small[1], small[2] } }, EA = 1 } end)
fails("catmull_clark: needs at least 3 particles, got 2", function() m:catmull_clark{ particles = { ps[1], ps[2] }, EA = 1 } end)
fails("catmull_clark: 'levels' must be an integer from 0 to 8", function()
  m:catmull_clark{ particles = ps, levels = 9, EA = 1 }
end)
fails("project: the sequences differ in length (3 and 2)", function()
  m:project{ from = { ps[1], ps[2], ps[3] }, to = { ps[5], ps[6] }, EA = 1 }
end)
fails("project: each sequence needs at least 3 particles when closed, got 2", function()
  m:project{ from = { ps[1], ps[2] }, to = { ps[5], ps[6] }, closed = true, EA = 1 }
end)
fails("project: particle 0 (B[0]) appears twice in A and B", function()
  m:project{ from = { ps[1], ps[2] }, to = { ps[1], ps[6] }, EA = 1 }
end)
fails("subdivide_patch: argument 2: expected a patch, got a beam", function() m:subdivide_patch(rim) end)
fails("subdivide_patch: 'EA' must be > 0", function() m:subdivide_patch(grid, { EA = -1 }) end)
fails("quality: block 0 is a beam, not a patch", function() m:quality(rim) end)
fails("triangulation: block 0 is a beam, not a patch", function() m:triangulation(rim) end)
assert(m:count().patches == 1 and m:count().particles == 23)
m:check()
m:save(tendril.out("bad_after.xml"))
)lua");
  CHECK(error == "");
  CHECK(slurp(work_dir() / "bad_before.xml") == slurp(work_dir() / "bad_after.xml"));
}

TEST_CASE("the patch rules 19-22 and 25: axioms, productions, quality figures") {
  const std::string error = run("patch_rules.lua", std::string(kRing) + R"lua(
local m = tendril.model()
local R = tendril.rules
local near = function(a, b) return math.abs(a - b) < 1e-9 end

-- rule 20 on a 4 x 4 square of unit spacing: the unit grid
local sq = {}
for i = 0, 3 do sq[#sq + 1] = m:particle{ i, 0, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 4, i, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 4 - i, 4, 0 } end
for i = 0, 3 do sq[#sq + 1] = m:particle{ 0, 4 - i, 0 } end
local ok, paved = m:apply(R.patch_paving, { particles = sq, EA = 1e3 })
assert(ok)
local q = m:quality(paved)
assert(q.quads == 16 and near(q.jacobian_min, 1) and near(q.jacobian_mean, 1))
assert(near(q.angle_min, 90) and near(q.angle_max, 90))
assert(q.irregular == 0 and q.interior_vertices == 9 and q.irregular_vertices == 0)
-- its CST triangulation: 32 triangles, every first side parallel to x or every one to y
local t = m:triangulation(paved)
assert(#t.triangles == 32 and #t.seams == 0 and t.warp_edges == 20 and t.weft_edges == 20)
local function axis(tri)
  local a, b = m:position(tri[1]), m:position(tri[2])
  return a[2] == b[2] and "x" or "y"
end
for _, tri in ipairs(t.triangles) do assert(axis(tri) == axis(t.triangles[1])) end
t = m:triangulation(paved, { warp = { 0, 1, 0 } })
assert(axis(t.triangles[1]) == "y")

-- rule 25: one Catmull-Clark step; the old patch goes (rule 27)
local before = m:count().patches
local ok, finer = m:apply(R.patch_refine, paved)
assert(ok and m:quality(finer).quads == 64 and m:count().patches == before)

-- rule 19 on a triangle: 3 quads, then 12 with a level more
local tri = { m:particle{ 10, 0, 0 }, m:particle{ 12, 0, 0 }, m:particle{ 11, 2, 0 } }
local ok, cc = m:apply(R.patch_subdivision, { particles = tri, levels = 1, EA = 1e3 })
assert(ok and m:quality(cc).quads == 12 and m:quality(cc).irregular_vertices == 1)   -- the centre, valence 3
local ok, err = pcall(m.triangulation, m, cc)
assert(not ok and err:find("valence 3", 1, true), err)
assert(#m:triangulation(cc, { seams = true }).seams > 0)

-- rule 21 between two rows of four, two interior rows: 3 x 3 quads
local a, b = {}, {}
for i = 0, 3 do a[#a + 1] = m:particle{ 20 + i, 0, 0 }; b[#b + 1] = m:particle{ 20 + i, 3, 1 } end
local ok, proj = m:apply(R.patch_projection, { from = a, to = b, rows = 2, EA = 1e3 })
assert(ok and m:quality(proj).quads == 9 and #m:particles(proj) == 16)

-- rule 22: a tube between two rings of 8
local low, high = m:particles(ring(m, 8, 1, 0, 10)), m:particles(ring(m, 8, 1, 0, 12))
local ok, tube = m:apply(R.patch_tube, { from = low, to = high, rows = 1, EA = 1e3 })
assert(ok and m:quality(tube).quads == 16 and #m:particles(tube) == 24)
assert(m:state(low[1]) == "shared")

-- axioms refuse, failing productions roll back
local n = m:count().particles
local ok, why = m:apply(R.patch_paving, { particles = { sq[1], sq[2], sq[3], sq[4], sq[5], sq[6] }, EA = 1 })
assert(not ok and why:find("'particles' has 6 particles, needs at least 8", 1, true), why)
ok, why = m:apply(R.patch_subdivision, { EA = 1 })
assert(not ok and why:find("needs options with 'particles'", 1, true), why)
ok, why = m:apply(R.patch_projection, { from = a, to = { b[1] }, EA = 1 })
assert(not ok and why:find("'from' has 4 particles and 'to' 1", 1, true), why)
ok, why = m:apply(R.patch_tube, { from = { a[1], a[2] }, to = { b[1], b[2] }, EA = 1 })
assert(not ok and why:find("needs at least 3", 1, true), why)
ok, why = m:apply(R.patch_refine, m:blocks(low[1])[1])
assert(not ok and why:find("is a beam, not a patch", 1, true), why)
local crossed = { sq[1], sq[2], sq[3], sq[4], sq[5], sq[6], sq[8], sq[7] }
ok, why = m:apply(R.patch_paving, { particles = crossed, EA = 1 })
assert(not ok and why:find("rolled back", 1, true) and why:find("pave: the loop", 1, true), why)
assert(m:count().particles == n)
m:check()
)lua");
  CHECK(error == "");
}

TEST_CASE("patch rules 23, 24, 26 and 27 from Lua replay bit for bit from the journal") {
  const std::string error = run("replay_patch_ops.lua", R"lua(
local m = tendril.model()
local R = tendril.rules
local g = {}
for r = 0, 2 do for c = 0, 4 do g[r * 5 + c + 1] = m:particle{ c, r, 0.1 * c * r } end end
local function cells(c0, c1)
  local ps = {}
  for r = 0, 2 do for c = c0, c1 do ps[#ps + 1] = g[r * 5 + c + 1] end end
  return m:quad_grid{ particles = ps, rows = 3, cols = c1 - c0 + 1, EA = 1e3, prestress = 5 }
end
local a, b = cells(0, 2), cells(2, 4)
assert(m:merge_patches(a, b) == a and m:count().patches == 1)
local ok, why = pcall(m.merge_patches, m, a, a)
assert(not ok and why:find("both arguments", 1, true), why)
m:remove_from_patch(g[1])
local anchor = m:particle{ 2, 1, 2 }
m:cable(anchor, g[8], { EA = 1e4 })
assert(m:apply(R.patch_remove_shared, g[8], a))
assert(m:count().patches == 2)
m:lock(g[5], "xyz"); m:lock(g[15], "xyz"); m:lock(g[11], "xyz"); m:lock(anchor, "xyz")
m:step(20)
assert(m:apply(R.patch_delete, m:blocks(g[6])[1]))
m:step(5)
assert(m:count().patches == 1)
m:check()
m:save(tendril.out("patch_ops_live.xml"))
m:save_journal(tendril.out("patch_ops_journal.txt"))
)lua");
  REQUIRE(error == "");
  const test::Replayed replayed(work_dir() / "patch_ops_journal.txt");
  const Model& model = replayed.model;
  CHECK(model.check() == "");
  const std::string lines = slurp(work_dir() / "patch_ops_journal.txt");
  CHECK(lines.find("\nmerge_patches ") != std::string::npos);
  CHECK(lines.find("\nremove_from_patch ") != std::string::npos);
  CHECK(lines.find("\ndelete ") != std::string::npos);
  CHECK(replayed.xml() == slurp(work_dir() / "patch_ops_live.xml"));
  CHECK(model.block_count(BlockKind::Patch) == 1);
}
