#pragma once
// A sweep as one Slurm job array: task K runs run K of the plan
// (`tendril sweep --task K --out DIR`), so the runs' folders, markers and
// sweep.csv are those of a local sweep. Through sbatch, squeue and scancel.
#include <map>
#include <string>
#include <vector>

#include "sweep/gather.hpp"
#include "sweep/plan.hpp"

namespace tendril::sweep {

struct SlurmOptions {
  std::string partition;  // sbatch --partition; "" for the cluster's default
  std::string time;       // sbatch --time per task; "" for the partition's default
  int array_max = 0;      // at most this many tasks at once (--array=...%N); 0: no limit
};

// "1-4,7,9-12" for {1,2,3,4,7,9,10,11,12}.
std::string array_ranges(const std::vector<int>& indices);

// Writes DIR/slurm/array.sh over the runs of `todo` and submits it; returns
// the job id. Throws with sbatch's message when it refuses.
std::string submit(const std::string& tendril, const Plan& plan, const std::string& dir, const std::vector<int>& todo,
                   const SlurmOptions& options);

// The state of each task of the job Slurm still lists, by run index:
// "pending", "running", "cancelled", or Slurm's word in lower case.
// `listed` is false when squeue no longer knows the job.
std::map<int, std::string> queue_states(const std::string& job, bool* listed = nullptr);

// Waits until no task of the job is pending or running, with a progress line
// of the array's state, updating `g` and sweep.csv as runs finish. On a stop
// signal cancels the job (scancel), waits for it to go, writes sweep.csv and
// dies of the signal.
void wait_for(const std::string& job, const Plan& plan, const std::string& dir, Gathered& g);

// The job id a sweep submitted last (DIR/slurm/job), or "".
std::string submitted_job(const std::string& dir);

}  // namespace tendril::sweep
