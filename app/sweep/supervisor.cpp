#include "sweep/supervisor.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <ctime>

namespace tendril::sweep {

namespace {

bool is_stop(int sig) { return sig == SIGINT || sig == SIGTERM || sig == SIGHUP; }

}  // namespace

Supervisor::Supervisor(std::string tendril, const Plan& plan, std::string dir)
    : tendril_(std::move(tendril)), dir_(std::move(dir)), plan_(plan) {
  sigemptyset(&waited_);
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGCHLD}) sigaddset(&waited_, sig);
  sigprocmask(SIG_BLOCK, &waited_, &previous_);
}

Supervisor::~Supervisor() { sigprocmask(SIG_SETMASK, &previous_, nullptr); }

void Supervisor::reap(const OnEnd& on_end) {
  int status = 0;
  for (pid_t pid; (pid = waitpid(-1, &status, WNOHANG)) > 0;) {
    auto it = children_.find(pid);
    if (it == children_.end()) continue;
    const PlannedRun& r = plan_.runs[std::size_t(it->second.index - 1)];
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - it->second.start).count();
    children_.erase(it);
    const Outcome o = record_end(run_dir(dir_, r.index), status, seconds, stop_);
    if (on_end) on_end(r, o);
  }
}

void Supervisor::run(const std::vector<int>& todo, int slots, const OnEnd& on_end,
                     const std::function<void()>& tick) {
  std::size_t next = 0;
  for (;;) {
    while (!stop_ && running() < slots && next < todo.size()) {
      const PlannedRun& r = plan_.runs[std::size_t(todo[next++] - 1)];
      const pid_t pid = start_run(tendril_, plan_, r, run_dir(dir_, r.index));
      children_[pid] = {r.index, std::chrono::steady_clock::now()};
    }
    reap(on_end);
    if (children_.empty() && (stop_ || next >= todo.size())) break;
    if (tick) tick();
    if (running() == slots || stop_ || next >= todo.size()) {
      timespec wait{0, 200'000'000};
      siginfo_t info;
      const int sig = sigtimedwait(&waited_, &info, &wait);
      if (sig > 0 && is_stop(sig)) {
        // A second signal is passed on too: a child that ignores the first
        // gets it again.
        stop_ = sig;
        for (const auto& [pid, child] : children_) kill(pid, sig);
      }
    }
  }
  if (tick) tick();
}

void die_of(int sig) {
  std::signal(sig, SIG_DFL);
  sigset_t just;
  sigemptyset(&just);
  sigaddset(&just, sig);
  sigprocmask(SIG_UNBLOCK, &just, nullptr);
  raise(sig);
  _exit(128 + sig);
}

}  // namespace tendril::sweep
