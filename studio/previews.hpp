#pragma once
// Timeline previews (the page's slider over the journal): the model after a
// production, replayed from the journal's lines on an empty model in a
// thread of its own, so a long replay never holds the solver up. Only the
// latest request counts: one still waiting when a newer comes is answered
// "superseded" and never replayed.
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <nlohmann/json.hpp>

namespace tendril::studio {

class Outbox;
using ClientId = std::uint64_t;

class Previews {
 public:
  explicit Previews(Outbox& out);
  ~Previews();
  // Replays `lines` (the journal up to production `index` of `of`), then
  // sends the asking page the preview's topology and frame and the reply
  // to its command (`id` echoed).
  void request(ClientId to, nlohmann::json id, std::size_t index, std::size_t of, std::vector<std::string> lines);

 private:
  struct Job {
    ClientId to;
    nlohmann::json id;
    std::size_t index, of;
    std::vector<std::string> lines;
  };
  void run();
  void reply(const Job& job, nlohmann::json body);

  Outbox& out_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::optional<Job> next_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace tendril::studio
