// Warp and weft prestress on a patch of bars (m:patch_prestress, issue 11):
// a square net held on its edges under nodal loads P, with T_warp along x
// and T_weft along y, is the anisotropic discrete membrane
//   T_w (z[i+1,j] - 2 z + z[i-1,j]) / a + T_f (z[i,j+1] - 2 z + z[i,j-1]) / a + P = 0
// (small slopes: the error is of order slope^2 = 1e-6 here), solved in the
// scene by Gauss-Seidel as the independent solution. The bars carry their
// family's prestress, the prestress survives the model database, a CST
// switch and back, and the journal.
#include <doctest/doctest.h>

#include "io/model_xml.hpp"
#include "model/model.hpp"
#include "scene_files.hpp"

using namespace tendril;
using test::Replayed;
using test::run_scene_in;
using test::slurp;

namespace {

const char* kNet = R"lua(
local n, a, P, Tw, Tf = 8, 1.0, 0.01, 20, 5
local m = tendril.model()
local grid = {}
for r = 0, n do for c = 0, n do grid[#grid + 1] = m:particle{ c * a, r * a, 0 } end end
local function at(r, c) return grid[r * (n + 1) + c + 1] end
local net = m:quad_grid{ particles = grid, rows = n + 1, cols = n + 1, EA = 1, prestress = 7 }
m:patch_prestress(net, { Tw, Tf }, { warp = { 1, 0, 0 } })
for r = 0, n do for c = 0, n do
  if r == 0 or c == 0 or r == n or c == n then m:lock(at(r, c), "xyz") else m:load(at(r, c), { 0, 0, -P }) end
end end
-- The bars before any step: x bars carry Tw, y bars Tf.
for _, e in ipairs(m:results(net).elements) do
  local pa, pb = m:position(e.a), m:position(e.b)
  local along_x = math.abs(pa[1] - pb[1]) > 0.5
  if math.abs(e.axial - (along_x and Tw or Tf)) > 1e-12 then error("bar axial " .. e.axial) end
end
local res = m:run{ tolerance = 1e-9, max_steps = 400000 }
assert(res.converged, "not converged: residual " .. res.residual)
-- The independent solution: the discrete anisotropic membrane equation.
local z = {}
for r = 0, n do z[r] = {} for c = 0, n do z[r][c] = 0 end end
for sweep = 1, 20000 do
  for r = 1, n - 1 do for c = 1, n - 1 do
    z[r][c] = (Tw * (z[r][c - 1] + z[r][c + 1]) + Tf * (z[r - 1][c] + z[r + 1][c]) - P * a) / (2 * (Tw + Tf))
  end end
end
local worst, centre = 0, -z[n // 2][n // 2]
for r = 1, n - 1 do for c = 1, n - 1 do
  worst = math.max(worst, math.abs(m:position(at(r, c))[3] - z[r][c]))
end end
print(string.format("warp/weft net: centre sag %.6e m (exact %.6e), worst %.2e of it, %d steps",
                    -m:position(at(n // 2, n // 2))[3], centre, worst / centre, res.steps))
assert(worst < 1e-3 * centre, "off the anisotropic membrane: " .. worst / centre)
-- The load goes mostly along the warp (x): one quad in from the edges it
-- crosses the net sags less than one quad in from the edges it runs along.
assert(-m:position(at(n // 2, 1))[3] < 0.8 * -m:position(at(1, n // 2))[3])
)lua";

}  // namespace

TEST_CASE("Lua: a net with warp and weft prestress sags as the anisotropic discrete membrane (1e-3)") {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-patch-prestress";
  std::string scene = kNet;
  scene += R"lua(
m:save(tendril.out("net.xml"))
-- Through a CST switch and back: the interior bars come back with their prestress.
m:formulation(net, "cst", { stress = { 2, 2 } })
m:formulation(net, "bars")
for _, e in ipairs(m:results(net).elements) do
  local pa, pb = m:position(e.a), m:position(e.b)
  local T = math.abs(pa[1] - pb[1]) > 0.5 and Tw or Tf
  if math.abs(e.axial - T) > 1e-3 * T then error("after the CST switch, bar axial " .. e.axial) end
end
m:step(5)
m:save(tendril.out("live.xml"))
m:save_journal(tendril.out("journal.txt"))
)lua";
  std::string error;
  REQUIRE(run_scene_in(dir, scene, &error) == 0);
  REQUIRE(error == "");
  const std::string text = slurp(dir / "net.xml");
  CHECK(text.find("prestress=\"20\"") != std::string::npos);
  Model loaded;
  SolverSettings settings;
  load_model_xml_string(text, loaded, settings, "net.xml");
  CHECK(loaded.check() == "");
  CHECK(model_xml_string(loaded, settings) == text);
  std::size_t warp = 0, weft = 0;
  for (const Bar& b : loaded.bars.items) {
    warp += b.prestress == 20;
    weft += b.prestress == 5;
  }
  CHECK(warp == 8u * 9);
  CHECK(weft == 8u * 9);
  const Replayed replayed(dir / "journal.txt");
  CHECK(replayed.model.check() == "");
  CHECK(replayed.xml() == slurp(dir / "live.xml"));
}

TEST_CASE("patch prestress: a seam takes the mean; a wrong or missing edge is refused and changes nothing") {
  Model m;
  std::vector<ParticleId> grid;
  for (int r = 0; r < 2; ++r)
    for (int c = 0; c < 3; ++c) grid.push_back(m.add_particle(Vec3(c, r, 0)));
  Section s;
  s.EA = 10;
  s.prestress = 1;
  const BlockId patch = m.add_quad_grid(grid, 2, 3, s);
  // Rows 0-1-2 and 3-4-5 warp, the three columns weft; 1-4 listed as both.
  const std::vector<Model::EdgePair> warp = {{0, 1}, {1, 2}, {3, 4}, {4, 5}, {1, 4}};
  const std::vector<Model::EdgePair> weft = {{0, 3}, {1, 4}, {2, 5}};
  const std::string before = model_xml_string(m, SolverSettings{});
  CHECK_THROWS_WITH(m.set_patch_prestress(patch, 4, 2, warp, {{0, 3}, {2, 5}, {0, 4}}),
                    "patch_prestress: particles 0 and 4 are not an edge of patch 0");
  CHECK_THROWS_WITH(m.set_patch_prestress(patch, 4, 2, warp, {{0, 3}}),
                    "patch_prestress: edge 2-5 of patch 0 is neither warp nor weft");
  CHECK_THROWS_WITH(m.set_patch_prestress(patch, -1, 2, warp, weft),
                    "patch_prestress: the warp and weft prestress must be finite numbers >= 0 [N]");
  CHECK(model_xml_string(m, SolverSettings{}) == before);
  m.set_patch_prestress(patch, 4, 2, warp, weft);
  CHECK(m.check() == "");
  for (const Bar& b : m.bars.items) {
    const bool row = (b.i < 3) == (b.j < 3);
    const bool seam = std::min(b.i, b.j) == 1 && std::max(b.i, b.j) == 4;
    CAPTURE(b.i);
    CAPTURE(b.j);
    CHECK(b.prestress == (seam ? 3.0 : row ? 4.0 : 2.0));
  }
}
