#pragma once
// Shared by the benchmarks: timing, printf-style formatting, aligned tables
// and size lists such as "1K,100K,1M".
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

namespace tendril::bench {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
// CPU time of the calling thread: on a shared machine the wall clock also
// counts the time other processes held the core.
inline double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// The 1-minute load average (/proc/loadavg): on a shared machine a figure
// measured at load 2 on 2 cores is not one measured idle.
inline double load_average() {
  double l = -1;
  if (std::FILE* f = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(f, "%lf", &l) != 1) l = -1;
    std::fclose(f);
  }
  return l;
}

inline std::string fmt(const char* f, ...) {
  char buf[256];
  va_list ap;
  va_start(ap, f);
  std::vsnprintf(buf, sizeof buf, f, ap);
  va_end(ap);
  return buf;
}

class Table {
 public:
  explicit Table(std::vector<std::string> head) { rows_.push_back(std::move(head)); }
  void add(std::vector<std::string> row) { rows_.push_back(std::move(row)); }
  void print() const {
    std::vector<std::size_t> w(rows_[0].size(), 0);
    for (const auto& r : rows_)
      for (std::size_t c = 0; c < r.size(); ++c) w[c] = std::max(w[c], r[c].size());
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      std::string line;
      for (std::size_t c = 0; c < rows_[i].size(); ++c) {
        const std::string& s = rows_[i][c];
        std::string pad(w[c] - s.size(), ' ');
        line += (c == 0 ? s + pad : pad + s) + (c + 1 < rows_[i].size() ? "  " : "");
      }
      std::puts(line.c_str());
      if (i == 0) {
        std::size_t total = 0;
        for (std::size_t x : w) total += x + 2;
        std::puts(std::string(total - 2, '-').c_str());
      }
    }
  }

 private:
  std::vector<std::vector<std::string>> rows_;
};

inline std::size_t parse_count(const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  std::string suffix(end);
  if (suffix == "K" || suffix == "k") v *= 1e3;
  else if (suffix == "M" || suffix == "m") v *= 1e6;
  else if (!suffix.empty() || end == s.c_str()) throw std::runtime_error("bad size '" + s + "'");
  if (!(v >= 1)) throw std::runtime_error("bad size '" + s + "'");
  return static_cast<std::size_t>(std::llround(v));
}

// The items of a comma-separated list, empty ones left out.
inline std::vector<std::string> split(const std::string& list) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= list.size()) {
    std::size_t comma = list.find(',', start);
    if (comma == std::string::npos) comma = list.size();
    if (comma > start) out.push_back(list.substr(start, comma - start));
    start = comma + 1;
  }
  return out;
}

// The entries of `known` (anything with a `label`) named in a
// comma-separated list, in the list's order; a name not known throws.
template <class Variant>
std::vector<Variant> chosen_by_label(const std::vector<Variant>& known, const std::string& list) {
  std::vector<Variant> out;
  for (const std::string& name : split(list)) {
    auto it = std::find_if(known.begin(), known.end(), [&](const Variant& v) { return v.label == name; });
    if (it == known.end()) throw std::runtime_error("unknown integrator '" + name + "'");
    out.push_back(*it);
  }
  return out;
}

inline std::vector<std::size_t> parse_sizes(const std::string& list) {
  std::vector<std::size_t> out;
  for (const std::string& item : split(list)) out.push_back(parse_count(item));
  if (out.empty()) throw std::runtime_error("--sizes needs a comma-separated list, e.g. 10K,100K,1M");
  return out;
}

}  // namespace tendril::bench
