#pragma once
// The bounds of every solver setting, checked in one place for every entry
// point that sets them: m:settings / tendril.model{...}, the model database
// reader and replay (DESIGN principle 8). A value outside them is refused,
// never clamped: vie_iterations = 2^31 would make one step last for hours.
#include <cstdint>
#include <optional>
#include <string>

#include "physics/solver.hpp"

namespace tendril {

inline constexpr int kMaxVieIterations = 1000;
inline constexpr int kMaxThreads = 64;

struct SettingError {
  std::string key;      // "vie_iterations"
  std::string message;  // "must be a whole number from 1 to 1000"
};
// The first setting out of its bounds, in declaration order; nullopt when all hold.
std::optional<SettingError> check_settings(const SolverSettings& s);

// A whole number read as a double (a Lua number, an attribute, a journal
// word) when it lies in [lo, hi]; nullopt otherwise, so that no caller casts
// an out-of-range double to an integer (undefined behaviour).
std::optional<std::int64_t> whole_number_in(double x, std::int64_t lo, std::int64_t hi);

}  // namespace tendril
