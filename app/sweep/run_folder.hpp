#pragma once
// One run's folder, DIR/run-K: the scene's outputs, stdout.txt, stderr.txt
// and, written last, a marker. `done` says the run finished -- well, or with
// its scene's error -- and holds the outcome; `cancelled` says a signal
// stopped it (scancel, a time limit, a signal to the sweep). A folder
// without `done` is not finished: --resume runs it again from scratch.
#include <sys/types.h>

#include <string>

#include "sweep/plan.hpp"

namespace tendril::sweep {

struct Outcome {
  enum Kind { kPending, kInterrupted, kCancelled, kOk, kFailed };
  Kind kind = kPending;
  int exit_status = -1;
  double seconds = 0;  // wall time of the run
  std::string host;    // where it ran
  std::string error;   // a failed run's error; a cancelled run's signal
  bool finished() const { return kind == kOk || kind == kFailed; }
};

// "ok", "failed", "cancelled", "interrupted" (started, no marker), "pending".
const char* kind_name(Outcome::Kind kind);

std::string run_dir(const std::string& sweep_dir, int index);

// What the folder's markers say; kPending when the folder does not exist.
Outcome read_outcome(const std::string& dir);

// Empties the folder (a rerun starts clean) and starts `tendril run` for the
// run there, in plan.workdir, stdout and stderr into files. The child dies
// with its parent (PR_SET_PDEATHSIG) and gets the signals blocked here
// unblocked. Returns its pid; throws when it cannot start.
pid_t start_run(const std::string& tendril, const Plan& plan, const PlannedRun& run, const std::string& dir);

// Writes the marker for a run whose process ended with `wait_status` after
// `seconds`: `done` when it exited or crashed on its own, `cancelled` when
// `signalled` (a signal we forwarded) or SIGKILL (from outside) ended it.
Outcome record_end(const std::string& dir, int wait_status, double seconds, int signalled);

}  // namespace tendril::sweep
