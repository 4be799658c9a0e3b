#include "lua_sandbox.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

#include "io/file_policy.hpp"
#include "lua_args.hpp"

namespace tendril::lua {

namespace {

constexpr int kHookEvery = 10000;  // instructions between two looks at the limits

// check(path, mode): a FileRefused error unless the file policy allows it.
int l_check_path(lua_State* L) {
  const char* path = luaL_checkstring(L, 1);
  const char* mode = luaL_optstring(L, 2, "r");
  const bool writing = std::strpbrk(mode, "wa+") != nullptr;
  if (writing) check_writable(path);
  else check_readable(path);
  return 0;
}

// Run with (check, io.open, io.lines, load): wraps what may open files or
// load bytecode, and drops what may run programs or reach beyond Lua.
const char* const kRestrict = R"lua(
local check, raw_open, raw_lines, raw_load = ...
package, require, dofile, loadfile, debug = nil, nil, nil, nil, nil
io.open = function(path, mode) check(path, mode) return raw_open(path, mode) end
io.lines = function(path, ...)
  if path ~= nil then check(path, "r") end
  return raw_lines(path, ...)
end
io.popen, io.input, io.output, io.tmpfile = nil, nil, nil, nil
load = function(chunk, name, mode, ...)  -- text only, whatever the mode asked
  if select("#", ...) > 0 then return raw_load(chunk, name, "t", (...)) end
  return raw_load(chunk, name, "t")
end
local kept = {clock = os.clock, time = os.time, date = os.date, difftime = os.difftime}
for name in pairs(os) do os[name] = kept[name] end
)lua";

}  // namespace

Sandbox::Sandbox(const SandboxLimits& limits)
    : limits_(limits),
      heap_limit_(std::size_t(limits.memory_mb) << 20),
      deadline_(std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                                       std::chrono::duration<double>(limits.seconds))) {}

lua_State* Sandbox::new_state() {
  lua_State* L = lua_newstate(&Sandbox::allocate, this);
  if (!L) return nullptr;
  lua_sethook(L, &Sandbox::hook, LUA_MASKCOUNT, kHookEvery);  // coroutines inherit it
  lua_atpanic(L, [](lua_State* S) -> int {
    std::fprintf(stderr, "tendril: unprotected Lua error: %s\n", lua_tostring(S, -1));
    return 0;
  });
  return L;
}

Sandbox* Sandbox::of(lua_State* L) {
  void* self = nullptr;
  return lua_getallocf(L, &self) == &Sandbox::allocate ? static_cast<Sandbox*>(self) : nullptr;
}

void Sandbox::restrict_libraries(lua_State* L) {
  if (luaL_loadbuffer(L, kRestrict, std::strlen(kRestrict), "=sandbox") != LUA_OK) lua_error(L);
  lua_pushcfunction(L, guarded<l_check_path>);
  lua_getglobal(L, "io");
  lua_getfield(L, -1, "open");
  lua_getfield(L, -2, "lines");
  lua_remove(L, -3);
  lua_getglobal(L, "load");
  lua_call(L, 4, 0);
}

std::string Sandbox::out_of_time() const {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%g", limits_.seconds);
  return std::string("--sandbox: the scene ran longer than its time limit of ") + seconds + " s";
}

void Sandbox::check_time() {
  if (std::chrono::steady_clock::now() > deadline_) throw std::runtime_error(stopped_ = out_of_time());
}

void* Sandbox::allocate(void* self, void* block, std::size_t old_size, std::size_t new_size) noexcept {
  auto* s = static_cast<Sandbox*>(self);
  const std::size_t had = block ? old_size : 0;  // without a block, old_size is a type tag
  if (new_size == 0) {
    std::free(block);
    s->heap_ -= had;
    return nullptr;
  }
  if (new_size > had && s->heap_ + (new_size - had) > s->heap_limit_) {
    s->stopped_ = "--sandbox: the scene's Lua memory reached its limit of " + std::to_string(s->limits_.memory_mb) + " MB";
    return nullptr;  // Lua raises "not enough memory"
  }
  void* moved = std::realloc(block, new_size);
  if (moved) s->heap_ = s->heap_ - had + new_size;
  return moved;
}

void Sandbox::hook(lua_State* L, lua_Debug*) {
  Sandbox* s = of(L);
  if (!s) return;
  if (s->production_left_ >= 0 && (s->production_left_ -= kHookEvery) < 0) {
    s->production_left_ = 0;  // every further look fails too, until the production ends
    s->stopped_ = "--sandbox: a rule application ran more than " + std::to_string(s->limits_.production_instructions) +
                  " Lua instructions";
    luaL_error(L, "%s", s->stopped_.c_str());
  }
  if (std::chrono::steady_clock::now() > s->deadline_) {
    s->stopped_ = s->out_of_time();
    luaL_error(L, "%s", s->stopped_.c_str());
  }
}

Sandbox::Production::Production(lua_State* L) : sandbox_(of(L)) {
  if (!sandbox_ || sandbox_->production_left_ >= 0) return;
  outer_ = true;
  sandbox_->production_left_ = sandbox_->limits_.production_instructions;
}

Sandbox::Production::~Production() {
  if (outer_) sandbox_->production_left_ = -1;
}

}  // namespace tendril::lua
