#include "io/status_line.hpp"

#include <unistd.h>

#include <cmath>

namespace tendril {

StatusLine::StatusLine(std::FILE* out) : StatusLine(out, isatty(fileno(out)) != 0) {}

StatusLine::StatusLine(std::FILE* out, bool terminal) : out_(out), terminal_(terminal) {}

StatusLine::~StatusLine() {
  if (open_) std::fputc('\n', out_);
}

void StatusLine::show(const std::string& line) {
  if (terminal_) {
    std::fprintf(out_, "\r%s\033[K", line.c_str());
    open_ = true;
  } else {
    std::fprintf(out_, "%s\n", line.c_str());
  }
  std::fflush(out_);
  shown_ = true;
}

void StatusLine::end(const std::string& line) {
  if (open_) std::fputs("\r\033[K", out_);
  std::fprintf(out_, "%s\n", line.c_str());
  std::fflush(out_);
  open_ = false;
}

std::string duration_text(double seconds) {
  char buf[64];
  if (!(seconds >= 0) || !std::isfinite(seconds)) return "?";
  if (seconds < 60) {
    std::snprintf(buf, sizeof buf, "%.1f s", seconds);
    return buf;
  }
  const auto s = static_cast<long long>(std::llround(seconds));
  if (s < 3600) std::snprintf(buf, sizeof buf, "%lld min %02lld s", s / 60, s % 60);
  else std::snprintf(buf, sizeof buf, "%lld h %02lld min", s / 3600, (s % 3600) / 60);
  return buf;
}

}  // namespace tendril
