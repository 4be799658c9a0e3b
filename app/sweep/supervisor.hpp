#pragma once
// Runs planned runs as child processes, a few at once, and passes signals
// on. While a Supervisor lives SIGINT, SIGTERM, SIGHUP and SIGCHLD are
// blocked and taken synchronously (sigtimedwait): a stop signal is forwarded
// to every running child and no run starts after it; each child's end is
// recorded in its folder (run_folder.hpp) as soon as it is reaped. Children
// die with the supervisor even when it is SIGKILLed (PR_SET_PDEATHSIG), so a
// sweep never leaves orphans.
#include <sys/types.h>

#include <chrono>
#include <csignal>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "sweep/plan.hpp"
#include "sweep/run_folder.hpp"

namespace tendril::sweep {

class Supervisor {
 public:
  Supervisor(std::string tendril, const Plan& plan, std::string dir);
  ~Supervisor();  // restores the signal mask
  Supervisor(const Supervisor&) = delete;
  Supervisor& operator=(const Supervisor&) = delete;

  using OnEnd = std::function<void(const PlannedRun&, const Outcome&)>;
  // Runs the runs of `todo` (plan indices), `slots` at once, until all have
  // ended or a stop signal arrived and the running ones have ended. on_end
  // sees each run's outcome; tick runs at least every 0.2 s (progress).
  void run(const std::vector<int>& todo, int slots, const OnEnd& on_end, const std::function<void()>& tick);

  int running() const { return int(children_.size()); }
  // The stop signal that arrived, or 0.
  int stop_signal() const { return stop_; }

 private:
  struct Child {
    int index;
    std::chrono::steady_clock::time_point start;
  };
  void reap(const OnEnd& on_end);

  std::string tendril_, dir_;
  const Plan& plan_;
  sigset_t waited_, previous_;
  std::map<pid_t, Child> children_;
  int stop_ = 0;
};

// The supervisor's own end after a stop signal: its outputs written, it dies
// of the same signal (the default action), so its exit status says which.
[[noreturn]] void die_of(int sig);

}  // namespace tendril::sweep
