#pragma once
// The progress of one m:run{}: a line that updates in place on a terminal
// (plain lines in a log), shown once the run has lasted a second, and a
// final line saying whether it converged and why not.
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

#include "io/status_line.hpp"
#include "physics/solver.hpp"

namespace tendril::lua {

// Where and how the lines go; the defaults are stderr as it is.
struct ProgressStyle {
  std::FILE* out = stderr;
  bool terminal;                               // lines update in place
  std::chrono::milliseconds first_line{1000};  // a shorter run shows nothing
  std::chrono::milliseconds every;             // 0.2 s on a terminal, 10 s in a log
  ProgressStyle();                             // terminal: isatty(stderr)
};

class RunProgress {
 public:
  // cap: the run's step limit; capped_by_option: it comes from --steps.
  RunProgress(bool enabled, double tolerance, std::uint64_t cap, bool capped_by_option,
              ProgressStyle style = ProgressStyle());
  // A run with a relative tolerance too (RunLimits::relative).
  RunProgress(bool enabled, const RunLimits& limits, std::uint64_t cap, bool capped_by_option,
              ProgressStyle style = ProgressStyle());
  // Cheap enough to call every step; draws at most every style.every.
  // total_steps: the solver's count since the model began.
  void update(const RunResult& r, std::uint64_t total_steps, std::size_t particles);
  // How the run ended, in words ("converged in 812 steps: residual ... <
  // tolerance ...", "not converged: stalled at max_steps ..."): its verdict
  // and the numbers behind it. Printed as the final line when progress was
  // shown, and whenever the run did not converge (unless disabled).
  // `warning`, when not empty, follows the verdict ("; " + warning) and
  // makes the line show even for a run that converged.
  std::string finish(const RunResult& r, const std::string& warning = "");

 private:
  bool enabled_;
  ProgressStyle style_;
  StatusLine line_;
  double tolerance_;
  double relative_ = 0;
  std::uint64_t cap_;
  bool capped_by_option_;
  std::chrono::steady_clock::time_point start_, last_;
  std::uint64_t last_steps_ = 0;
  double rate_ = 0;  // steps per second, smoothed
};

}  // namespace tendril::lua
