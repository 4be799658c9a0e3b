#include "io/gnuplot.hpp"

#include <cstdio>
#include <cstdlib>

#include "io/shell.hpp"

namespace tendril {

bool gnuplot_available() { return std::system("command -v gnuplot >/dev/null 2>&1") == 0; }

std::string gnuplot_quote(const std::string& s) {
  std::string q = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') q += '\\';
    q += ch == '\n' ? std::string("\\n") : std::string(1, ch);
  }
  return q + "\"";
}

std::string run_gnuplot(const std::string& dir, const std::string& script, const std::string& settings,
                        const std::string& log) {
  const std::string command = "cd " + shell_quote(dir) + " && gnuplot" +
                              (settings.empty() ? "" : " -e " + shell_quote(settings)) + " " + shell_quote(script) +
                              " 2>" + shell_quote(log);
  if (std::system(command.c_str()) != 0) return "gnuplot failed on " + dir + "/" + script + " (see " + dir + "/" + log + ")";
  std::remove((dir + "/" + log).c_str());
  return "";
}

}  // namespace tendril
