// Issue 13: handle metamethods type-check their operands, and no tendril
// metatable is reachable from a scene. `p == m` read a particle handle out
// of the model's userdata (past its end under ASan); `getmetatable(m).__gc(m)`
// freed the scene while it ran.
#include <doctest/doctest.h>

#include <filesystem>
#include <string>

#include "scene_files.hpp"

using namespace tendril;

namespace {

std::string run(const std::string& name, const std::string& code) {
  std::string error;
  const int status =
      test::run_scene_in(std::filesystem::temp_directory_path() / "tendril-test-handles" / name, code, &error);
  CHECK((status == 0) == error.empty());
  return error;
}

// Particle 0 and block 0, a model, a rule and a multi-resolution box.
const char* const kScene = R"(
local m = tendril.model()
local ps = {}
for r = 0, 1 do for c = 0, 1 do ps[#ps + 1] = m:particle{c, r, 0} end end
local patch = m:quad_grid{particles = ps, rows = 2, cols = 2, EA = 1e3}
local p = ps[1]
local rule = tendril.rule{name = "nothing", production = function(m) end}
local mr = m:multires(patch, {factor = 2})
assert(p.id == 0 and patch.id == 0)
)";

}  // namespace

TEST_CASE("a handle compared with anything but a handle of its kind is unequal") {
  CHECK(run("eq", std::string(kScene) + R"lua(
assert(not (p == m) and not (m == p))            -- a model's userdata is no handle
assert(not (p == mr.core) and not (mr.core == p)) -- nor a multires box
assert(not (p == patch) and not (patch == p))    -- particle 0 is not block 0
assert(p == ps[1] and p == m:particles(patch)[1] and p ~= ps[2])
assert(patch == m:blocks()[1])
assert(tostring(p) == "particle 0" and tostring(patch) == "block 0" and p.id == 0 and p.name == nil)
)lua") == "");
}

TEST_CASE("every tendril metatable is protected: getmetatable gives its name, setmetatable refuses") {
  CHECK(run("protected", std::string(kScene) + R"lua(
assert(getmetatable(m) == "tendril.Model", tostring(getmetatable(m)))
assert(getmetatable(p) == "tendril.Particle")
assert(getmetatable(patch) == "tendril.Block")
assert(getmetatable(rule) == "tendril.Rule")
assert(getmetatable(mr.core) == "tendril.Multires", tostring(getmetatable(mr.core)))
for _, v in ipairs{rule} do
  local ok, err = pcall(setmetatable, v, {})
  assert(not ok and err:find("cannot change a protected metatable"), err)
end
-- The attack of issue 13: freeing the model from a trigger's predicate while
-- m:run steps it. Now an error in the scene, and the model lives on.
local ok, err = pcall(function() getmetatable(m).__gc(m) end)
assert(not ok and err:find("attempt to call a nil value %(field '__gc'%)"), err)
m:trigger{rule = rule, when = function(m) getmetatable(m).__gc(m) return true end}
local ran, why = pcall(m.step, m, 1)
assert(not ran and why:find("__gc"), why)
assert(m:count().particles == 9, m:count().particles)
assert(m:check() == true)
)lua") == "");
}

TEST_CASE("a handle metamethod taken out through debug checks its operand") {
  // debug.getmetatable bypasses __metatable (an unsandboxed scene has debug):
  // the metamethods themselves refuse what is not a handle.
  CHECK(run("debug", std::string(kScene) + R"lua(
local meta = debug.getmetatable(p)
assert(meta.__eq(p, m) == false and meta.__eq(m, p) == false and meta.__eq(nil, 1) == false)
assert(meta.__eq(p, p) == true)
for _, bad in ipairs{m, mr.core, 1} do
  local ok, err = pcall(meta.__tostring, bad)
  assert(not ok and err:find("tostring: expected a particle or a block, got "), err)
  ok, err = pcall(meta.__index, bad, "id")
  assert(not ok and err:find("handle index: expected a particle or a block, got "), err)
end
local ok, err = pcall(meta.__tostring, m)
assert(err:find("got tendril.Model"), err)
)lua") == "");
}
