// The 6-DOF beam from Lua: m:beam{dofs = 6, GJ, EIy, EIz}, m:formulation,
// m:lock with rotations, m:orientation, m:torque; the end-moment cantilever
// as a scene.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>

#include "lua_host.hpp"

using namespace tendril;

namespace {

std::string run(const std::string& name, const std::string& code) {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-beam6-lua";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << code;
  SceneOptions options;
  options.progress = false;
  options.out_dir = (dir / "out").string();
  std::string error;
  run_scene((dir / name).string(), options, &error);
  return error;
}

}  // namespace

TEST_CASE("Lua: a 6-DOF cantilever rolled into a circle by m:torque, frames read with m:orientation") {
  const std::string error = run("circle.lua", R"(
local m = tendril.model()
local pts = {}
for i = 0, 20 do pts[#pts + 1] = { i / 20, 0, 0 } end
local b = m:beam{ points = pts, EA = 1e4, EI = 1, dofs = 6, GJ = 0.5, EIy = 2, EIz = 1 }
assert(m:formulation(b) == 6)
local ps = m:particles(b)
m:lock(ps[1], "xyz rxyz")
assert(m:locks(ps[1]) == "xyz rxyz")
assert(m:state(ps[1]) == "full-lock")
m:torque(ps[21], { 0, 0, 2 * math.pi })
local t = m:torque(ps[21])
assert(t[3] == 2 * math.pi)
local r = m:run{ tolerance = 1e-7, max_steps = 100000 }
assert(r.converged, "did not converge")
local tip, root = m:position(ps[21]), m:position(ps[1])
local gap = math.sqrt((tip[1] - root[1])^2 + (tip[2] - root[2])^2 + (tip[3] - root[3])^2)
assert(gap < 0.01, "gap " .. gap)
-- Half way the frame has turned by pi about z: its x axis points back.
local x, y, z = m:orientation(ps[11])
assert(math.abs(x[1] + 1) < 0.01 and math.abs(y[2] + 1) < 0.01 and math.abs(z[3] - 1) < 1e-9, "frame " .. x[1] .. " " .. y[2])
m:check()
-- Back to 3 DOF: the hinges know EI only; the moment no longer acts.
m:formulation(b, 3)
assert(m:formulation(b) == 3)
m:check()
)");
  CHECK(error == "");
}

TEST_CASE("Lua: m:orientation sets a frame; bad 6-DOF arguments are errors naming the function") {
  CHECK(run("set.lua", R"(
local m = tendril.model()
local p = m:particle{ 0, 0, 0 }
m:orientation(p, { 0, 1, 0 }, { -1, 0, 0 }, { 0, 0, 1 })
local x, y, z = m:orientation(p)
assert(math.abs(x[2] - 1) < 1e-12 and math.abs(y[1] + 1) < 1e-12 and math.abs(z[3] - 1) < 1e-12)
)") == "");
  struct Case {
    const char* code;
    const char* expect;
  };
  const Case cases[] = {
      {"m:beam{ points = {{0,0,0},{1,0,0}}, EA = 1, EI = 1, dofs = 5 }", "beam: 'dofs' must be 3 or 6"},
      {"m:beam{ points = {{0,0,0},{1,0,0}}, EA = 1, EI = 1, GJ = -1 }", "beam: 'GJ' must be a finite number >= 0"},
      {"m:formulation(m:beam{ points = {{0,0,0},{1,0,0}}, EA = 1, EI = 1 }, 4)", "formulation"},
      {"m:formulation(m:cable(m:particle{0,0,0}, m:particle{1,0,0}, { EA = 1 }), 6)", "only beams switch"},
      {"m:orientation(m:particle{0,0,0}, {1,0,0}, {1,0,0}, {0,0,1})", "orthonormal"},
      {"m:torque(m:particle{0,0,0}, {0, 0/0, 0})", "torque"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.code);
    const std::string error = run("bad.lua", std::string("local m = tendril.model()\n") + c.code + "\n");
    CHECK(error.find("bad.lua:2:") != std::string::npos);
    CHECK(error.find(c.expect) != std::string::npos);
  }
}
