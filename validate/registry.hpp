#pragma once
// Every validation case, in the file-name order of validate/cases/.
#include <string_view>
#include <vector>

#include "case.hpp"

namespace tendril::validate {

const std::vector<Case>& cases();
const Case* find_case(std::string_view name);  // nullptr if none

}  // namespace tendril::validate
