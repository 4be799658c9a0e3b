#pragma once
// 1 along the axes a particle may move on, 0 along its locked axes.
#include "model/types.hpp"

namespace tendril {

inline Vec3 free_axes(std::uint8_t lock) {
  return Vec3((lock & kLockX) ? 0.0 : 1.0, (lock & kLockY) ? 0.0 : 1.0, (lock & kLockZ) ? 0.0 : 1.0);
}

// The same for rotations about the global axes.
inline Vec3 free_rotation_axes(std::uint8_t lock) {
  return Vec3((lock & kLockRX) ? 0.0 : 1.0, (lock & kLockRY) ? 0.0 : 1.0, (lock & kLockRZ) ? 0.0 : 1.0);
}

}  // namespace tendril
