#pragma once
// Every file tendril reads as data (model databases, journals) goes through
// here: only regular files, and only up to a size, so a FIFO, a device such as
// /dev/zero, a directory or a runaway file is refused with a clear error
// instead of hanging, spinning or exhausting memory.
#include <cstddef>
#include <stdexcept>
#include <string>

namespace tendril {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

inline constexpr std::size_t kMaxInputBytes = std::size_t(1) << 30;  // 1 GiB

// The whole file; throws InputError naming `path` when it is not a regular
// file, larger than max_bytes or unreadable.
std::string read_input_file(const std::string& path, std::size_t max_bytes = kMaxInputBytes);

}  // namespace tendril
