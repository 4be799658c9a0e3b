// libFuzzer target: journal replay (`tendril replay`) on any bytes. It must
// refuse a bad journal with ModelError and never crash or leak. Two things a
// valid journal may do are kept out, being costs rather than faults: `open`
// (reads another file) and `steps` beyond 64 in all (a journal's steps cost
// what they say).
#include <cstdint>
#include <sstream>
#include <string>

#include "command/replay.hpp"
#include "io/trace.hpp"

using namespace tendril;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string text(reinterpret_cast<const char*>(data), size);
  std::istringstream lines(text);
  std::string kept;
  double steps = 0;
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string op;
    words >> op;
    if (op == "open") continue;
    if (op == "steps") {
      double n = 0;
      words >> n;
      if (!(n >= 0) || (steps += n) > 64) continue;
    }
    if (op == "settings" && line.find("vie_iterations") != std::string::npos) continue;
    kept += line + "\n";
  }
  std::istringstream in(kept);
  Model m;
  Solver s(m);
  try {
    replay_trace(in, "fuzz.journal", m, s);
  } catch (const ModelError&) {
  }
  return 0;
}
