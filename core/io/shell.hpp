#pragma once
// Other programs run through /bin/sh: gnuplot for plots, sbatch, squeue and
// scancel for sweeps on a Slurm cluster.
#include <string>

namespace tendril {

// A single-quoted shell word.
std::string shell_quote(const std::string& s);

struct ShellResult {
  int status = -1;     // the exit status; -1 when it did not run or was killed
  std::string output;  // its stdout (stderr too when the command says 2>&1)
};
ShellResult run_shell(const std::string& command);

}  // namespace tendril
