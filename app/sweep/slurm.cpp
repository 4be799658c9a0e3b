#include "sweep/slurm.hpp"

#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "io/shell.hpp"
#include "io/status_line.hpp"
#include "sweep/supervisor.hpp"

namespace tendril::sweep {

namespace {

namespace fs = std::filesystem;

bool active(const std::string& state) { return state == "pending" || state == "running"; }

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace

std::string array_ranges(const std::vector<int>& indices) {
  std::string out;
  for (std::size_t k = 0; k < indices.size();) {
    std::size_t end = k;
    while (end + 1 < indices.size() && indices[end + 1] == indices[end] + 1) ++end;
    out += (out.empty() ? "" : ",") + std::to_string(indices[k]);
    if (end > k) out += "-" + std::to_string(indices[end]);
    k = end + 1;
  }
  return out;
}

std::string submit(const std::string& tendril, const Plan& plan, const std::string& dir, const std::vector<int>& todo,
                   const SlurmOptions& options) {
  const std::string sweep = fs::absolute(dir).lexically_normal().string();
  const std::string slurm = sweep + "/slurm";
  fs::create_directories(slurm);
  std::ostringstream script;
  script << "#!/bin/sh\n"
         << "# Written by tendril sweep: task K runs run K of " << sweep << "/plan.csv.\n"
         << "#SBATCH --job-name=tendril-sweep\n"
         << "#SBATCH --array=" << array_ranges(todo) << (options.array_max > 0 ? "%" + std::to_string(options.array_max) : "")
         << "\n"
         << "#SBATCH --ntasks=1\n#SBATCH --cpus-per-task=1\n"
         << "#SBATCH --chdir=" << plan.workdir << "\n"
         << "#SBATCH --output=" << slurm << "/task-%a.out\n";
  if (!options.partition.empty()) script << "#SBATCH --partition=" << options.partition << "\n";
  if (!options.time.empty()) script << "#SBATCH --time=" << options.time << "\n";
  script << "exec " << shell_quote(tendril) << " sweep --task \"$SLURM_ARRAY_TASK_ID\" --out " << shell_quote(sweep)
         << "\n";
  write_file_atomically(slurm + "/array.sh", script.str());
  const ShellResult r = run_shell("sbatch --parsable " + shell_quote(slurm + "/array.sh") + " 2>&1");
  std::string job = r.output.substr(0, r.output.find_first_of(";\n"));
  if (r.status != 0 || job.empty() || job.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("sbatch refused " + slurm + "/array.sh: " + r.output);
  write_file_atomically(slurm + "/job", job + "\n");
  return job;
}

std::map<int, std::string> queue_states(const std::string& job, bool* listed) {
  std::map<int, std::string> states;
  const ShellResult r = run_shell("squeue --noheader --array --states=all --jobs=" + shell_quote(job) +
                                  " --format='%K %T' 2>/dev/null");
  if (listed) *listed = r.status == 0 && !r.output.empty();
  std::istringstream lines(r.output);
  for (std::string task, state; lines >> task >> state;) {
    // A pending array still folded ("3-9%2") stands for each of its tasks.
    const std::string word = lower(state) == "configuring" || lower(state) == "completing" ? "running" : lower(state);
    const auto bar = task.find('%');
    if (bar != std::string::npos) task.resize(bar);
    std::istringstream ranges(task);
    for (std::string range; std::getline(ranges, range, ',');) {
      const auto dash = range.find('-');
      try {
        const int first = std::stoi(range.substr(0, dash));
        const int last = dash == std::string::npos ? first : std::stoi(range.substr(dash + 1));
        for (int k = first; k <= last; ++k) states[k] = word;
      } catch (const std::exception&) {
      }
    }
  }
  return states;
}

void wait_for(const std::string& job, const Plan& plan, const std::string& dir, Gathered& g) {
  sigset_t stops, previous;
  sigemptyset(&stops);
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stops, sig);
  sigprocmask(SIG_BLOCK, &stops, &previous);
  StatusLine line(stderr);
  const auto start = std::chrono::steady_clock::now();
  auto shown = start - std::chrono::hours(1);
  std::string last_text;
  int stop = 0;
  for (;;) {
    bool listed = false;
    const auto states = queue_states(job, &listed);
    bool busy = false;
    for (const PlannedRun& r : plan.runs) {
      const auto it = states.find(r.index);
      const std::string state = it == states.end() ? "" : it->second;
      if (!g.runs()[std::size_t(r.index - 1)].outcome.finished()) g.update(r.index, state);
      busy |= active(state);
    }
    write_sweep_csv(plan, g, dir, true);
    const Tally t = g.tally();
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char text[256];
    std::snprintf(text, sizeof text,
                  "[tendril] sweep: Slurm job %s: %d pending, %d running, %d done (%d failed), %d cancelled; %s",
                  job.c_str(), t.waiting, t.running, t.finished(), t.failed, t.cancelled,
                  duration_text(elapsed).c_str());
    // A log gets a line when the array's state changed, at most every 10 s.
    const auto now = std::chrono::steady_clock::now();
    const std::string counts = std::string(text).substr(0, std::string(text).rfind(';'));
    if (line.terminal() || (counts != last_text && now - shown >= std::chrono::seconds(10))) {
      line.show(text);
      shown = now;
      last_text = counts;
    }
    if (!busy) break;
    timespec wait{1, 0};
    siginfo_t info;
    const int sig = sigtimedwait(&stops, &info, &wait);
    if (sig > 0 && !stop) {
      stop = sig;
      run_shell("scancel " + shell_quote(job) + " 2>&1");
    }
  }
  line.end("[tendril] sweep: Slurm job " + job + " has left the queue");
  sigprocmask(SIG_SETMASK, &previous, nullptr);
  if (stop) {
    write_sweep_csv(plan, g, dir, false);
    std::fprintf(stderr, "[tendril] sweep: stopped by SIG%s: job %s cancelled, --resume continues\n", sigabbrev_np(stop),
                 job.c_str());
    die_of(stop);
  }
}

std::string submitted_job(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_regular_file(dir + "/slurm/job", ec)) return "";
  std::string job = read_input_file(dir + "/slurm/job");
  while (!job.empty() && (job.back() == '\n' || job.back() == ' ')) job.pop_back();
  return job;
}

}  // namespace tendril::sweep
