#include "run_progress.hpp"

#include <unistd.h>

#include <cmath>

namespace tendril::lua {

namespace {

std::string format(const char* fmt, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, args...);
  return buf;
}

}  // namespace

ProgressStyle::ProgressStyle()
    : terminal(isatty(fileno(stderr)) != 0), every(terminal ? std::chrono::milliseconds(200) : std::chrono::seconds(10)) {}

RunProgress::RunProgress(bool enabled, double tolerance, std::uint64_t cap, bool capped_by_option,
                         ProgressStyle style)
    : enabled_(enabled),
      style_(style),
      line_(style.out, style.terminal),
      tolerance_(tolerance),
      cap_(cap),
      capped_by_option_(capped_by_option),
      start_(std::chrono::steady_clock::now()),
      last_(start_) {}

void RunProgress::update(const RunResult& r, std::uint64_t total_steps, std::size_t particles) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (now - start_ < style_.first_line || now - last_ < style_.every) return;
  const double dt = std::chrono::duration<double>(now - last_).count();
  if (dt > 0) {
    const double instant = double(r.steps - last_steps_) / dt;
    rate_ = rate_ > 0 ? 0.7 * rate_ + 0.3 * instant : instant;
  }
  last_ = now;
  last_steps_ = r.steps;
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  std::string line = format("[tendril] step %llu (run %llu", static_cast<unsigned long long>(total_steps),
                            static_cast<unsigned long long>(r.steps));
  if (cap_ != UINT64_MAX) line += format(" of %llu", static_cast<unsigned long long>(cap_));
  line += format(")  %.0f steps/s  residual %.2e N (tolerance %.1e)  %zu particles  %s", rate_, r.residual, tolerance_,
                 particles, duration_text(elapsed).c_str());
  // Steps left over the rate bounds the time left: the run may converge sooner.
  if (cap_ != UINT64_MAX && rate_ > 0)
    line += "  at most " + duration_text(double(cap_ - r.steps) / rate_) + " left";
  line_.show(line);
}

std::string RunProgress::finish(const RunResult& r) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const auto steps = static_cast<unsigned long long>(r.steps);
  std::string why;
  if (r.converged)
    why = format("converged in %llu steps (%s): residual %.2e N < tolerance %.1e", steps,
                 duration_text(elapsed).c_str(), r.residual, tolerance_);
  else if (!std::isfinite(r.residual))
    why = format("not converged: the residual is %g after %llu steps", r.residual, steps);
  else if (r.residual < tolerance_)
    why = format("not converged: %s %llu reached (%s) with residual %.2e N below tolerance %.1e but still moving",
                 capped_by_option_ ? "--steps" : "max_steps", steps, duration_text(elapsed).c_str(), r.residual,
                 tolerance_);
  else
    why = format("not converged: %s %llu reached (%s) with residual %.2e N, tolerance %.1e",
                 capped_by_option_ ? "--steps" : "max_steps", steps, duration_text(elapsed).c_str(), r.residual,
                 tolerance_);
  if (line_.shown()) line_.end("[tendril] " + why);
  return why;
}

}  // namespace tendril::lua
