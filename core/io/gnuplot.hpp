#pragma once
// gnuplot (Debian gnuplot-nox) as the plots' renderer: `validate --plots` and
// a sweep's summary write a script and run it.
#include <string>

namespace tendril {

bool gnuplot_available();
// A double-quoted gnuplot string (where \n is a line break).
std::string gnuplot_quote(const std::string& s);
// Runs `gnuplot -e SETTINGS SCRIPT` in folder DIR (relative names in the
// script resolve there), its stderr into DIR/LOG, removed when it succeeds.
// Returns "" or what went wrong.
std::string run_gnuplot(const std::string& dir, const std::string& script, const std::string& settings,
                        const std::string& log);

}  // namespace tendril
