#pragma once
// The parameters a scene declares with tendril.param, read by running it up
// to its first step (SceneOptions::declarations_only).
#include <string>
#include <vector>

#include "lua_host.hpp"

namespace tendril::app {

// Throws std::runtime_error with the scene's error (file:line) when the scene
// fails before its first step.
std::vector<SceneReport::Param> declared_params(const std::string& scene);

// Throws UsageError when a name is not among the declared parameters.
void check_declared(const std::string& scene, const std::vector<std::string>& names);

}  // namespace tendril::app
