#pragma once
// A progress line: rewritten in place on a terminal ("\r" and erase to the
// end of the line), one plain line per update in a log. Used by m:run{}'s
// progress and by tendril sweep.
#include <cstdio>
#include <string>

namespace tendril {

class StatusLine {
 public:
  // terminal: whether `out` is one (isatty) unless told.
  explicit StatusLine(std::FILE* out = stderr);
  StatusLine(std::FILE* out, bool terminal);
  ~StatusLine();  // a line left open gets its line break
  StatusLine(const StatusLine&) = delete;
  StatusLine& operator=(const StatusLine&) = delete;

  void show(const std::string& line);
  // The last line, replacing the one in place; a log gets it as a line too.
  void end(const std::string& line);
  bool terminal() const { return terminal_; }
  bool shown() const { return shown_; }

 private:
  std::FILE* out_;
  bool terminal_;
  bool open_ = false;   // a line in place without its line break
  bool shown_ = false;  // show() was called
};

// "1.5 s", "3 min 12 s", "2 h 05 min".
std::string duration_text(double seconds);

}  // namespace tendril
