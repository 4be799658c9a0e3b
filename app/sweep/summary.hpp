#pragma once
// DIR/summary.md: for each figure the runs reported, per combination of
// parameter values over its seeds, the runs, mean, spread (sample standard
// deviation) and the lowest and highest run; and per figure and parameter a
// plot of the figure against the parameter (DIR/plots/, gnuplot), so a
// researcher sees at a glance which parameters matter.
#include <optional>
#include <string>
#include <vector>

#include "sweep/gather.hpp"
#include "sweep/plan.hpp"

namespace tendril::sweep {

struct Spread {
  std::vector<std::string> values;  // the combination
  int runs = 0;                     // finished well and reporting the figure
  double mean = 0, sd = 0;          // sd: NaN for a single run
  double low = 0, high = 0;
  int low_run = 0, high_run = 0;    // plan indices
  int trues = 0;                    // a true/false figure: how many true
};

enum class FigureKind { kNumber, kBoolean, kText };

// How a figure reads over the runs that finished well: numbers, true/false
// or text (text is not summarised).
FigureKind figure_kind(const Gathered& g, const std::string& figure);

// One Spread per combination of parameter values, in plan order.
std::vector<Spread> spreads(const Plan& plan, const Gathered& g, const std::string& figure);

// Writes DIR/summary.md and, when gnuplot is there, DIR/plots/. Returns what
// went wrong with the plots ("" when nothing did); summary.md is written
// either way.
std::string write_summary(const Plan& plan, const Gathered& g, const std::string& dir);

}  // namespace tendril::sweep
