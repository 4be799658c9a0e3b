// m:results and m:reactions (issue 14) against hand calculations: a 6-DOF
// cantilever under a tip moment (M constant, sigma = M / W), a twisted
// 6-DOF bar (T = GJ phi / L), a CST square under uniaxial strain (the
// plane-stress law), a cable pair at an angle (N from statics), a 3-DOF
// beam's moment, and the principal stresses of Mohr's circle.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <tiny_gltf.h>

#include "io/gltf.hpp"
#include "io/model_xml.hpp"
#include "lua_host.hpp"
#include "query/element_results.hpp"

using namespace tendril;

namespace {

std::string run(const std::string& name, const std::string& code) {
  const auto dir = std::filesystem::temp_directory_path() / "tendril-test-results";
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

TEST_CASE("principal stresses: Mohr's circle of (sx, sy, tau)") {
  double s1, s2, angle;
  principal_stresses(3, 1, 0, s1, s2, angle);
  CHECK(s1 == doctest::Approx(3));
  CHECK(s2 == doctest::Approx(1));
  CHECK(angle == doctest::Approx(0));
  principal_stresses(0, 0, 2, s1, s2, angle);  // pure shear: +-tau at 45 degrees
  CHECK(s1 == doctest::Approx(2));
  CHECK(s2 == doctest::Approx(-2));
  CHECK(angle == doctest::Approx(M_PI / 4));
}

TEST_CASE("m:results: a 6-DOF cantilever under a tip moment carries M everywhere, stress M / W") {
  // GFRP rod d = 12 mm, L = 1 m, M = 10 N m: kappa = M / EI = 0.393 1/m,
  // sigma = M / W = 10 / (pi 0.012^3 / 32) = 58.95 MPa, 14.7 % of 400 MPa.
  CHECK(run("cantilever.lua", R"(
local rod = tendril.section.rod{ d = 0.012, material = "gfrp" }
local m = tendril.model()
local pts = {}
for i = 0, 10 do pts[#pts + 1] = { i / 10, 0, 0 } end
local b = m:beam{ points = pts, EA = rod.EA, EI = rod.EI, GJ = rod.GJ, dofs = 6 }
local ps = m:particles(b)
m:lock(ps[1], "full")
local M = 10
m:torque(ps[#ps], { 0, 0, M })
assert(m:run{ tolerance = 1e-7, max_steps = 200000 }.converged, "did not converge")
local r = m:results(b, rod)
assert(#r.elements == 10)
local sigma = M / rod.Wz
for k, e in ipairs(r.elements) do
  assert(math.abs(e.moment - M) < 0.01 * M, k .. ": moment " .. e.moment)
  assert(math.abs(math.abs(e.Mz) - M) < 0.01 * M and math.abs(e.My) < 1e-3 * M, k .. ": Mz " .. e.Mz .. " My " .. e.My)
  assert(math.abs(e.curvature - M / rod.EI) < 0.01 * M / rod.EI, k .. ": curvature " .. e.curvature)
  assert(math.abs(e.radius - rod.EI / M) < 0.01 * rod.EI / M)
  assert(math.abs(e.stress - sigma) < 0.01 * sigma, k .. ": stress " .. e.stress .. " vs " .. sigma)
  assert(math.abs(e.utilisation - sigma / rod.strength) < 0.01 * sigma / rod.strength)
  assert(math.abs(e.torsion) < 1e-3 * M)
end
assert(math.abs(r.max_stress - sigma) < 0.01 * sigma and math.abs(r.max_utilisation - sigma / 400e6) < 0.01 * sigma / 400e6)
-- The clamp takes the moment back.
local rs = m:reactions()
assert(#rs == 1 and rs[1].particle == ps[1])
assert(math.abs(rs[1].moment[3] + M) < 0.01 * M, "reaction moment " .. rs[1].moment[3])
-- Without a section: forces and moments, no stress.
local plain = m:results(b)
assert(plain.elements[1].stress == nil and plain.max_stress == nil and math.abs(plain.max_moment - M) < 0.01 * M)
)") == "");
}

TEST_CASE("m:results: a twisted 6-DOF bar carries T = GJ phi / L") {
  CHECK(run("twist.lua", R"(
local m = tendril.model()
local pts = {}
for i = 0, 8 do pts[#pts + 1] = { 2 * i / 8, 0, 0 } end
local GJ, L = 40, 2
local b = m:beam{ points = pts, EA = 1e6, EI = 100, GJ = GJ, dofs = 6 }
local ps = m:particles(b)
m:lock(ps[1], "full")
local T = 0.2   -- phi = T L / GJ = 0.01 rad
m:torque(ps[#ps], { T, 0, 0 })
assert(m:run{ tolerance = 1e-9, max_steps = 200000 }.converged, "did not converge")
local _, y = m:orientation(ps[#ps])
local phi = math.atan(y[3], y[2])
assert(math.abs(phi - T * L / GJ) < 0.01 * T * L / GJ, "phi " .. phi)
for k, e in ipairs(m:results(b).elements) do
  assert(math.abs(e.torsion - GJ * phi / L) < 0.01 * T, k .. ": torsion " .. e.torsion .. " vs " .. GJ * phi / L)
  assert(math.abs(e.moment) < 1e-3 * T, k .. ": moment " .. e.moment)
end
)") == "");
}

TEST_CASE("m:results: a CST square under uniaxial strain has the plane-stress law's principal stresses") {
  // eps_x = 1 %, eps_y = 0: sigma_x = dxx eps = 8 N/m, sigma_y = dyx eps =
  // 2.4 N/m, no shear; s1 along x.
  CHECK(run("cst.lua", R"(
local m = tendril.model()
local function row(y) local ps = {} for i = 0, 3 do ps[#ps + 1] = m:particle{ i / 3, y, 0 } end return ps end
local patch = m:project{ from = row(0), to = row(1), rows = 3, EA = 10 }
m:formulation(patch, "cst", { stress = { 0, 0 }, warp = { 1, 0, 0 }, analysis = { dxx = 800, dyy = 600, dxy = 240, dyx = 240, G = 30 } })
for _, p in ipairs(m:particles(patch)) do local x = m:position(p) m:set_position(p, { 1.01 * x[1], x[2], x[3] }) end
local r = m:results(patch)
assert(#r.triangles == 24, #r.triangles)  -- rows = 3 between the two rows: 4 x 3 quads
for k, t in ipairs(r.triangles) do
  assert(math.abs(t.warp - 8) < 1e-9 and math.abs(t.weft - 2.4) < 1e-9 and math.abs(t.shear) < 1e-9, k .. ": " .. t.warp .. " " .. t.weft .. " " .. t.shear)
  assert(math.abs(t.s1 - 8) < 1e-9 and math.abs(t.s2 - 2.4) < 1e-9)
  assert(math.abs(math.abs(t.d1[1]) - 1) < 1e-9 and math.abs(math.abs(t.d2[2]) - 1) < 1e-9)
end
-- With a fabric's strengths: utilisation = max(warp / strength_warp, weft /
-- strength_weft) = max(8 / 100, 2.4 / 20) = 0.12; compression counts 0.
local u = m:results(patch, { strength_warp = 100, strength_weft = 20 })
for k, t in ipairs(u.triangles) do assert(math.abs(t.utilisation - 0.12) < 1e-9, k .. ": " .. t.utilisation) end
assert(math.abs(u.max_utilisation - 0.12) < 1e-9)
assert(m:results(patch).triangles[1].utilisation == nil, "no strength, no utilisation")
local fabric = tendril.fabric("pvc_polyester")
assert(math.abs(m:results(patch, fabric).max_utilisation - 8 / fabric.strength_warp) < 1e-15)
for _, p in ipairs(m:particles(patch)) do local x = m:position(p) m:set_position(p, { x[1] / 1.01 / 1.01, x[2], x[3] }) end
assert(m:results(patch, { strength_warp = 100, strength_weft = 20 }).max_utilisation == 0, "compressed: 0")
local ok, err = pcall(m.results, m, patch, { strength_warp = 100 })
assert(not ok and err:find("results: 'strength_weft' is required"), err)
)") == "");
}

TEST_CASE("m:results: a cable pair at an angle carries N = P / (2 sin theta); a slack cable is flagged") {
  CHECK(run("cables.lua", R"(
local m = tendril.model()
local a, b, c = m:particle{ -1, 0, 0 }, m:particle{ 1, 0, 0 }, m:particle{ 0, 0, -0.5 }
local left, right = m:cable(a, c, { EA = 1e6 }), m:cable(c, b, { EA = 1e6 })
local d = m:particle{ 0, 0, -2 }
local loose = m:cable(c, d, { EA = 1e6, rest_length = 3 })
m:lock(a, "xyz") m:lock(b, "xyz") m:lock(d, "xyz")
local P = 1000
m:load(c, { 0, 0, -P })
assert(m:run{ tolerance = 1e-6, max_steps = 200000 }.converged, "did not converge")
local x = m:position(c)
local sin = -x[3] / math.sqrt(1 + x[3]^2)
local N = P / (2 * sin)
for _, cable in ipairs{ left, right } do
  local e = m:results(cable).elements[1]
  assert(math.abs(e.axial - N) < 1e-3 * N, "N " .. e.axial .. " vs " .. N)
  assert(not e.slack and math.abs(e.strain - e.axial / 1e6) < 1e-9)
end
local s = m:results(loose).elements[1]
assert(s.slack and s.axial == 0 and s.strain < 0)
local reactions = m:reactions()
assert(#reactions == 3)
for _, r in ipairs(reactions) do
  if r.particle ~= d then assert(math.abs(r.force[3] - P / 2) < 1e-3 * P, "reaction " .. r.force[3]) end
end
)") == "");
}

TEST_CASE("m:results: a 3-DOF beam's links carry the larger moment of their vertices, and its stress") {
  // A simply supported beam under a central load: M = P L / 4 at mid-span.
  CHECK(run("beam3.lua", R"(
local rod = tendril.section.rod{ d = 0.02, material = "steel" }
local m = tendril.model()
local pts = {}
for i = 0, 20 do pts[#pts + 1] = { i / 10, 0, 0 } end
local b = m:beam{ points = pts, EA = rod.EA, EI = rod.EI }
local ps = m:particles(b)
m:lock(ps[1], "xyz") m:lock(ps[#ps], "yz")
for _, p in ipairs(ps) do m:lock(p, "y") end
local P = 100
m:load(ps[11], { 0, 0, -P })
assert(m:run{ tolerance = 1e-6, max_steps = 400000 }.converged, "did not converge")
local r = m:results(b, rod)
local M = P * 2 / 4
assert(math.abs(r.max_moment - M) < 0.01 * M, "moment " .. r.max_moment)
assert(math.abs(r.max_stress - M / rod.Wy) < 0.01 * M / rod.Wy, "stress " .. r.max_stress)
assert(#r.vertices == 19 and #r.elements == 20)
local summary = m:summary(rod)   -- the most stressed beam: at mid-span
assert(summary.max_stress == r.max_stress and summary.max_stress_block == b.id and summary.max_stress_particle == ps[11].id)
assert(r.elements[10].at == ps[11] and r.elements[11].at == ps[11])
-- Sections per beam, by handle or id: the same here; a cable takes none.
local by_beam, by_id = m:summary({ [b] = rod }), m:summary({ [b.id] = rod })
assert(by_beam.max_stress == summary.max_stress and by_id.max_utilisation == summary.max_utilisation)
local c = m:cable(ps[1], ps[3], { EA = 1 })
local ok, err = pcall(m.summary, m, { [c] = rod })
assert(not ok and err:find("is a cable; sections give beams their stress", 1, true), err)
ok, err = pcall(m.summary, m, { [99] = rod })
assert(not ok and err:find("99", 1, true), err)
local ok, err = pcall(m.results, m, b, { A = 1 })
assert(not ok and err:find("Wy"), err)
)") == "");
}

namespace {

// A legacy VTK file read back: points, cells and every SCALARS / VECTORS
// field of CELL_DATA ("cell.NAME") and POINT_DATA ("point.NAME").
struct VtkFile {
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<int>> cells;
  std::vector<int> types;
  std::map<std::string, std::vector<double>> fields;
};

VtkFile read_vtk(const std::filesystem::path& path) {
  std::ifstream in(path);
  REQUIRE(in.good());
  VtkFile f;
  std::string line, word, section;
  std::getline(in, line);
  REQUIRE(line == "# vtk DataFile Version 3.0");
  std::getline(in, line);  // title
  std::getline(in, line);
  REQUIRE(line == "ASCII");
  std::size_t count = 0;
  while (in >> word) {
    if (word == "DATASET") {
      in >> word;
      REQUIRE(word == "UNSTRUCTURED_GRID");
    } else if (word == "POINTS") {
      in >> count >> word;
      f.points.resize(count);
      for (auto& p : f.points) in >> p[0] >> p[1] >> p[2];
    } else if (word == "CELLS") {
      std::size_t size;
      in >> count >> size;
      f.cells.resize(count);
      for (auto& c : f.cells) {
        int n;
        in >> n;
        c.resize(std::size_t(n));
        for (int& v : c) in >> v;
      }
    } else if (word == "CELL_TYPES") {
      in >> count;
      f.types.resize(count);
      for (int& t : f.types) in >> t;
    } else if (word == "CELL_DATA" || word == "POINT_DATA") {
      section = word == "CELL_DATA" ? "cell." : "point.";
      in >> count;
    } else if (word == "SCALARS" || word == "VECTORS") {
      const int width = word == "SCALARS" ? 1 : 3;
      std::string name, type;
      in >> name >> type;
      if (width == 1) {
        int components;
        in >> components >> word >> word;  // LOOKUP_TABLE default
      }
      auto& v = f.fields[section + name];
      v.resize(count * std::size_t(width));
      for (double& x : v) in >> x;
    } else {
      FAIL("unexpected word in the VTK file: " << word);
    }
  }
  REQUIRE(!in.bad());
  return f;
}

}  // namespace

TEST_CASE("m:export_vtk: a file ParaView reads, with the results read back equal to the hand calculations") {
  const auto out = std::filesystem::temp_directory_path() / "tendril-test-results" / "out";
  std::filesystem::remove(out / "r.vtk");
  REQUIRE(run("vtk.lua", R"(
local rod = tendril.section.rod{ d = 0.012, material = "gfrp" }
local m = tendril.model()
local pts = {}
for i = 0, 10 do pts[#pts + 1] = { i / 10, 0, 0 } end
local beam = m:beam{ points = pts, EA = rod.EA, EI = rod.EI, GJ = rod.GJ, dofs = 6 }
local ps = m:particles(beam)
m:lock(ps[1], "full")
m:torque(ps[#ps], { 0, 0, 10 })
local a, b, c = m:particle{ -1, 0, -5 }, m:particle{ 1, 0, -5 }, m:particle{ 0, 0, -5.5 }
m:cable(a, c, { EA = 1e7 })
m:cable(c, b, { EA = 1e7 })
m:lock(a, "xyz"); m:lock(b, "xyz")
m:load(c, { 0, 0, -1000 })
local function row(y) local r = {} for i = 0, 2 do r[#r + 1] = m:particle{ i / 2, y, 3 } end return r end
local patch = m:project{ from = row(0), to = row(1), rows = 1, EA = 10 }
m:formulation(patch, "cst", { stress = { 0, 0 }, warp = { 1, 0, 0 }, analysis = { dxx = 800, dyy = 600, dxy = 240, dyx = 240, G = 30 } })
for _, p in ipairs(m:particles(patch)) do local x = m:position(p) m:set_position(p, { 1.01 * x[1], x[2], x[3] }) m:lock(p, "xyz") end
assert(m:run{ tolerance = 1e-6, max_steps = 200000 }.converged)
m:export_vtk(tendril.out("r.vtk"), rod)
m:export_gltf(tendril.out("r.glb"), { colour = "utilisation", section = { [beam] = rod } })   -- per beam
for _, bad in ipairs{ { colour = "heat" }, { colour = "stress" } } do
  local ok, err = pcall(m.export_gltf, m, tendril.out("bad.glb"), bad)
  assert(not ok and err:find(bad.colour == "heat" and "'heat' is none of" or "needs a section", 1, true), err)
end
local ok, err = pcall(m.export_vtk, m, "/nonexistent-dir/r.vtk")
assert(not ok and err:find("nonexistent", 1, true), err)
)") == "");
  const VtkFile f = read_vtk(out / "r.vtk");
  // 11 beam, 3 cable, 3 x 3 patch particles (rows = 1: one row between
  // the two given); 10 beam elements, 2 cable segments, the patch's 8
  // boundary bars (a CST patch keeps them) and 2 x 2 x 2 triangles.
  REQUIRE(f.points.size() == 11 + 3 + 9);
  REQUIRE(f.cells.size() == 10 + 2 + 8 + 8);
  const auto& axial = f.fields.at("cell.axial");
  const auto& stress = f.fields.at("cell.stress");
  const auto& utilisation = f.fields.at("cell.utilisation");
  const auto& s1 = f.fields.at("cell.s1");
  const auto& s2 = f.fields.at("cell.s2");
  for (std::size_t k = 0; k < 10; ++k) {  // sigma = M / W = 10 / (pi 0.012^3 / 32)
    CHECK(f.types[k] == 3);
    CHECK(stress[k] == doctest::Approx(10 / (M_PI * std::pow(0.012, 3) / 32)).epsilon(0.01));
    CHECK(utilisation[k] == doctest::Approx(stress[k] / 400e6));
    CHECK(f.fields.at("cell.moment")[k] == doctest::Approx(10).epsilon(0.01));
  }
  for (std::size_t k = 10; k < 12; ++k) {  // N = P / (2 sin theta) from the cable's own geometry
    const auto& p = f.points[std::size_t(f.cells[k][0])];
    const auto& q = f.points[std::size_t(f.cells[k][1])];
    const double dx = q[0] - p[0], dz = q[2] - p[2];
    CHECK(axial[k] == doctest::Approx(1000 / (2 * std::abs(dz) / std::hypot(dx, dz))).epsilon(1e-4));
    CHECK(stress[k] == 0);
  }
  for (std::size_t k = 20; k < 28; ++k) {  // plane stress, eps_x = 1 %
    CHECK(f.types[k] == 5);
    CHECK(s1[k] == doctest::Approx(8));
    CHECK(s2[k] == doctest::Approx(2.4));
    CHECK(std::abs(f.fields.at("cell.d1")[3 * k]) == doctest::Approx(1));
  }
  // Reactions: the cable supports (points 11 and 12) take P / 2 upwards each,
  // the clamp (point 0) the moment.
  const auto& reaction = f.fields.at("point.reaction");
  CHECK(reaction[3 * 11 + 2] == doctest::Approx(500).epsilon(1e-4));
  CHECK(reaction[3 * 12 + 2] == doctest::Approx(500).epsilon(1e-4));
  CHECK(f.fields.at("point.reaction_moment")[2] == doctest::Approx(-10).epsilon(0.01));
  CHECK(f.fields.at("point.locked")[0] == 1);
  CHECK(f.fields.at("point.locked")[1] == 0);

  // The same state as glTF, read back with tinygltf: the line elements'
  // vertices coloured by utilisation (the beam's 0.147 on the ramp, the
  // cables' none grey), y up.
  std::ifstream glb_in(out / "r.glb", std::ios::binary);
  const std::string glb((std::istreambuf_iterator<char>(glb_in)), std::istreambuf_iterator<char>());
  tinygltf::Model g;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  REQUIRE(loader.LoadBinaryFromMemory(&g, &err, &warn, reinterpret_cast<const unsigned char*>(glb.data()),
                                      unsigned(glb.size())));
  CHECK(err == "");
  REQUIRE(g.meshes.size() == 1);
  REQUIRE(g.meshes[0].primitives.size() == 2);
  auto floats = [&](int accessor) {
    const tinygltf::Accessor& a = g.accessors[std::size_t(accessor)];
    const tinygltf::BufferView& v = g.bufferViews[std::size_t(a.bufferView)];
    const float* p = reinterpret_cast<const float*>(g.buffers[std::size_t(v.buffer)].data.data() + v.byteOffset + a.byteOffset);
    return std::vector<float>(p, p + a.count * 3);
  };
  const tinygltf::Primitive& lines = g.meshes[0].primitives[0];
  CHECK(lines.mode == TINYGLTF_MODE_LINE);
  const std::vector<float> colour = floats(lines.attributes.at("COLOR_0"));
  const std::vector<float> position = floats(lines.attributes.at("POSITION"));
  REQUIRE(colour.size() == 3u * 2 * (10 + 2 + 8));
  const auto expected = gltf_ramp(utilisation[0]);
  for (std::size_t v = 0; v < 20; ++v)
    for (int c = 0; c < 3; ++c) CHECK(colour[3 * v + std::size_t(c)] == doctest::Approx(expected[std::size_t(c)]));
  CHECK(colour[3 * 20] == doctest::Approx(0.6));  // a cable: no utilisation
  CHECK(position[3 * 21 + 1] == doctest::Approx(f.points[std::size_t(f.cells[10][1])][2]));  // y up: tendril's z
  const tinygltf::Primitive& faces = g.meshes[0].primitives[1];
  CHECK(faces.mode == TINYGLTF_MODE_TRIANGLES);
  CHECK(g.accessors[std::size_t(faces.attributes.at("POSITION"))].count == 3u * 8);
  CHECK(g.accessors[std::size_t(faces.attributes.at("POSITION"))].maxValues[1] == doctest::Approx(3));
}

TEST_CASE("m:results: a ring under radial loads is in uniform compression; a catenary's horizontal tension is constant") {
  CHECK(run("ring.lua", R"(
-- A regular 24-gon ring (stress free as built), P inward at every node: the
-- node's equilibrium gives N = -P / (2 sin(pi / n)) in every segment.
local m = tendril.model()
local n, R, P = 24, 2, 50
local pts = {}
for k = 0, n - 1 do pts[#pts + 1] = { R * math.cos(2 * math.pi * k / n), R * math.sin(2 * math.pi * k / n), 0 } end
local ring = m:beam{ points = pts, EA = 1e7, EI = 1e3, closed = true, rest = "current" }
local ps = m:particles(ring)
for k, p in ipairs(ps) do
  local x = m:position(p)
  m:load(p, { -P * x[1] / R, -P * x[2] / R, 0 })
  m:lock(p, "z")
end
m:lock(ps[1], "y"); m:lock(ps[n // 2 + 1], "y"); m:lock(ps[n // 4 + 1], "x")   -- rigid motions only
assert(m:run{ tolerance = 1e-7, max_steps = 200000 }.converged, "the ring did not converge")
local N = -P / (2 * math.sin(math.pi / n))
local r = m:results(ring)
assert(#r.elements == n)
for k, e in ipairs(r.elements) do
  assert(math.abs(e.axial - N) < 1e-4 * math.abs(N), k .. ": N " .. e.axial .. " vs " .. N)
  -- The shortening N / EA = -2e-5 tightens the curvature alike: M = EI 2e-5 / R = 0.01 N m, no more.
  assert(math.abs(e.moment) < 1e-4 * math.abs(N) * R, k .. ": moment " .. e.moment)
end

-- A chain of 20 cable segments of 1 kg/m hanging between two pins 10 m
-- apart: the horizontal component of N is the same in every segment, and
-- each pin carries half the weight upwards.
local c = tendril.model()
c:gravity{ 0, 0, -9.81 }
local chain, prev = {}, c:particle{ 0, 0, 0 }
local first = prev
for k = 1, 20 do
  local p = c:particle{ 10 * k / 20, 0, -2 * math.sin(math.pi * k / 20) }
  chain[#chain + 1] = c:cable(prev, p, { EA = 1e7, line_mass = 1, rest_length = 0.6 })
  prev = p
end
c:lock(first, "xyz"); c:lock(prev, "xyz")
for _, p in ipairs(c:particles()) do c:lock(p, "y") end
local run = c:run{ tolerance = 1e-6, max_steps = 400000 }
assert(run.converged, "the chain did not converge: residual " .. run.residual)
local H
for k, cable in ipairs(chain) do
  local e = c:results(cable).elements[1]
  local a, b = c:position(e.a), c:position(e.b)
  local h = e.axial * math.abs(b[1] - a[1]) / math.sqrt((b[1] - a[1])^2 + (b[3] - a[3])^2)
  H = H or h
  assert(math.abs(h - H) < 1e-5 * H, k .. ": H " .. h .. " vs " .. H)
end
local weight = 9.81 * 20 * 0.6
for _, s in ipairs(c:reactions()) do
  if s.particle == first or s.particle == prev then
    assert(math.abs(s.force[3] - weight / 2) < 1e-4 * weight, "pin " .. s.force[3] .. " vs " .. weight / 2)
  end
end
)") == "");
}

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// The values of the VTK XML DataArray `name` of a file (the first such).
std::vector<double> xml_array(const std::string& text, const std::string& name) {
  const std::size_t at = text.find("Name=\"" + name + "\"");
  REQUIRE(at != std::string::npos);
  const std::size_t from = text.find('>', at) + 1, to = text.find("</DataArray>", from);
  std::istringstream in(text.substr(from, to - from));
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

}  // namespace

TEST_CASE("m:export_vtk .vtp: lines then triangles, the cell data following them; the same values as .vtu") {
  const auto out = std::filesystem::temp_directory_path() / "tendril-test-results" / "out";
  REQUIRE(run("vtp.lua", R"(
local m = tendril.model()
local function row(y) local r = {} for i = 0, 2 do r[#r + 1] = m:particle{ i / 2, y, 3 } end return r end
local patch = m:project{ from = row(0), to = row(1), rows = 1, EA = 10 }
m:formulation(patch, "cst", { stress = { 0, 0 }, warp = { 1, 0, 0 }, analysis = { dxx = 800, dyy = 600, dxy = 240, dyx = 240, G = 30 } })
for _, p in ipairs(m:particles(patch)) do local x = m:position(p) m:set_position(p, { 1.01 * x[1], x[2], x[3] }) m:lock(p, "xyz") end
local a, b, c = m:particle{ -1, 0, -5 }, m:particle{ 1, 0, -5 }, m:particle{ 0, 0, -5.5 }
m:cable(a, c, { EA = 1e7 })
m:cable(c, b, { EA = 1e7 })
m:lock(a, "xyz"); m:lock(b, "xyz")
m:load(c, { 0, 0, -1000 })
assert(m:run{ tolerance = 1e-6, max_steps = 200000 }.converged)
m:export_vtk(tendril.out("r.vtu"))
m:export_vtk(tendril.out("r.vtp"))
)") == "");
  const std::string vtu = slurp(out / "r.vtu"), vtp = slurp(out / "r.vtp");
  CHECK(vtp.find("<VTKFile type=\"PolyData\"") != std::string::npos);
  CHECK(vtp.find("NumberOfLines=\"10\" NumberOfStrips=\"0\" NumberOfPolys=\"8\"") != std::string::npos);
  // .vtu in block order: the patch's 8 boundary bars, its 8 triangles, the 2 cable segments.
  const std::vector<double> types = xml_array(vtu, "types");
  REQUIRE(types.size() == 18);
  for (std::size_t k = 0; k < 18; ++k) CHECK(types[k] == (k >= 8 && k < 16 ? 5 : 3));
  // .vtp: the 10 lines (bars, then the cables), then the 8 triangles.
  std::vector<std::size_t> order;
  for (std::size_t k : {0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 8, 9, 10, 11, 12, 13, 14, 15}) order.push_back(k);
  for (const char* name : {"axial", "s1", "s2", "block"}) {
    CAPTURE(name);
    const std::vector<double> u = xml_array(vtu, name), p = xml_array(vtp, name);
    REQUIRE(u.size() == 18);
    REQUIRE(p.size() == 18);
    for (std::size_t k = 0; k < 18; ++k) CHECK(p[k] == u[order[k]]);
  }
  CHECK(xml_array(vtp, "s1")[10] == doctest::Approx(8));  // plane stress, eps_x = 1 %
  CHECK(xml_array(vtp, "axial")[8] > 1000);                 // a cable: P / (2 sin theta)
  const std::vector<double> d1u = xml_array(vtu, "d1"), d1p = xml_array(vtp, "d1");
  for (std::size_t k = 0; k < 18; ++k)
    for (std::size_t c = 0; c < 3; ++c) CHECK(d1p[3 * k + c] == d1u[3 * order[k] + c]);
  // The polygons' connectivity is the triangles' of .vtu.
  const std::vector<double> cu = xml_array(vtu, "connectivity");
  const std::size_t polys = vtp.find("<Polys>");
  const std::vector<double> cp = xml_array(vtp.substr(polys), "connectivity");
  REQUIRE(cp.size() == 24);
  for (std::size_t k = 0; k < 24; ++k) CHECK(cp[k] == cu[16 + k]);
}

TEST_CASE("model database <results>: the hanging cables' N = P / (2 sin theta), a ring's moment; refused garbage") {
  const auto out = std::filesystem::temp_directory_path() / "tendril-test-results" / "out";
  REQUIRE(run("db.lua", R"(
local m = tendril.model()
local a, b, c = m:particle{ -1, 0, 0 }, m:particle{ 1, 0, 0 }, m:particle{ 0, 0, -0.5 }
m:cable(a, c, { EA = 1e7 })
m:cable(c, b, { EA = 1e7 })
m:lock(a, "xyz"); m:lock(b, "xyz")
m:load(c, { 0, 0, -1000 })
-- a straight 3-DOF beam bent into a closed ring of radius 1: M = EI / R at every vertex
local pts = {}
for i = 0, 23 do local t = 2 * math.pi * i / 24 pts[#pts + 1] = { math.cos(t), math.sin(t), 5 } end
local ring = m:beam{ points = pts, EA = 1e6, EI = 2, closed = true }
for _, p in ipairs(m:particles(ring)) do m:lock(p, "xyz") end
assert(m:run{ tolerance = 1e-7, max_steps = 200000 }.converged)
m:save(tendril.out("db.xml"))
)") == "");
  const std::string text = slurp(out / "db.xml");
  const std::size_t results = text.find("<results>");
  REQUIRE(results != std::string::npos);
  auto attr = [](const std::string& line, const std::string& name) {
    const std::size_t at = line.find(" " + name + "=\"") + name.size() + 3;
    return std::stod(line.substr(at, line.find('"', at) - at));
  };
  std::istringstream in(text.substr(results));
  int cables = 0, vertices = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.find("<line block=\"0\"") != std::string::npos || line.find("<line block=\"1\"") != std::string::npos) {
      // the cable's own geometry from the particles' saved positions is statics' sin theta
      CHECK(attr(line, "a") < attr(line, "b"));
      CHECK(attr(line, "axial") > 1000);
      ++cables;
    }
    if (line.find("<vertex block=\"2\"") != std::string::npos) {
      // three particles of a circle of R = 1: the hinge's curvature 2 sin(alpha) / Lc
      // (eq. 3.41) is their circumcircle's, 1 / R, and M = EI / R
      CHECK(attr(line, "curvature") == doctest::Approx(1).epsilon(1e-9));
      CHECK(attr(line, "moment") == doctest::Approx(2).epsilon(1e-9));
      ++vertices;
    }
  }
  CHECK(cables == 2);
  CHECK(vertices == 24);
  // Statics: the two segments carry P / (2 sin theta) for the sag the solver found.
  Model loaded;
  SolverSettings settings;
  load_model_xml_string(text, loaded, settings, "db.xml");
  CHECK(model_xml_string(loaded, settings) == text);
  const Vec3 mass = loaded.particles.position[2];
  const double sin_theta = -mass.z() / std::hypot(1.0, mass.z());
  std::istringstream again(text.substr(results));
  for (std::string line; std::getline(again, line);)
    if (line.find("<line block=\"0\"") != std::string::npos)
      CHECK(attr(line, "axial") == doctest::Approx(1000 / (2 * sin_theta)).epsilon(1e-6));
  // A <results> holding anything else is refused, naming it.
  std::string bad = text;
  bad.insert(bad.find("<results>") + 9, "<reaction p=\"0\"/>");
  Model refused;
  CHECK_THROWS_WITH_AS(load_model_xml_string(bad, refused, settings, "bad.xml"),
                       doctest::Contains("unknown element <reaction> inside <results>"), std::exception);
}
