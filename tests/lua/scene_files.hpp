#pragma once
// Helpers of the Lua suite: a scene written to its own folder and run there
// (tendril.out writes beside it), files read back, and a journal replayed
// into a fresh model.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "command/replay.hpp"
#include "io/model_xml.hpp"
#include "io/trace.hpp"
#include "lua_host.hpp"

namespace tendril::test {

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Writes `scene` to dir/scene.lua and runs it with dir as its output folder
// and no progress lines; returns run_scene's status.
inline int run_scene_in(const std::filesystem::path& dir, const std::string& scene, std::string* error,
                        SceneOptions options = {}) {
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "scene.lua") << scene;
  options.progress = false;
  options.out_dir = dir.string();
  return run_scene((dir / "scene.lua").string(), options, error);
}

// The model a journal file rebuilds (`tendril replay`).
struct Replayed {
  Model model;
  Solver solver{model};
  explicit Replayed(const std::filesystem::path& journal) {
    std::ifstream in(journal);
    replay_trace(in, journal.filename().string(), model, solver);
  }
  std::string xml() const { return model_xml_string(model, solver.settings); }
};

// Whether dir/journal.txt replays to the model saved as dir/live.xml.
inline bool replays_to_live(const std::filesystem::path& dir) {
  return Replayed(dir / "journal.txt").xml() == slurp(dir / "live.xml");
}

}  // namespace tendril::test
