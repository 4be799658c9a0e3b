#pragma once
// tendril run --sandbox (SandboxLimits in lua_host.hpp): the Lua state of a
// scene that is not the user's own.
//   - memory: an allocator that refuses Lua's heap beyond memory_mb;
//   - time: a count hook that stops a rule application after
//     production_instructions VM instructions (deterministic) and the whole
//     scene after `seconds` of wall time (also checked after every solver
//     step, which runs in C++ where no hook fires);
//   - libraries: no package, require, dofile, loadfile or debug; load takes
//     text chunks only; io.open and io.lines only inside the output folder
//     (reads also beside the scene); os keeps clock, time, date, difftime.
// Files tendril itself writes or reads for the scene follow the same folders
// (io/file_policy.hpp).
#include <lua.hpp>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>

#include "lua_host.hpp"

namespace tendril::lua {

class Sandbox {
 public:
  explicit Sandbox(const SandboxLimits& limits);
  Sandbox(const Sandbox&) = delete;
  Sandbox& operator=(const Sandbox&) = delete;
  // A new Lua state under this sandbox's allocator and hook (close it before
  // the sandbox goes). Open the libraries, then restrict them.
  lua_State* new_state();
  static void restrict_libraries(lua_State* L);
  // Throws std::runtime_error when the scene's time is up (between steps).
  void check_time();
  // Why the scene was stopped, when the sandbox stopped it ("" otherwise).
  const std::string& stopped() const { return stopped_; }

  // The sandbox of L, or nullptr when L is not sandboxed.
  static Sandbox* of(lua_State* L);

  // Counts the instructions of one rule application (nested ones join the outer).
  class Production {
   public:
    explicit Production(lua_State* L);
    ~Production();
   private:
    Sandbox* sandbox_;
    bool outer_ = false;
  };

 private:
  static void* allocate(void* self, void* block, std::size_t old_size, std::size_t new_size) noexcept;
  static void hook(lua_State* L, lua_Debug*);
  std::string out_of_time() const;
  SandboxLimits limits_;
  std::size_t heap_ = 0, heap_limit_;
  std::chrono::steady_clock::time_point deadline_;
  std::int64_t production_left_ = -1;  // -1: not in a production
  std::string stopped_;
};

}  // namespace tendril::lua
