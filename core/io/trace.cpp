#include "io/trace.hpp"

#include <algorithm>
#include <cstdio>

namespace tendril {

void Trace::pending(const std::vector<std::uint64_t>& failed, std::uint64_t steps_to, std::size_t failures_to,
                    std::uint64_t& steps, std::size_t& failures, std::vector<std::string>& out) {
  for (; failures < failures_to; ++failures) {
    if (failed[failures] > steps) out.push_back("steps " + std::to_string(failed[failures] - steps));
    steps = std::max(steps, failed[failures]);
    out.push_back("failed_step");
  }
  if (steps_to > steps) out.push_back("steps " + std::to_string(steps_to - steps));
  steps = std::max(steps, steps_to);
}

void Trace::record(const Solver& s, const std::string& line) {
  pending(s.failed_steps(), s.steps(), s.failed_steps().size(), traced_steps_, traced_failures_, lines_);
  lines_.push_back(line);
}

std::vector<std::string> Trace::lines(const Solver& s) const {
  return lines_until(s, mark(), s.steps(), s.failed_steps().size());
}

std::vector<std::string> Trace::lines_until(const Solver& s, Mark m, std::uint64_t steps, std::size_t failures) const {
  std::vector<std::string> out(lines_.begin(), lines_.begin() + std::ptrdiff_t(std::min(m.lines, lines_.size())));
  pending(s.failed_steps(), steps, std::min(failures, s.failed_steps().size()), m.steps, m.failures, out);
  return out;
}

std::string Trace::number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string Trace::vec(const Vec3& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

}  // namespace tendril
