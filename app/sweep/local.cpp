#include "sweep/local.hpp"

#include <chrono>
#include <cstdio>
#include <cstring>

#include "io/status_line.hpp"
#include "sweep/summary.hpp"
#include "sweep/supervisor.hpp"

namespace tendril::sweep {

namespace {

using Clock = std::chrono::steady_clock;

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

void run_local(const std::string& tendril, const Plan& plan, const std::string& dir, const std::vector<int>& todo,
               int jobs, Gathered& g) {
  Supervisor supervisor(tendril, plan, dir);
  StatusLine line(stderr);
  const auto start = Clock::now();
  auto last_line = start - std::chrono::hours(1), last_csv = last_line;
  int ended = 0;
  bool csv_due = false;
  auto on_end = [&](const PlannedRun& r, const Outcome&) {
    g.update(r.index);
    ++ended;
    csv_due = true;
  };
  auto tick = [&] {
    const auto now = Clock::now();
    // Rows as runs finish, but not a rewrite per run of a thousand-run sweep.
    if (csv_due && now - last_csv >= std::chrono::milliseconds(500)) {
      write_sweep_csv(plan, g, dir, true);
      last_csv = now;
      csv_due = false;
    }
    if (now - last_line < (line.terminal() ? std::chrono::milliseconds(200) : std::chrono::seconds(10))) return;
    last_line = now;
    const Tally t = g.tally();
    const double elapsed = std::chrono::duration<double>(now - start).count();
    const int left = int(todo.size()) - ended;
    std::string text = format("[tendril] sweep: %d of %zu done (%d failed), %d running, %d to go", t.finished(),
                              plan.runs.size(), t.failed, supervisor.running(), left - supervisor.running());
    if (ended > 0 && elapsed > 0) {
      const double rate = ended / elapsed;
      text += format("; %.2f runs/s, about %s left", rate, duration_text(left / rate).c_str());
    }
    text += "; " + duration_text(elapsed);
    line.show(text);
  };
  supervisor.run(todo, jobs, on_end, tick);
  if (line.shown()) line.end(format("[tendril] sweep: %d runs ended here in %s", ended,
                                    duration_text(std::chrono::duration<double>(Clock::now() - start).count()).c_str()));
  if (const int sig = supervisor.stop_signal()) {
    write_sweep_csv(plan, g, dir, false);
    std::fprintf(stderr, "[tendril] sweep: stopped by SIG%s; the running runs are cancelled, --resume continues\n",
                 sigabbrev_np(sig));
    die_of(sig);
  }
}

int finish_sweep(const Plan& plan, const Gathered& g, const std::string& dir) {
  write_sweep_csv(plan, g, dir, false);
  const std::string plots = write_summary(plan, g, dir);
  if (!plots.empty()) std::fprintf(stderr, "tendril sweep: %s\n", plots.c_str());
  const Tally t = g.tally();
  std::printf("%zu runs: %d ok, %d failed, %d cancelled, %d not finished -> %s/sweep.csv, %s/summary.md\n",
              plan.runs.size(), t.ok, t.failed, t.cancelled, t.running + t.waiting, dir.c_str(), dir.c_str());
  return t.ok == int(plan.runs.size()) ? 0 : 1;
}

}  // namespace tendril::sweep
