#include "io/trace.hpp"

#include <cstdio>

namespace tendril {

void Trace::record(const Solver& s, const std::string& line) {
  if (s.steps() > traced_steps_) {
    lines_.push_back("steps " + std::to_string(s.steps() - traced_steps_));
    traced_steps_ = s.steps();
  }
  lines_.push_back(line);
}

std::vector<std::string> Trace::lines(const Solver& s) const {
  std::vector<std::string> out = lines_;
  if (s.steps() > traced_steps_) out.push_back("steps " + std::to_string(s.steps() - traced_steps_));
  return out;
}

std::string Trace::number(double x) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%a", x);
  return buf;
}

std::string Trace::vec(const Vec3& v) { return number(v.x()) + " " + number(v.y()) + " " + number(v.z()); }

}  // namespace tendril
