// Issue 13: replay accepted values the Lua API and the model database reader
// refuse (dt <= 0, NaN positions, lock > 63, negative GJ, ...), wrote model
// files tendril.load refused, and hung on `steps 1e300` and `vie_iterations
// 2000000000`. Each journal of tests/lua/journals/refused/ did one of these
// at 823d526; the command layer's checks now refuse each, naming the line,
// the command and the parameter.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "command/replay.hpp"
#include "model/model.hpp"
#include "physics/solver.hpp"

using namespace tendril;

namespace {

const std::filesystem::path kRefused = std::filesystem::path(TENDRIL_SOURCE_DIR) / "tests/lua/journals/refused";

// What replaying `file` throws ("" when it replays).
std::string refusal(const std::string& file) {
  std::ifstream in(kRefused / file);
  REQUIRE(in);
  Model m;
  Solver s(m);
  try {
    replay_trace(in, file, m, s);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("replay refuses the values Lua and the model reader refuse, naming line and parameter") {
  const std::pair<const char*, const char*> cases[] = {
      {"beam-from-segments-huge", "2: beam_from: 'segments' '1e300' is not a whole number"},
      {"beam-section6-gj-neg", "5: section6: 'GJ' must be >= 0"},
      {"cable-rest-neg", "3: cable: 'rest_length' must be from 0 to 1e+13"},
      {"dt-negative", "4: settings: 'dt' must be a finite number > 0"},
      {"dt-word", "3: settings: 'dt' 'fast' is not a number"},
      {"dt-zero", "4: settings: 'dt' must be a finite number > 0"},
      {"gravity-nan", "1: gravity: 'g' must be a finite number"},
      {"load-inf", "3: load: 'force' must be a finite number"},
      {"load-nan", "3: load: 'force' must be a finite number"},
      {"lock-300", "3: lock: 'bits' must be a whole number from 0 to 63"},
      {"lock-64", "3: lock: 'bits' must be a whole number from 0 to 63"},
      {"lock-frac", "3: lock: 'bits' '1.5' is not a whole number"},
      {"lock-neg", "3: lock: 'bits' '-1' is not a whole number"},
      {"mass-factor-0", "3: settings: 'mass_factor' must be a finite number >= 1"},
      {"passive-nan", "3: passive: 'passive' 'nan' is not a whole number"},
      {"position-far", "3: position: 'x' must be from -1e+12 to 1e+12"},
      {"position-nan", "3: position: 'x' must be a finite number"},
      {"quad-grid-huge", "3: quad_grid: 'rows' '1e300' is not a whole number"},
      {"role-frac", "3: role: 'role' '1.5' is not a whole number"},
      {"steps-frac", "3: steps: 'n' '2.5' is not a whole number"},
      {"steps-huge", "3: steps: 'n' '1e300' is not a whole number"},  // hung
      {"steps-nan", "3: steps: 'n' 'nan' is not a whole number"},
      {"steps-neg", "3: steps: 'n' '-5' is not a whole number"},
      {"vie-iter-huge", "4: settings: 'vie_iterations' must be a whole number from 0 to 1000"},  // hung
      {"viscous-3", "3: settings: 'viscous' must be in [0, 2)"},
  };
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kRefused)) files += entry.path().extension() == ".journal";
  CHECK(files == std::size(cases));  // every journal there is checked here
  for (const auto& [name, message] : cases) {
    const std::string file = std::string(name) + ".journal";
    CAPTURE(file);
    CHECK(refusal(file) == file + ":" + message);
  }
}
