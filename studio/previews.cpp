#include "previews.hpp"

#include <cstring>
#include <exception>

#include "frames.hpp"
#include "session.hpp"
#include "timeline.hpp"

namespace tendril::studio {

Previews::Previews(Outbox& out) : out_(out), thread_([this] { run(); }) {}

Previews::~Previews() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void Previews::request(ClientId to, nlohmann::json id, std::size_t index, std::size_t of, std::vector<std::string> lines) {
  std::optional<Job> superseded;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    superseded.swap(next_);
    next_ = Job{to, std::move(id), index, of, std::move(lines)};
  }
  wake_.notify_all();
  if (superseded) reply(*superseded, {{"ok", false}, {"message", "a later timeline request replaced this one"}});
}

void Previews::reply(const Job& job, nlohmann::json body) {
  body["type"] = "reply";
  body["cmd"] = "timeline";
  if (!job.id.is_null()) body["id"] = job.id;
  out_.send(job.to, body.dump(), false);
}

void Previews::run() {
  while (true) {
    Job job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || next_; });
      if (stopping_) return;
      job = std::move(*next_);
      next_.reset();
    }
    try {
      Model m;
      Solver solver(m);
      replay_lines(job.lines, m, solver);
      Topology t = topology_of(m);
      t.revision = 0;
      std::string topo = encode(t), frame = encode_frame(m, solver, t, {});
      std::memcpy(topo.data(), &kPreviewTopology, 4);
      std::memcpy(frame.data(), &kPreviewFrame, 4);
      out_.send(job.to, topo, true);
      out_.send(job.to, frame, true);
      reply(job, {{"ok", true},
                  {"value", {{"index", job.index}, {"of", job.of}, {"steps", solver.steps()}, {"particles", m.particle_count()}}}});
    } catch (const std::exception& e) {
      reply(job, {{"ok", false}, {"message", e.what()}});
    }
  }
}

}  // namespace tendril::studio
