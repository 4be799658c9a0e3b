#pragma once
// The drift of the frames (eq. 3.17 and 3.19): R <- (rotation of dt w) R,
// normalized, for many particles at once (frame_drift.cpp).
#include <cstdint>

#include "model/types.hpp"

namespace tendril {

// R[p] = Quat(rotation_of(dt * w[p]) * R[p]).normalized() for the active
// particles among ids[0..n) (kick_drift's turned), bit for bit, in vectorised blocks; the
// half angles' sines and cosines are half_angle_sincos' (model/half_angle.hpp),
// computed in the blocks.
void drift_frames(const ParticleId* ids, std::uint32_t n, const std::uint8_t* active, double dt, const Vec3* w, Quat* R);

}  // namespace tendril
