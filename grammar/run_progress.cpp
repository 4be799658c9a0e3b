#include "run_progress.hpp"

#include <unistd.h>

#include <cmath>

namespace tendril::lua {

namespace {

std::string format(const char* fmt, auto... args) {
  char buf[1024];
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

RunProgress::RunProgress(bool enabled, const RunLimits& limits, std::uint64_t cap, bool capped_by_option,
                         ProgressStyle style)
    : RunProgress(enabled, limits.tolerance, cap, capped_by_option, style) {
  relative_ = limits.relative;
}

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
  const double threshold = relative_ > 0 ? r.threshold : tolerance_;
  line += format(")  %.0f steps/s  residual %.2e N (tolerance %.1e)  %zu particles  %s", rate_, r.residual, threshold,
                 particles, duration_text(elapsed).c_str());
  // Steps left over the rate bounds the time left: the run may converge sooner.
  if (cap_ != UINT64_MAX && rate_ > 0)
    line += "  at most " + duration_text(double(cap_ - r.steps) / rate_) + " left";
  line_.show(line);
}

std::string RunProgress::finish(const RunResult& r, const std::string& warning) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const auto steps = static_cast<unsigned long long>(r.steps);
  const std::string took = duration_text(elapsed);
  // The threshold the run was held to: with a relative tolerance, the larger
  // of the absolute one and relative times the force scale.
  const double tolerance = relative_ > 0 ? r.threshold : tolerance_;
  const char* limit = capped_by_option_ ? "--steps" : "max_steps";
  std::string why;
  if (r.converged)
    why = format("converged in %llu steps (%s): residual %.2e N < tolerance %.1e", steps, took.c_str(), r.residual,
                 tolerance);
  else if (!std::isfinite(r.residual))
    why = format("not converged: the residual is %g after %llu steps", r.residual, steps);
  else if (r.verdict == Verdict::Diverged || r.verdict == Verdict::Mechanism)
    why = format("not converged: %s at step %llu (%s): ", verdict_name(r.verdict), steps, took.c_str()) + r.detail;
  else if (r.verdict == Verdict::Stalled)
    why = format("not converged: stalled: %s %llu reached (%s) with residual %.2e N, tolerance %.1e; its lowest in "
                 "the second half of the run, %.2e N, is not below 0.9 times its lowest in the first half, %.2e N "
                 "(%llu kinetic-damping resets in the run)",
                 limit, steps, took.c_str(), r.residual, tolerance, r.best_after, r.best_before,
                 static_cast<unsigned long long>(r.kinetic_resets));
  else if (r.residual < tolerance)
    why = format("not converged: %s %llu reached (%s) with residual %.2e N below tolerance %.1e but still moving",
                 limit, steps, took.c_str(), r.residual, tolerance);
  else
    why = format("not converged: %s %llu reached (%s) with residual %.2e N, tolerance %.1e", limit, steps,
                 took.c_str(), r.residual, tolerance);
  // The residual against the model's forces, when it has any.
  if (r.force_scale > 0 && std::isfinite(r.residual))
    why += format(r.converged ? " (%.2e of the force scale %.3g N)" : "; relative residual %.2e of the force scale %.3g N",
                  r.relative_residual, r.force_scale);
  if (!warning.empty()) why += "; " + warning;
  if (line_.shown()) line_.end("[tendril] " + why);
  else if (enabled_ && (!r.converged || !warning.empty())) std::fprintf(style_.out, "[tendril] %s\n", why.c_str());
  return why;
}

}  // namespace tendril::lua
