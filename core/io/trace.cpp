#include "io/trace.hpp"

#include <algorithm>
#include <cstdio>

namespace tendril {

void Trace::steps_lines(const Solver& s, std::uint64_t steps, std::uint64_t to, std::vector<std::string>& out) {
  const std::vector<Solver::StepRange>& newton = s.auto_newton_steps();
  // The first range that ends after `steps` (ranges are in order and apart).
  auto r = std::upper_bound(newton.begin(), newton.end(), steps,
                            [](std::uint64_t x, const Solver::StepRange& range) { return x < range.end; });
  while (steps < to) {
    if (r != newton.end() && r->first <= steps) {
      const std::uint64_t end = std::min(r->end, to);
      out.push_back("newton_steps " + std::to_string(end - steps));
      steps = end;
      ++r;
      continue;
    }
    const std::uint64_t end = r != newton.end() ? std::min(r->first, to) : to;
    out.push_back("steps " + std::to_string(end - steps));
    steps = end;
  }
}

void Trace::pending(const Solver& s, std::uint64_t steps_to, std::size_t failures_to, std::uint64_t& steps,
                    std::size_t& failures, std::vector<std::string>& out) {
  const std::vector<std::uint64_t>& failed = s.failed_steps();
  for (; failures < failures_to; ++failures) {
    if (failed[failures] > steps) steps_lines(s, steps, failed[failures], out);
    steps = std::max(steps, failed[failures]);
    out.push_back(s.failed_as_newton(failures) ? "failed_step as=newton" : "failed_step");
  }
  if (steps_to > steps) steps_lines(s, steps, steps_to, out);
  steps = std::max(steps, steps_to);
}

void Trace::record(const Solver& s, const std::string& line) {
  pending(s, s.steps(), s.failed_steps().size(), traced_steps_, traced_failures_, lines_);
  lines_.push_back(line);
}

std::vector<std::string> Trace::lines(const Solver& s) const {
  return lines_until(s, mark(), s.steps(), s.failed_steps().size());
}

std::vector<std::string> Trace::lines_until(const Solver& s, Mark m, std::uint64_t steps, std::size_t failures) const {
  std::vector<std::string> out(lines_.begin(), lines_.begin() + std::ptrdiff_t(std::min(m.lines, lines_.size())));
  pending(s, steps, std::min(failures, s.failed_steps().size()), m.steps, m.failures, out);
  return out;
}

std::string Trace::number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string Trace::vec(const Vec3& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

}  // namespace tendril
