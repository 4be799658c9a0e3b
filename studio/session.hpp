#pragma once
// A studio session (thesis 5.4.1.1): the scene runs on the solver thread and
// keeps integrating after it returned; the page's commands wait in a queue
// and are applied between solver steps through the scene's own bindings
// (lua_bridge.hpp), so the model is only ever touched by that thread, every
// command is journaled like a production, and the session's journal replays
// to the same model. Frames of positions go to the Outbox (the server).
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "frames.hpp"
#include "lua_host.hpp"
#include "previews.hpp"
#include "timeline.hpp"

struct lua_State;

namespace tendril::studio {

using json = nlohmann::json;
using ClientId = std::uint64_t;

// Where the session's messages go; called from the solver thread.
class Outbox {
 public:
  virtual ~Outbox() = default;
  // The latest frame, at each page's rate; an urgent one (the first to show
  // a command's effect) goes out at once. With `topology` (the frame is the
  // first drawn on it) both change together: a page gets the topology and,
  // as soon as it took its last frame, this one, and never a frame of an
  // older topology after it.
  virtual void frame(std::shared_ptr<const std::string> bytes, bool urgent,
                     std::shared_ptr<const std::string> topology = nullptr) = 0;
  virtual void send(ClientId to, const std::string& bytes, bool binary) = 0;
  virtual void broadcast(const std::string& text) = 0;
  virtual bool wants_frame() const = 0;  // a page is due a frame (cheap: called after every step)
};

struct SessionOptions {
  std::string scene;     // the scene file
  SceneOptions run;      // out_dir, seed, params, preload (the studio's own chunk goes first)
  double tolerance = 1e-3;  // equilibrium of the live loop [N]
  double speed = 2000;      // at most this many steps per second, so growth can be watched; 0: no limit
  bool wait_for_page = true;  // the scene starts when the first page said hello
};

class Session {
 public:
  Session(SessionOptions options, Outbox& out);
  ~Session();
  // Any thread.
  void post(ClientId from, json command);  // a command the server parsed (see is_command)
  void stop();                              // saves the model, journal and OBJ; run() returns
  static bool is_command(const std::string& name);
  // The solver thread: runs the scene, then keeps the model integrating
  // until stop(). Returns 0, or 1 when the scene failed and the session was
  // stopped without a model.
  int run();

 private:
  struct Command {
    ClientId from;
    json body;
  };
  using Handler = json (Session::*)(lua_State*, const json&);
  struct CommandSpec {
    const char* name;
    Handler handler;
    bool changes_model;  // an undo point is taken before it
  };
  static const std::vector<CommandSpec>& commands();

  bool after_step(lua_State* L);
  void live(lua_State* L);
  void bind(lua_State* L, int model_index);
  bool apply_queued(lua_State* L);  // true when the model changed
  void wait_for_commands(std::chrono::milliseconds timeout);
  void publish(bool force, bool urgent = false);
  void build_frame(bool force, bool urgent);
  bool frame_error_ = false;
  bool show_next_step_ = false;  // a command changed the model: the frame after the next step shows it
  void broadcast_status();
  std::size_t production_count(const lua::Scene& s);  // incremental: the journal only grows between rewinds
  struct {
    std::size_t lines = 0, productions = 0;
  } counted_;
  void save(lua_State* L);
  json hello(lua_State* L) const;
  void go_to(const JournalPoint& p);  // restore, then a fresh topology

  struct GoalsOnly;
  json cmd_hello(lua_State*, const json&);
  json cmd_pause(lua_State*, const json&);
  json cmd_resume(lua_State*, const json&);
  json cmd_step(lua_State*, const json&);
  json cmd_drag(lua_State*, const json&);
  json cmd_release(lua_State*, const json&);
  json cmd_lock(lua_State*, const json&);
  json cmd_unlock(lua_State*, const json&);
  json cmd_rule(lua_State*, const json&);
  json cmd_settings(lua_State*, const json&);
  json cmd_formulation(lua_State*, const json&);
  json cmd_param(lua_State*, const json&);
  json cmd_field(lua_State*, const json&);
  json cmd_undo(lua_State*, const json&);
  json cmd_save(lua_State*, const json&);
  json cmd_timeline(lua_State*, const json&);
  json cmd_branch(lua_State*, const json&);
  json cmd_apply(lua_State*, const json&);
  json cmd_commands(lua_State*, const json&);

  SessionOptions options_;
  Outbox& out_;
  Previews previews_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Command> queue_;
  std::atomic<bool> stopping_{false};
  bool greeted_ = false;  // a page said hello (guarded by mutex_)
  bool restart_ = false;  // a parameter changed: the scene runs again
  ClientId replying_to_ = 0;

  // Solver thread only.
  int model_ref_ = -2;  // LUA_NOREF
  lua_State* L_ = nullptr;
  bool live_ = false;  // the scene returned; the session's own loop steps the model
  bool paused_ = false;
  std::int64_t step_budget_ = 0;  // steps still to take while paused
  bool converged_ = false;
  std::string field_;
  Topology topology_;
  std::uint64_t topology_model_revision_ = ~0ull;
  std::uint32_t topology_tag_ = 0;
  // What the last frame showed: a page that is due a frame gets none while
  // the solver has not stepped and nothing else moved (paused, at rest).
  struct {
    std::uint64_t steps = ~0ull;
    std::uint32_t topology = 0;
    bool stale = true;  // a page said hello, a colour map changed, the model was rewound
  } shown_;
  std::vector<std::shared_ptr<std::string>> frame_buffers_;  // recycled once the server let go of them
  std::shared_ptr<std::string> free_frame_buffer();
  std::chrono::steady_clock::time_point next_step_{};  // the speed limit
  void pace();
  std::vector<JournalPoint> undo_, snapshots_;
  struct Drag {
    bool active = false;
    ParticleId particle = 0;
    std::int64_t goal = 0;  // 1-based, as m:anchor returns it
  } drag_;
};

}  // namespace tendril::studio
