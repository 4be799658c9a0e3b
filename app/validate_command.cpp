// `tendril validate [--csv FILE] [--plots DIR] [--quick] [--case NAME]`: runs
// every validation case (validate/cases/) with each integrator, formulation
// and resolution, prints the table, and fails when a case under its default
// settings misses its tolerance.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "registry.hpp"
#include "report.hpp"
#include "runner.hpp"

namespace {

const char* const kValidateUsage =
    "usage: tendril validate [--csv FILE] [--plots DIR] [--quick] [--case NAME]...\n"
    "  --csv    writes the table's rows to FILE\n"
    "  --plots  writes DIR/CASE.png (error against wall time, log-log; needs gnuplot)\n"
    "  --quick  every integrator at the coarsest resolution, the defaults at theirs (for CI)\n"
    "  --case   runs only this case (repeatable)\n";

}  // namespace

int run_validate(int argc, char** argv) {
  using namespace tendril::validate;
  std::string csv, plots;
  RunOptions options;
  std::vector<const Case*> selected;
  try {
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      auto value = [&]() -> std::string {
        if (i + 1 >= argc) throw std::invalid_argument(arg + " needs a value");
        return argv[++i];
      };
      if (arg == "--csv") csv = value();
      else if (arg == "--plots") plots = value();
      else if (arg == "--quick") options.quick = true;
      else if (arg == "--case") {
        const std::string name = value();
        const Case* c = find_case(name);
        if (!c) {
          std::string known;
          for (const Case& k : cases()) known += " " + k.name;
          throw std::invalid_argument("no case '" + name + "'; the cases are:" + known);
        }
        if (std::find(selected.begin(), selected.end(), c) == selected.end()) selected.push_back(c);
      } else if (arg == "--help" || arg == "-h") {
        std::fputs(kValidateUsage, stdout);
        return 0;
      } else {
        throw std::invalid_argument("unexpected argument '" + arg + "'");
      }
    }
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "tendril: validate: %s\n\n%s", e.what(), kValidateUsage);
    return 2;
  }
  if (selected.empty())
    for (const Case& c : cases()) selected.push_back(&c);
  if (options.quick) options.max_runs = 1;

  bool plot = !plots.empty();
  if (plot && !gnuplot_available()) {
    std::fprintf(stderr, "tendril: validate: gnuplot not found (Debian: apt-get install gnuplot-nox); no plots\n");
    plot = false;
  }
  // Refused before the cases run, not after: an output that cannot be written.
  if (plot) {
    std::error_code ec;
    std::filesystem::create_directories(plots, ec);
    if (ec || ::access(plots.c_str(), W_OK | X_OK) != 0) {
      const std::string reason = ec ? ec.message() : std::strerror(errno);
      std::fprintf(stderr, "tendril: validate: cannot write plots to %s: %s\n", plots.c_str(), reason.c_str());
      return 1;
    }
  }
  if (!csv.empty()) {
    const std::string folder = std::filesystem::path(csv).parent_path().string();
    if (::access(folder.empty() ? "." : folder.c_str(), W_OK | X_OK) != 0) {
      std::fprintf(stderr, "tendril: validate: cannot write %s: %s\n", csv.c_str(), std::strerror(errno));
      return 1;
    }
  }

  for (const Case* c : selected)
    std::printf("%s: %s\n  segments = %s; default %s, %s damping, %d segments, %s\n", c->name.c_str(),
                c->reference.c_str(), c->resolution.c_str(), tendril::integrator_name(c->defaults.solver.integrator),
                tendril::damping_name(c->defaults.solver.damping), c->defaults.segments,
                c->defaults.formulation.c_str());
  std::printf("\n");
  Table table(stdout, selected);
  table.header();
  std::vector<Row> rows, failed_defaults;
  bool output_failed = false;
  for (const Case* c : selected) {
    for (const Setting& s : matrix(*c, options.quick)) {
      rows.push_back(run_setting(*c, s, options));
      table.row(rows.back());
      if (rows.back().is_default && !rows.back().passes()) failed_defaults.push_back(rows.back());
    }
    if (plot) {
      const std::string problem = tendril::validate::plot(*c, rows, plots);
      if (!problem.empty()) std::fprintf(stderr, "tendril: validate: %s\n", problem.c_str());
      output_failed |= !problem.empty();
    }
  }

  if (!csv.empty()) {
    try {
      write_csv(csv, rows);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "tendril: validate: %s\n", e.what());
      return 1;
    }
  }
  if (plot) std::printf("\nplots: %s/<case>.png\n", plots.c_str());
  if (!failed_defaults.empty()) {
    for (const Row& r : failed_defaults) std::fprintf(stderr, "tendril: validate: %s\n", default_failure(r).c_str());
    return 1;
  }
  if (output_failed) return 1;
  std::printf("\nevery case within its tolerance under its default settings\n");
  return 0;
}
