// Issue 13: every error a tendril function raised leaked its message (the
// guard built it in a std::string, then lua_error longjmped over the
// string's destructor; ~160 bytes a refused call). LeakSanitizer sees it in
// the sanitizer build; here the heap's size says it in the ordinary one.
#include <doctest/doctest.h>

#include <malloc.h>

#include <filesystem>
#include <string>

#include "scene_files.hpp"

using namespace tendril;

namespace {

// Heap bytes in use after a scene that refuses `calls` calls has run and
// closed its Lua state (which frees everything Lua owns).
std::size_t heap_after(int calls) {
  const std::string scene = R"(
local m = tendril.model()
local p = m:particle{0, 0, 0}
local long = string.rep("q", 200)  -- no axis letter; a message far beyond the small-string buffer
for k = 1, )" + std::to_string(calls) + R"( do
  local ok, err = pcall(m.particle, m, long)
  assert(not ok and err:find("particle: argument 2: expected", 1, true), err)
  ok, err = pcall(function() m:lock(p, long) end)
  assert(not ok and err:find("scene.lua:8: lock: ", 1, true), err)  -- where the call is
end
)";
  std::string error;
  test::run_scene_in(std::filesystem::temp_directory_path() / "tendril-test-binding-errors", scene, &error);
  CHECK(error == "");
  return mallinfo2().uordblks;
}

}  // namespace

TEST_CASE("a refused call leaks nothing: 20 000 refusals leave the heap as 6 did") {
  heap_after(3);  // caches and first-use allocations
  const std::size_t few = heap_after(3);
  const std::size_t many = heap_after(10000);
  // The leak was ~200 bytes a message: 4 MB here.
  CHECK(many < few + (1u << 20));
}

TEST_CASE("a readout given a value refuses it and says what changes it (m:position(p, x) moved nothing)") {
  std::string error;
  test::run_scene_in(std::filesystem::temp_directory_path() / "tendril-test-readout-value", R"(
local m = tendril.model()
local p = m:particle{ 0, 0, 0 }
local ok, err = pcall(m.position, m, p, { 1, 2, 3 })
assert(not ok and err:find("position: argument 3: a readout takes no value; m:set_position(p, {x, y, z}) moves a particle", 1, true), err)
assert(m:position(p)[1] == 0)
ok, err = pcall(m.residual, m, 5)
assert(not ok and err:find("residual: argument 2: a readout takes no value", 1, true), err)
)", &error);
  CHECK(error == "");
}
