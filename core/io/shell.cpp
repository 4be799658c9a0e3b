#include "io/shell.hpp"

#include <sys/wait.h>

#include <cstdio>

namespace tendril {

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char ch : s) q += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return q + "'";
}

ShellResult run_shell(const std::string& command) {
  ShellResult r;
  std::FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buf[4096];
  for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) r.output.append(buf, n);
  const int status = pclose(pipe);
  r.status = status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

}  // namespace tendril
