// The progress of a long m:run{}: in place on a terminal, plain lines in a
// log, and a final line that says whether the run converged and why not.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "run_progress.hpp"

using namespace tendril;
using tendril::lua::ProgressStyle;
using tendril::lua::RunProgress;

namespace {

ProgressStyle immediate(std::FILE* out, bool terminal) {
  ProgressStyle style;
  style.out = out;
  style.terminal = terminal;
  style.first_line = std::chrono::milliseconds(0);
  style.every = std::chrono::milliseconds(0);
  return style;
}

std::string contents(std::FILE* f) {
  std::rewind(f);
  std::string s;
  for (int c; (c = std::fgetc(f)) != EOF;) s += char(c);
  std::fclose(f);
  return s;
}

RunResult result(std::uint64_t steps, double residual, bool converged) {
  RunResult r;
  r.steps = steps;
  r.residual = residual;
  r.converged = converged;
  return r;
}

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto k = s.find(what); k != std::string::npos; k = s.find(what, k + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("progress: durations read as seconds, minutes or hours") {
  CHECK(duration_text(1.46) == "1.5 s");
  CHECK(duration_text(75) == "1 min 15 s");
  CHECK(duration_text(2 * 3600 + 5 * 60 + 10) == "2 h 05 min");
  CHECK(duration_text(-1) == "?");
}

TEST_CASE("progress: on a terminal one line is rewritten in place, then replaced by the final line") {
  std::FILE* f = std::tmpfile();
  std::string why;
  {
    RunProgress meter(true, 1e-3, 1000, false, immediate(f, true));
    meter.update(result(100, 0.5, false), 1100, 42);
    meter.update(result(200, 0.25, false), 1200, 42);
    why = meter.finish(result(250, 4e-4, true));
  }
  const std::string s = contents(f);
  CHECK(count(s, "\r[tendril] step ") == 2);
  CHECK(count(s, "\n") == 1);  // only the final line ends one
  CHECK(s.find("step 1200 (run 200 of 1000)") != std::string::npos);
  CHECK(s.find("residual 2.50e-01 N (tolerance 1.0e-03)  42 particles") != std::string::npos);
  CHECK(s.find("left") != std::string::npos);  // max_steps is known: the time left is estimated
  CHECK(why.rfind("converged in 250 steps", 0) == 0);
  CHECK(why.find("residual 4.00e-04 N < tolerance 1.0e-03") != std::string::npos);
  CHECK(s.find("\r\033[K[tendril] " + why + "\n") != std::string::npos);
}

TEST_CASE("progress: in a log every update is a plain line; the final line says why the run stopped") {
  std::FILE* f = std::tmpfile();
  std::string why;
  {
    RunProgress meter(true, 1e-6, 300, false, immediate(f, false));
    meter.update(result(100, 2e-2, false), 100, 7);
    meter.update(result(200, 1e-2, false), 200, 7);
    why = meter.finish(result(300, 8e-3, false));
  }
  const std::string s = contents(f);
  CHECK(s.find('\r') == std::string::npos);
  CHECK(s.find('\033') == std::string::npos);
  CHECK(count(s, "\n") == 3);
  CHECK(why.rfind("not converged: max_steps 300 reached", 0) == 0);
  CHECK(why.find("residual 8.00e-03 N, tolerance 1.0e-06") != std::string::npos);
}

TEST_CASE("progress: a cap from --steps, a run still moving below the tolerance, a residual gone non-finite") {
  std::FILE* f = std::tmpfile();
  RunProgress by_option(true, 1e-3, 50, true, immediate(f, false));
  CHECK(by_option.finish(result(50, 0.1, false)).rfind("not converged: --steps 50 reached", 0) == 0);
  RunProgress moving(true, 1e-3, 50, false, immediate(f, false));
  CHECK(moving.finish(result(50, 1e-4, false)).find("below tolerance 1.0e-03 but still moving") != std::string::npos);
  RunProgress blown(true, 1e-3, 50, false, immediate(f, false));
  CHECK(blown.finish(result(12, std::nan(""), false)).rfind("not converged: the residual is nan after 12 steps", 0) ==
        0);
  // No progress was shown, but a run that did not converge says so anyway.
  const std::string s = contents(f);
  CHECK(count(s, "\n") == 3);
  CHECK(count(s, "[tendril] not converged: ") == 3);
}

TEST_CASE("progress: the final line names the verdict and its numbers") {
  std::FILE* f = std::tmpfile();
  RunResult stalled = result(20000, 0.5, false);
  stalled.verdict = Verdict::Stalled;
  stalled.best_before = 0.2, stalled.best_after = 0.21, stalled.kinetic_resets = 4000;
  stalled.force_scale = 1e8, stalled.relative_residual = 5e-9;
  RunProgress a(true, 1e-3, 20000, false, immediate(f, false));
  const std::string why = a.finish(stalled);
  CHECK(why.rfind("not converged: stalled: max_steps 20000 reached", 0) == 0);
  CHECK(why.find("its lowest in the second half of the run, 2.10e-01 N, is not below 0.9 times its lowest in the "
                 "first half, 2.00e-01 N (4000 kinetic-damping resets in the run)") != std::string::npos);
  CHECK(why.find("; relative residual 5.00e-09 of the force scale 1e+08 N") != std::string::npos);
  RunResult diverged = result(3, 1e9, false);
  diverged.verdict = Verdict::Diverged;
  diverged.detail = "the residual grew to 1e+09 N";
  RunProgress b(true, 1e-3, 20000, false, immediate(f, false));
  CHECK(b.finish(diverged).rfind("not converged: diverged at step 3 (", 0) == 0);
  RunLimits relative;
  relative.tolerance = 0, relative.relative = 1e-9;
  RunResult done = result(700, 0.05, true);
  done.verdict = Verdict::Converged, done.threshold = 0.1, done.force_scale = 1e8, done.relative_residual = 5e-10;
  RunProgress c(true, relative, 20000, false, immediate(f, false));
  const std::string ok = c.finish(done);
  CHECK(ok.find("residual 5.00e-02 N < tolerance 1.0e-01 (5.00e-10 of the force scale 1e+08 N)") != std::string::npos);
  const std::string s = contents(f);
  CHECK(count(s, "[tendril] not converged: ") == 2);  // the converged run is silent
}

TEST_CASE("progress: --quiet shows nothing, a short run shows nothing") {
  std::FILE* f = std::tmpfile();
  ProgressStyle style = immediate(f, false);
  RunProgress quiet(false, 1e-3, 10, false, style);
  quiet.update(result(5, 1, false), 5, 1);
  quiet.finish(result(10, 1, false));
  style.first_line = std::chrono::milliseconds(60000);
  RunProgress brief(true, 1e-3, 10, false, style);
  brief.update(result(5, 1, false), 5, 1);
  brief.finish(result(10, 1, true));
  CHECK(contents(f).empty());
}
