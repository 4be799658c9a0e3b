#pragma once
// DIR/sweep.csv from the plan and the run folders alone: one row per run, in
// plan order -- run, the parameters, seed, status, the figures its scene
// reported (its summary.csv: tendril.report), error. So a local sweep and a
// gathered Slurm sweep write the same bytes; what differs between machines
// (wall time, host) goes to DIR/times.csv.
#include <map>
#include <string>
#include <vector>

#include "sweep/plan.hpp"
#include "sweep/run_folder.hpp"

namespace tendril::sweep {

struct RunState {
  Outcome outcome;
  std::string status;                         // the outcome, or the scheduler's word for it
  std::map<std::string, std::string> figures;  // what a finished run reported
};

struct Tally {
  int ok = 0, failed = 0, cancelled = 0, running = 0, waiting = 0;  // waiting: pending or interrupted
  int finished() const { return ok + failed; }
};

// Every run's state, in plan order.
class Gathered {
 public:
  // `queue`: the scheduler's state of runs without a marker ("running",
  // "pending", "cancelled": from squeue), by run index.
  Gathered(const Plan& plan, std::string dir, const std::map<int, std::string>& queue = {});
  // Reads run `index` (1..N) again: it just ended, or the queue said more.
  void update(int index, const std::string& queue_state = "");
  const std::vector<RunState>& runs() const { return runs_; }
  Tally tally() const;

 private:
  const Plan& plan_;
  std::string dir_;
  std::vector<RunState> runs_;
};

struct SweepTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;  // one per planned run
  std::vector<std::string> metrics;            // the reported figures' columns
  std::size_t metric_column = 0;               // where they start
};
SweepTable sweep_table(const Plan& plan, const Gathered& g);

// DIR/sweep.csv and DIR/times.csv, each written whole. finished_only: the
// rows of the runs that have finished (a sweep in progress writes them so).
void write_sweep_csv(const Plan& plan, const Gathered& g, const std::string& dir, bool finished_only);

}  // namespace tendril::sweep
