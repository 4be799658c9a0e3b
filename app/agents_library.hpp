#pragma once
// The agents layer's Lua files (name, source), in load order.
#include <string>
#include <utility>
#include <vector>

namespace tendril {
const std::vector<std::pair<std::string, std::string>>& agents_library();
}
