#include "scene_declarations.hpp"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "agents_library.hpp"
#include "command.hpp"

namespace tendril::app {

std::vector<SceneReport::Param> declared_params(const std::string& scene) {
  // Whatever the scene writes before its first step goes to a scratch folder.
  std::string scratch = (std::filesystem::temp_directory_path() / "tendril-params-XXXXXX").string();
  if (!mkdtemp(scratch.data())) throw std::runtime_error("cannot create a scratch folder in the temp directory");
  SceneOptions options;
  options.declarations_only = true;
  options.progress = false;
  options.out_dir = scratch;
  options.preload = agents_library();
  SceneReport report;
  std::string error;
  const int status = run_scene(scene, options, &error, &report);
  std::error_code ignored;
  std::filesystem::remove_all(scratch, ignored);
  if (status != 0) throw std::runtime_error(error);
  return report.params;
}

void check_declared(const std::string& scene, const std::vector<std::string>& names) {
  const auto declared = declared_params(scene);
  for (const std::string& name : names) {
    if (std::any_of(declared.begin(), declared.end(), [&](const SceneReport::Param& p) { return p.name == name; }))
      continue;
    std::string known;
    for (const SceneReport::Param& p : declared) known += (known.empty() ? "" : ", ") + p.name;
    throw UsageError("--param " + name + ": " + scene + " declares no such parameter (" +
                     (known.empty() ? std::string("it declares none") : "it declares " + known) + ")");
  }
}

}  // namespace tendril::app
