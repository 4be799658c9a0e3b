#pragma once
// A sweep's runs on this machine: `jobs` at once, a progress line (done,
// failed, running, the rate, the time left), sweep.csv rewritten as runs
// finish. After a stop signal the running runs are cancelled, sweep.csv is
// written, and the sweep dies of the signal.
#include <string>
#include <vector>

#include "sweep/gather.hpp"
#include "sweep/plan.hpp"

namespace tendril::sweep {

void run_local(const std::string& tendril, const Plan& plan, const std::string& dir, const std::vector<int>& todo,
               int jobs, Gathered& g);

// The end of every sweep, local or gathered: DIR/sweep.csv, times.csv and
// summary.md, a line saying how it went; returns the exit status (0 when
// every run finished well, 1 when one failed or did not finish).
int finish_sweep(const Plan& plan, const Gathered& g, const std::string& dir);

}  // namespace tendril::sweep
