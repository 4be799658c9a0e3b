#include "session.hpp"

#include <lua.hpp>

#include <cmath>
#include <cstdio>
#include <optional>
#include <filesystem>
#include <stdexcept>

#include "fields.hpp"
#include "command/json_form.hpp"
#include "command/session.hpp"
#include "lua_bridge.hpp"

namespace tendril::studio {

extern const char* const kStudioLua;  // studio.lua, compiled in (studio_lua.cpp)

namespace {

// Unwinds a running scene when the session stops or restarts (thrown from
// after_step, through the binding that stepped, into the scene's error path).
struct Interrupted : std::runtime_error {
  Interrupted() : std::runtime_error("the studio session was stopped") {}
};

std::string number_or(const json& c, const char* key, double fallback, double& out) {
  out = fallback;
  if (!c.contains(key)) return {};
  if (!c[key].is_number() || !std::isfinite(c[key].get<double>())) return std::string("'") + key + "' must be a finite number";
  out = c[key].get<double>();
  return {};
}

json ok(json value = nullptr) { return {{"ok", true}, {"value", std::move(value)}}; }
json refused(std::string why) { return {{"ok", false}, {"message", std::move(why)}}; }
json from(const CallResult& r) { return r.ok ? ok(r.value) : refused(r.message); }
// A command whose reply is sent later, by someone else (a timeline preview).
const json kAnsweredLater = {{"answered", "later"}};

json particle_arg(const json& c) {
  if (!c.contains("particle")) throw std::runtime_error("'particle' is required (a particle id)");
  return json{{"particle", c["particle"]}};
}

}  // namespace

const std::vector<Session::CommandSpec>& Session::commands() {
  // One line per command the page may send (docs/studio.md lists them).
  static const std::vector<CommandSpec> all = {
      {"hello", &Session::cmd_hello, false},
      {"pause", &Session::cmd_pause, false},
      {"run", &Session::cmd_resume, false},
      {"step", &Session::cmd_step, false},
      {"drag", &Session::cmd_drag, true},
      {"release", &Session::cmd_release, false},
      {"lock", &Session::cmd_lock, true},
      {"unlock", &Session::cmd_unlock, true},
      {"rule", &Session::cmd_rule, true},
      {"settings", &Session::cmd_settings, true},
      {"formulation", &Session::cmd_formulation, true},
      {"param", &Session::cmd_param, false},
      {"field", &Session::cmd_field, false},
      {"undo", &Session::cmd_undo, false},
      {"save", &Session::cmd_save, false},
      {"timeline", &Session::cmd_timeline, false},
      {"branch", &Session::cmd_branch, true},
      {"apply", &Session::cmd_apply, true},
      {"commands", &Session::cmd_commands, false},
  };
  return all;
}

bool Session::is_command(const std::string& name) {
  for (const CommandSpec& c : commands())
    if (name == c.name) return true;
  return false;
}

Session::Session(SessionOptions options, Outbox& out) : options_(std::move(options)), out_(out), previews_(out) {
  options_.run.preload.insert(options_.run.preload.begin(), {"studio/studio.lua", kStudioLua});
  options_.run.progress = false;
  options_.run.after_step = [this](lua_State* L) { return after_step(L); };
  options_.run.after_scene = [this](lua_State* L) { live(L); };
}

Session::~Session() = default;

void Session::post(ClientId from, json command) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (command.value("cmd", "") == "hello") greeted_ = true;
    queue_.push_back({from, std::move(command)});
  }
  wake_.notify_all();
}

void Session::stop() {
  stopping_ = true;
  wake_.notify_all();
}

int Session::run() {
  if (options_.wait_for_page) {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait(lock, [&] { return greeted_ || stopping_.load(); });
  }
  if (stopping_) return 0;
  int status = 0;
  while (true) {
    model_ref_ = LUA_NOREF;
    L_ = nullptr;
    live_ = false;
    restart_ = false;
    undo_.clear();
    snapshots_.clear();
    counted_ = {};
    drag_ = {};
    std::string error;
    status = run_scene(options_.scene, options_.run, &error);
    model_ref_ = LUA_NOREF;
    L_ = nullptr;
    if (restart_ && !stopping_) continue;
    if (stopping_) return 0;
    // The scene failed: say why on the terminal and the pages, and wait for
    // a parameter that makes it work, or for Ctrl-C.
    std::fprintf(stderr, "tendril: studio: %s\n", error.c_str());
    out_.broadcast(json{{"type", "error"}, {"message", error}}.dump());
    while (!stopping_ && !restart_) {
      wait_for_commands(std::chrono::milliseconds(200));
      apply_queued(nullptr);
    }
    if (stopping_) return status;
  }
}

void Session::bind(lua_State* L, int model_index) {
  L_ = L;
  lua_pushvalue(L, model_index);
  auto* slot = static_cast<lua::Scene**>(luaL_testudata(L, -1, lua::kModelMeta));
  if (!slot || !*slot) {
    lua_pop(L, 1);
    return;
  }
  if (model_ref_ != LUA_NOREF) {
    if (&scene_of(L, model_ref_) == *slot) {
      lua_pop(L, 1);
      return;
    }
    luaL_unref(L, LUA_REGISTRYINDEX, model_ref_);  // the scene moved on to another model
  }
  model_ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
  topology_model_revision_ = ~0ull;
  shown_.stale = true;
  out_.broadcast(json{{"type", "reload"}}.dump());  // pages ask hello again: new palette, params
}

void Session::pace() {
  if (options_.speed <= 0) return;
  const auto now = std::chrono::steady_clock::now();
  const auto period = std::chrono::nanoseconds(std::int64_t(1e9 / options_.speed));
  if (next_step_ < now - std::chrono::milliseconds(50)) next_step_ = now;  // no catching up after a pause
  next_step_ += period;
  if (next_step_ > now) {
    std::unique_lock<std::mutex> lock(mutex_);
    wake_.wait_until(lock, next_step_, [&] { return !queue_.empty() || stopping_.load(); });
  }
}

bool Session::after_step(lua_State* L) {
  bind(L, 1);
  if (show_next_step_) {
    publish(true, true);
    show_next_step_ = false;
  }
  pace();
  bool changed = apply_queued(L);
  publish(false);
  while (paused_ && step_budget_ == 0 && !stopping_ && !restart_) {
    wait_for_commands(std::chrono::milliseconds(50));
    changed |= apply_queued(L);
    publish(false);
  }
  if (step_budget_ > 0 && --step_budget_ == 0) broadcast_status();
  if (stopping_ && !live_) save(L);  // the scene unwinds next: save while the model is there
  if (stopping_ || restart_) throw Interrupted();
  return changed;
}

void Session::live(lua_State* L) {
  L_ = L;
  live_ = true;
  if (model_ref_ == LUA_NOREF) {  // the scene never stepped: watch the last model it made
    lua_getglobal(L, "tendril");
    lua_getfield(L, -1, "studio");
    lua_getfield(L, -1, "last");
    if (!lua_isnil(L, -1)) bind(L, lua_gettop(L));
    lua_settop(L, 0);
  }
  if (model_ref_ == LUA_NOREF) throw std::runtime_error("the scene made no model to watch");
  std::fprintf(stderr, "tendril: studio: the scene returned; the model keeps integrating\n");
  converged_ = false;
  while (!stopping_ && !restart_) {
    const bool changed = apply_queued(L);
    if (changed) converged_ = false;
    publish(false);
    if ((paused_ && step_budget_ == 0) || (converged_ && !paused_)) {
      wait_for_commands(std::chrono::milliseconds(100));
      continue;
    }
    const std::int64_t chunk = paused_ ? step_budget_ : 200;
    const CallResult r = [&] {
      try {
        return call_method(L, model_ref_, "run",
                           json::array({{{"tolerance", options_.tolerance}, {"max_steps", chunk}}}));
      } catch (const Interrupted&) {
        return CallResult{false, "interrupted", nullptr};
      }
    }();
    if (stopping_ || restart_) break;
    if (!r.ok) {  // the message names the element at fault (a NaN, a rule's error)
      if (r.message.find("the studio session was stopped") != std::string::npos) break;
      out_.broadcast(json{{"type", "error"}, {"message", r.message}}.dump());
      paused_ = true;
      broadcast_status();
      continue;
    }
    if (!paused_ && r.value.is_array() && !r.value.empty() && r.value[0].value("converged", false)) {
      converged_ = true;
      snapshots_.push_back(point_of(scene_of(L, model_ref_), "equilibrium"));
      publish(true);
      broadcast_status();
    }
  }
  if (stopping_) save(L);
}

void Session::wait_for_commands(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  wake_.wait_for(lock, timeout, [&] { return !queue_.empty() || stopping_; });
}

bool Session::apply_queued(lua_State* L) {
  std::deque<Command> batch;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    batch.swap(queue_);
  }
  bool changed = false;
  for (std::size_t k = 0; k < batch.size(); ++k) {
    const Command& c = batch[k];
    const std::string name = c.body.value("cmd", "");
    // Drags coalesce: only the latest target before the next step matters.
    if (name == "drag" && k + 1 < batch.size() && batch[k + 1].body.value("cmd", "") == "drag" &&
        batch[k + 1].body.value("particle", -1) == c.body.value("particle", -2))
      continue;
    json reply;
    replying_to_ = c.from;
    const CommandSpec* spec = nullptr;
    for (const CommandSpec& s : commands())
      if (name == s.name) spec = &s;
    try {
      if (!spec) reply = refused("unknown command '" + name + "'");
      else if (!L && name != "param" && name != "hello") reply = refused("no model: the scene failed (change a parameter)");
      else {
        const std::uint64_t before = L && model_ref_ != LUA_NOREF ? scene_of(L, model_ref_).model.revision : 0;
        const std::size_t lines = L && model_ref_ != LUA_NOREF ? scene_of(L, model_ref_).trace.mark().lines : 0;
        std::optional<JournalPoint> undo_point;
        if (spec->changes_model && !(name == "drag" && drag_.active)) undo_point = point_of(scene_of(L, model_ref_), name);
        reply = (this->*spec->handler)(L, c.body);
        if (L && model_ref_ != LUA_NOREF) {
          const lua::Scene& s = scene_of(L, model_ref_);
          const bool moved = s.model.revision != before || s.trace.mark().lines != lines;
          changed |= moved;
          if (undo_point && moved && reply.value("ok", false)) undo_.push_back(*undo_point);
        }
      }
    } catch (const Interrupted&) {
      throw;
    } catch (const std::exception& e) {
      reply = refused(e.what());
    }
    if (reply != kAnsweredLater) {
      reply["type"] = "reply";
      reply["cmd"] = name;
      if (c.body.contains("id")) reply["id"] = c.body["id"];
      out_.send(c.from, reply.dump(), false);
    }
    if (spec && name != "field") broadcast_status();
  }
  if (changed) show_next_step_ = true;  // drag-to-frame latency: one step, then the frame
  return changed;
}

void Session::publish(bool force, bool urgent) {
  if (!L_ || model_ref_ == LUA_NOREF) return;
  try {
    build_frame(force, urgent);
  } catch (const std::exception& e) {  // a drawing problem never stops the scene; say it once
    if (!frame_error_) out_.broadcast(json{{"type", "error"}, {"message", std::string("frame: ") + e.what()}}.dump());
    frame_error_ = true;
    topology_model_revision_ = ~0ull;  // the topology built with it was not sent either: again next time
    shown_.stale = true;
  }
}

void Session::build_frame(bool force, bool urgent) {
  if (!force && !out_.wants_frame()) return;
  const lua::Scene& s = scene_of(L_, model_ref_);
  std::shared_ptr<const std::string> new_topology;  // sent with the frame: never one without the other
  if (s.model.revision != topology_model_revision_) {
    Topology t = topology_of(s.model);
    topology_model_revision_ = s.model.revision;
    if (shown_.stale || !t.same_drawing(topology_)) {
      topology_ = std::move(t);
      topology_.revision = ++topology_tag_;
      new_topology = std::make_shared<const std::string>(encode(topology_));
    }
  }
  if (!force && !shown_.stale && shown_.steps == s.solver.steps() && shown_.topology == topology_tag_) return;
  shown_ = {s.solver.steps(), topology_tag_, false};
  std::vector<float> values;
  if (const Field* f = find_field(field_)) values = f->values(s.model, topology_);
  std::shared_ptr<std::string> frame = free_frame_buffer();
  encode_frame(s.model, s.solver, topology_, values, *frame);
  out_.frame(std::move(frame), urgent, std::move(new_topology));
}

// A frame is written into a buffer the server no longer holds (its only
// owner is this list), so a live session allocates none after the first few.
std::shared_ptr<std::string> Session::free_frame_buffer() {
  for (const auto& b : frame_buffers_)
    if (b.use_count() == 1) {
      std::atomic_thread_fence(std::memory_order_acquire);  // the sender's last read of it happened before
      return b;
    }
  frame_buffers_.push_back(std::make_shared<std::string>());
  return frame_buffers_.back();
}

std::size_t Session::production_count(const lua::Scene& s) {
  if (counted_.lines > s.trace.size()) counted_ = {};  // the journal was rewound (undo, branch)
  for (; counted_.lines < s.trace.size(); ++counted_.lines) counted_.productions += is_production(s.trace.line(counted_.lines));
  return counted_.productions;
}

void Session::broadcast_status() {
  if (!L_ || model_ref_ == LUA_NOREF) return;
  const lua::Scene& s = scene_of(L_, model_ref_);
  json snaps = json::array();
  for (const JournalPoint& p : snapshots_)
    snaps.push_back({{"steps", p.steps}, {"residual", p.residual}, {"productions", p.mark.lines}, {"label", p.label}});
  out_.broadcast(json{{"type", "status"},
                      {"paused", paused_},
                      {"converged", converged_},
                      {"steps", s.solver.steps()},
                      {"particles", s.model.particle_count()},
                      {"blocks", s.model.block_count()},
                      {"productions", production_count(s)},
                      {"journal", s.journal.entries.size()},
                      {"undo", undo_.size()},
                      {"snapshots", snaps}}
                     .dump());
}

void Session::save(lua_State* L) {
  if (model_ref_ == LUA_NOREF) return;
  std::filesystem::create_directories(options_.run.out_dir);
  const std::string dir = options_.run.out_dir + "/";
  for (auto [method, file] : {std::pair{"save", "model.xml"}, std::pair{"save_obj", "model.obj"},
                              std::pair{"save_journal", "journal.txt"}}) {
    const CallResult r = call_method(L, model_ref_, method, json::array({dir + file}));
    if (!r.ok) std::fprintf(stderr, "tendril: studio: %s failed: %s\n", method, r.message.c_str());
  }
  std::fprintf(stderr, "tendril: studio: saved %smodel.xml, %smodel.obj and %sjournal.txt\n", dir.c_str(), dir.c_str(),
               dir.c_str());
}

json Session::hello(lua_State* L) const {
  json f = json::array();
  for (const Field& field : fields()) f.push_back({{"name", field.name}, {"unit", field.unit}});
  json names = json::array();
  for (const CommandSpec& c : commands()) names.push_back(c.name);
  json settings = nullptr;
  if (L && model_ref_ != LUA_NOREF) settings = call_method(L, model_ref_, "settings", json::array()).value;
  return {{"scene", options_.scene},
          {"out", options_.run.out_dir},
          {"commands", names},
          {"palette", L ? studio_list(L, "palette") : json::array()},
          {"params", L ? studio_list(L, "parameters") : json::array()},
          {"settings", settings.is_array() && !settings.empty() ? settings[0] : json(nullptr)},
          {"tolerance", options_.tolerance},
          {"speed", options_.speed},
          {"fields", f},
          {"field", field_}};
}

void Session::go_to(const JournalPoint& p) {
  lua::Scene& s = scene_of(L_, model_ref_);
  restore(s, p);
  counted_ = {};
  drag_ = {};
  converged_ = false;
  topology_model_revision_ = ~0ull;
  shown_.stale = true;
}

// --- the commands -------------------------------------------------------------

json Session::cmd_hello(lua_State* L, const json&) {
  topology_model_revision_ = ~0ull;  // the new page needs the topology
  shown_.stale = true;
  return ok(hello(L));
}

json Session::cmd_pause(lua_State*, const json&) {
  paused_ = true;
  step_budget_ = 0;
  return ok();
}

json Session::cmd_resume(lua_State*, const json&) {
  paused_ = false;
  step_budget_ = 0;
  converged_ = false;
  return ok();
}

json Session::cmd_step(lua_State*, const json& c) {
  double n = 1;
  if (std::string e = number_or(c, "n", 1, n); !e.empty()) return refused(e);
  if (n < 1 || n > 1e6 || n != std::floor(n)) return refused("'n' must be a whole number of steps, 1 to 1000000");
  paused_ = true;
  step_budget_ = std::int64_t(n);
  return ok();
}

// A drag changes goals only, which the page does not draw: the model's
// revision moves, the topology the pages have stays (no topology_of per
// mouse move).
struct Session::GoalsOnly {
  GoalsOnly(Session& s, const Model& m) : session(s), model(m), current(s.topology_model_revision_ == m.revision) {}
  ~GoalsOnly() {
    if (current) session.topology_model_revision_ = model.revision;
  }
  Session& session;
  const Model& model;
  const bool current;
};

// A goal while the mouse is held (thesis 5.4.1.1): an anchor at the cursor,
// a hundred times as stiff as the particle's elements, moved by replacing it.
json Session::cmd_drag(lua_State* L, const json& c) {
  const json p = particle_arg(c);
  const GoalsOnly drawing_unchanged(*this, scene_of(L, model_ref_).model);
  if (!c.contains("to") || !c["to"].is_array() || c["to"].size() != 3) return refused("'to' must be [x, y, z]");
  for (const json& v : c["to"])
    if (!v.is_number() || !std::isfinite(v.get<double>())) return refused("'to' must hold three finite numbers");
  lua::Scene& s = scene_of(L, model_ref_);
  const ParticleId id = p["particle"].is_number_unsigned() ? p["particle"].get<ParticleId>() : kNone;
  if (drag_.active && (drag_.particle != id || !s.model.particle_valid(id))) cmd_release(L, c);
  if (drag_.active) {
    const CallResult r = call_method(L, model_ref_, "remove_goal", json::array({drag_.goal}));
    drag_.active = false;
    if (!r.ok) return from(r);
  }
  if (id == kNone || !s.model.particle_valid(id)) return refused("particle " + p["particle"].dump() + " does not exist");
  const double weight = std::max(1e3, 100 * s.model.particles.stiffness[id]);
  const CallResult r = call_method(L, model_ref_, "anchor", json::array({p, c["to"], weight}));
  if (!r.ok) return from(r);
  drag_ = {true, id, r.value[0].get<std::int64_t>()};
  converged_ = false;
  return ok(json{{"goal", drag_.goal}, {"step", s.solver.steps()}});
}

json Session::cmd_release(lua_State* L, const json&) {
  if (!drag_.active) return ok();
  const GoalsOnly drawing_unchanged(*this, scene_of(L, model_ref_).model);
  drag_.active = false;
  converged_ = false;
  return from(call_method(L, model_ref_, "remove_goal", json::array({drag_.goal})));
}

json Session::cmd_lock(lua_State* L, const json& c) {
  return from(call_method(L, model_ref_, "lock", json::array({particle_arg(c), c.value("axes", "xyz")})));
}

// Any command of docs/commands.md in its JSON form, checked and journaled
// by the command layer like a scene's call. Not `open` (a page names no
// file on the server) nor `steps` and `failed_step` (the step command paces the solver).
json Session::cmd_apply(lua_State* L, const json& c) {
  const auto [declared, args] =
      command::from_json({{"command", c.value("command", json())}, {"args", c.value("args", json::object())}});
  const std::string name = declared->name;
  if (name == "open" || declared->effect == command::Effect::Steps)
    return refused("apply: '" + name + "' is not for the page (use step, or --out files)");
  const command::Result r = command::apply(scene_of(L, model_ref_).session, *declared, args);
  converged_ = false;
  return ok(command::result_json(r));
}

json Session::cmd_commands(lua_State*, const json&) { return ok(command::declarations_json()); }

json Session::cmd_unlock(lua_State* L, const json& c) {
  return from(call_method(L, model_ref_, "unlock", json::array({particle_arg(c), c.value("axes", "xyz")})));
}

json Session::cmd_rule(lua_State* L, const json& c) {
  if (!c.contains("rule") || !c["rule"].is_string()) return refused("'rule' must name a rule of the palette");
  const CallResult r = apply_rule(L, model_ref_, c["rule"].get<std::string>(), c.value("args", json::array()));
  if (r.ok) converged_ = false;
  return from(r);
}

json Session::cmd_settings(lua_State* L, const json& c) {
  if (!c.contains("settings") || !c["settings"].is_object()) return refused("'settings' must be an object");
  json settings = c["settings"];
  if (settings.contains("tolerance")) {
    double t = 0;
    if (std::string e = number_or(settings, "tolerance", 0, t); !e.empty() || !(t > 0)) return refused("'tolerance' must be > 0");
    options_.tolerance = t;
    settings.erase("tolerance");
  }
  if (settings.contains("speed")) {
    double v = 0;
    if (std::string e = number_or(settings, "speed", 0, v); !e.empty() || v < 0) return refused("'speed' must be >= 0 steps/s (0: no limit)");
    options_.speed = v;
    settings.erase("speed");
  }
  converged_ = false;
  if (settings.empty()) return ok();
  return from(call_method(L, model_ref_, "settings", json::array({settings})));
}

json Session::cmd_formulation(lua_State* L, const json& c) {
  if (!c.contains("block")) return refused("'block' is required (a block id)");
  json args = json::array({json{{"block", c["block"]}}});
  if (c.contains("dofs")) args.push_back(c["dofs"]);
  else if (c.value("membrane", "") == "bars") args.push_back("bars");
  else if (c.value("membrane", "") == "cst") {
    args.push_back("cst");
    args.push_back(json{{"stress", c.value("stress", json::array({1000.0, 1000.0}))}});
  } else return refused("give 'dofs' (3 or 6) for a beam or 'membrane' (\"bars\" or \"cst\") for a patch");
  return from(call_method(L, model_ref_, "formulation", args));
}

// tendril.param values are read as the scene builds the model: a new value
// runs the scene again from the start (a fresh journal).
json Session::cmd_param(lua_State*, const json& c) {
  if (!c.contains("name") || !c["name"].is_string() || c["name"].get<std::string>().empty())
    return refused("'name' must name a parameter");
  if (!c.contains("value") || !(c["value"].is_number() || c["value"].is_string()))
    return refused("'value' must be a number or a string");
  const std::string name = c["name"], value = c["value"].is_string() ? c["value"].get<std::string>() : c["value"].dump();
  bool found = false;
  for (auto& [k, v] : options_.run.params)
    if (k == name) v = value, found = true;
  if (!found) options_.run.params.push_back({name, value});
  restart_ = true;
  return ok();
}

json Session::cmd_field(lua_State*, const json& c) {
  const std::string name = c.value("name", "");
  if (!name.empty() && !find_field(name)) return refused("no colour map '" + name + "'");
  field_ = name;
  shown_.stale = true;
  return ok();
}

json Session::cmd_undo(lua_State*, const json&) {
  if (undo_.empty()) return refused("nothing to undo");
  const JournalPoint p = undo_.back();
  undo_.pop_back();
  go_to(p);
  return ok(json{{"steps", p.steps}, {"undid", p.label}});
}

json Session::cmd_save(lua_State* L, const json&) {
  save(L);
  return ok(options_.run.out_dir);
}

// The model after production `index` (0: before the first), replayed on an
// empty model (Previews, off the solver thread) and sent to the asking page.
json Session::cmd_timeline(lua_State* L, const json& c) {
  const lua::Scene& s = scene_of(L, model_ref_);
  const std::vector<std::size_t> prods = productions(s);
  double index = 0;
  if (std::string e = number_or(c, "index", 0, index); !e.empty()) return refused(e);
  if (index < 0 || index > double(prods.size()) || index != std::floor(index))
    return refused("'index' must be 0 to " + std::to_string(prods.size()));
  const std::size_t k = std::size_t(index), n = k == 0 ? 0 : prods[k - 1] + 1;
  std::vector<std::string> lines;
  lines.reserve(n);
  for (std::size_t i = 0; i < n; ++i) lines.push_back(s.trace.line(i));
  previews_.request(replying_to_, c.value("id", json()), k, prods.size(), std::move(lines));
  return kAnsweredLater;
}

// Back to a snapshot (an equilibrium) or a production, and on from there.
json Session::cmd_branch(lua_State* L, const json& c) {
  const lua::Scene& s = scene_of(L, model_ref_);
  JournalPoint p;
  if (c.contains("snapshot")) {
    double k = 0;
    if (std::string e = number_or(c, "snapshot", 0, k); !e.empty()) return refused(e);
    if (k < 0 || k >= double(snapshots_.size()) || k != std::floor(k)) return refused("no snapshot " + c["snapshot"].dump());
    p = snapshots_[std::size_t(k)];
  } else if (c.contains("index")) {
    const std::vector<std::size_t> prods = productions(s);
    double index = 0;
    if (std::string e = number_or(c, "index", 0, index); !e.empty()) return refused(e);
    if (index < 1 || index > double(prods.size()) || index != std::floor(index))
      return refused("'index' must be 1 to " + std::to_string(prods.size()));
    // The point right after that production: its line, with the steps before it.
    p = point_of(s, "branch");
    p.mark.lines = prods[std::size_t(index) - 1] + 1;
    std::uint64_t steps = 0;
    std::size_t failures = 0;
    const std::vector<std::string> lines = s.trace.lines(s.solver);
    for (std::size_t k = 0; k < p.mark.lines; ++k) {
      if (lines[k].rfind("steps ", 0) == 0) steps += std::stoull(lines[k].substr(6));
      failures += lines[k] == "failed_step";
    }
    p.mark.steps = p.steps = steps;
    p.mark.failures = p.failures = failures;
    std::size_t entries = 0;  // assembly entries made at or before that step
    while (entries < s.journal.entries.size() && s.journal.entries[entries].step <= steps) ++entries;
    p.journal = entries;
  } else {
    return refused("give 'snapshot' (its index) or 'index' (a production)");
  }
  go_to(p);
  return ok(json{{"steps", p.steps}});
}

}  // namespace tendril::studio
