// `tendril validate [--csv FILE] [--plots DIR] [--quick] [--defaults-only]
// [--case NAME]`: runs every validation case (validate/cases/) with each
// integrator, formulation and resolution, prints the table, and fails when a
// case under its default settings misses its tolerance.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "command.hpp"
#include "io/gnuplot.hpp"
#include "registry.hpp"
#include "report.hpp"
#include "runner.hpp"

namespace tendril::app {

namespace {

struct ValidateArguments {
  std::string csv, plots;
  bool quick = false, defaults_only = false;
  std::vector<std::string> cases;
};

int validate(const ValidateArguments& a) {
  using namespace tendril::validate;
  RunOptions options;
  options.quick = a.quick;
  std::vector<const Case*> selected;
  for (const std::string& name : a.cases) {
    const Case* c = find_case(name);
    if (!c) {
      std::string known;
      for (const Case& k : cases()) known += " " + k.name;
      throw UsageError("--case: no case '" + name + "'; the cases are:" + known);
    }
    if (std::find(selected.begin(), selected.end(), c) == selected.end()) selected.push_back(c);
  }
  if (selected.empty())
    for (const Case& c : cases()) selected.push_back(&c);
  if (options.quick) options.max_runs = 1;

  const std::string& plots = a.plots;
  bool plot = !plots.empty();
  if (plot && !gnuplot_available()) {
    std::fprintf(stderr, "tendril validate: gnuplot not found (Debian: apt-get install gnuplot-nox); no plots\n");
    plot = false;
  }
  // Refused before the cases run, not after: an output that cannot be written.
  if (plot) {
    std::error_code ec;
    std::filesystem::create_directories(plots, ec);
    if (ec || ::access(plots.c_str(), W_OK | X_OK) != 0) {
      const std::string reason = ec ? ec.message() : std::strerror(errno);
      std::fprintf(stderr, "tendril validate: cannot write plots to %s: %s\n", plots.c_str(), reason.c_str());
      return 1;
    }
  }
  if (!a.csv.empty()) {
    const std::string folder = std::filesystem::path(a.csv).parent_path().string();
    if (::access(folder.empty() ? "." : folder.c_str(), W_OK | X_OK) != 0) {
      std::fprintf(stderr, "tendril validate: cannot write %s: %s\n", a.csv.c_str(), std::strerror(errno));
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
      if (a.defaults_only && !is_default(*c, s)) continue;
      rows.push_back(run_setting(*c, s, options));
      table.row(rows.back());
      if (rows.back().is_default && !rows.back().passes()) failed_defaults.push_back(rows.back());
    }
    if (plot) {
      const std::string problem = tendril::validate::plot(*c, rows, plots);
      if (!problem.empty()) std::fprintf(stderr, "tendril validate: %s\n", problem.c_str());
      output_failed |= !problem.empty();
    }
  }

  if (!a.csv.empty()) write_csv(a.csv, rows);
  if (plot) std::printf("\nplots: %s/<case>.png\n", plots.c_str());
  if (!failed_defaults.empty()) {
    for (const Row& r : failed_defaults) std::fprintf(stderr, "tendril validate: %s\n", default_failure(r).c_str());
    return kSceneError;
  }
  if (output_failed) return kSceneError;
  std::printf("\nevery case within its tolerance under its default settings\n");
  return kOk;
}

}  // namespace

Command validate_command() {
  return {"validate",
          "runs every validation case with each integrator and resolution; fails when a default misses its tolerance",
          [](CLI::App& cli) {
            auto a = std::make_shared<ValidateArguments>();
            cli.add_option("--csv", a->csv, "writes the table's rows to FILE")->type_name("FILE");
            cli.add_option("--plots", a->plots, "writes DIR/CASE.png: error against wall time (gnuplot)")
                ->type_name("DIR");
            cli.add_flag("--quick", a->quick,
                         "every integrator at the coarsest resolution, the defaults at theirs (for CI)");
            cli.add_flag("--defaults-only", a->defaults_only,
                         "each case under its default settings alone: the tolerance check without the survey");
            cli.add_option("--case", a->cases, "runs only this case (repeatable)")
                ->type_name("NAME")
                ->expected(1)
                ->take_all();
            return [a] { return validate(*a); };
          }};
}

}  // namespace tendril::app
