#include "sweep/run_folder.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

#include "io/atomic_file.hpp"
#include "io/csv.hpp"
#include "io/input_file.hpp"

namespace tendril::sweep {

namespace {

namespace fs = std::filesystem;

const std::vector<std::string> kMarkerHeader{"status", "exit_status", "wall_time_s", "host", "error"};

std::string host_name() {
  char name[256] = {};
  if (gethostname(name, sizeof name - 1) != 0) return "?";
  return name;
}

// The end of a run's stderr: where its error is, however much it printed before.
std::string tail_of(const std::string& path) {
  constexpr std::streamoff kTail = 64 * 1024;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return "";
  std::ifstream in(path, std::ios::binary);
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(size > kTail ? size - kTail : 0);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// The scene's error as `tendril run` printed it: from the last line naming
// tendril up to the traceback, without the "tendril: error: " prefix.
std::string error_of(const std::string& stderr_text, int exit_status) {
  std::string text = stderr_text;
  const auto trace = text.find("\nstack traceback:");
  if (trace != std::string::npos) text.resize(trace);
  auto start = text.rfind("\ntendril");
  start = start == std::string::npos ? (text.rfind("tendril", 0) == 0 ? 0 : std::string::npos) : start + 1;
  if (start != std::string::npos) text = text.substr(start);
  for (const char* prefix : {"tendril: error: ", "tendril run: ", "tendril: "})
    if (text.rfind(prefix, 0) == 0) {
      text = text.substr(std::strlen(prefix));
      break;
    }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  if (text.empty()) text = "exit status " + std::to_string(exit_status) + ", nothing on stderr";
  return text;
}

void write_marker(const std::string& path, const Outcome& o) {
  char seconds[32];
  std::snprintf(seconds, sizeof seconds, "%.3f", o.seconds);
  write_file_atomically(path, csv_line(kMarkerHeader) + "\n" +
                                  csv_line({kind_name(o.kind), std::to_string(o.exit_status), seconds, o.host, o.error}) +
                                  "\n");
}

Outcome parse_marker(const std::string& path) {
  const auto rows = parse_csv(read_input_file(path));
  if (rows.size() != 2 || rows[0] != kMarkerHeader || rows[1].size() != kMarkerHeader.size())
    throw std::runtime_error(path + ": not a run marker");
  const auto& f = rows[1];
  Outcome o;
  o.kind = f[0] == "ok" ? Outcome::kOk : f[0] == "failed" ? Outcome::kFailed : Outcome::kCancelled;
  o.exit_status = std::stoi(f[1]);
  o.seconds = std::stod(f[2]);
  o.host = f[3];
  o.error = f[4];
  return o;
}

}  // namespace

const char* kind_name(Outcome::Kind kind) {
  switch (kind) {
    case Outcome::kPending: return "pending";
    case Outcome::kInterrupted: return "interrupted";
    case Outcome::kCancelled: return "cancelled";
    case Outcome::kOk: return "ok";
    case Outcome::kFailed: return "failed";
  }
  return "?";
}

std::string run_dir(const std::string& sweep_dir, int index) { return sweep_dir + "/run-" + std::to_string(index); }

Outcome read_outcome(const std::string& dir) {
  std::error_code ec;
  if (fs::exists(dir + "/done", ec)) return parse_marker(dir + "/done");
  if (fs::exists(dir + "/cancelled", ec)) return parse_marker(dir + "/cancelled");
  Outcome o;
  o.kind = fs::exists(dir, ec) ? Outcome::kInterrupted : Outcome::kPending;
  return o;
}

pid_t start_run(const std::string& tendril, const Plan& plan, const PlannedRun& run, const std::string& dir) {
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir);
  std::vector<std::string> args{tendril, "run", plan.scene, "--out", fs::absolute(dir).string(),
                                "--seed", std::to_string(run.seed), "--quiet"};
  for (std::size_t k = 0; k < plan.params.size(); ++k)
    args.insert(args.end(), {"--param", plan.params[k] + "=" + run.values[k]});
  if (plan.steps >= 0) args.insert(args.end(), {"--steps", std::to_string(plan.steps)});
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const std::string out = dir + "/stdout.txt", err = dir + "/stderr.txt";
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error(std::string("cannot start a run: fork: ") + std::strerror(errno));
  if (pid == 0) {
    // The child: nothing here may allocate or throw (only async-signal-safe calls until exec).
    prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (getppid() != parent) _exit(127);  // the parent died before prctl took effect
    sigset_t none;
    sigemptyset(&none);
    sigprocmask(SIG_SETMASK, &none, nullptr);
    const int o = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0 || dup2(o, 1) < 0 || dup2(e, 2) < 0 || chdir(plan.workdir.c_str()) != 0) _exit(126);
    execv(tendril.c_str(), argv.data());
    _exit(127);
  }
  return pid;
}

Outcome record_end(const std::string& dir, int wait_status, double seconds, int signalled) {
  Outcome o;
  o.seconds = seconds;
  o.host = host_name();
  if (WIFEXITED(wait_status)) {
    o.exit_status = WEXITSTATUS(wait_status);
    o.kind = o.exit_status == 0 ? Outcome::kOk : Outcome::kFailed;
    if (o.exit_status != 0) o.error = error_of(tail_of(dir + "/stderr.txt"), o.exit_status);
  } else {
    const int sig = WTERMSIG(wait_status);
    o.exit_status = 128 + sig;
    // A crash of the scene itself (SIGSEGV, SIGABRT) repeats: the run is done.
    // A signal from outside -- ours, scancel's SIGTERM, a time limit, the OOM
    // killer's SIGKILL -- does not: the run is cancelled, --resume reruns it.
    const bool outside = sig == SIGTERM || sig == SIGINT || sig == SIGHUP || sig == SIGKILL;
    o.kind = signalled || outside ? Outcome::kCancelled : Outcome::kFailed;
    o.error = std::string(o.kind == Outcome::kCancelled ? "cancelled by SIG" : "crashed with SIG") + sigabbrev_np(sig);
  }
  write_marker(dir + (o.kind == Outcome::kCancelled ? "/cancelled" : "/done"), o);
  return o;
}

}  // namespace tendril::sweep
