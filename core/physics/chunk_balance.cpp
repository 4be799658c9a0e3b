#include "physics/chunk_balance.hpp"

#include <algorithm>

namespace tendril {

const std::vector<std::uint32_t>& ChunkBalance::split(const BarChunks& B, unsigned threads) {
  const std::uint32_t n = std::uint32_t(B.chunks.size());
  if (share_.size() != threads) share_.assign(threads, 1.0 / threads);
  first_.assign(threads + 1, n);  // allocates when the thread count grows only
  first_[0] = 0;
  const double total = double(B.particles.size());
  double before = 0;
  std::uint32_t c = 0;
  for (unsigned t = 1; t < threads; ++t) {
    // Each range ends at the chunk boundary nearest its share.
    before += share_[t - 1];
    const double target = total * before;
    while (c < n && B.chunks[c].particles_end <= target) ++c;
    const double below = c > 0 ? B.chunks[c - 1].particles_end : 0;
    if (c < n && B.chunks[c].particles_end - target < target - below) ++c;
    first_[t] = std::max(c, first_[t - 1]);
  }
  return first_;
}

void ChunkBalance::measured(const BarChunks& B, const std::vector<double>& busy) {
  const unsigned threads = unsigned(share_.size());
  if (busy.size() != threads || first_.size() != threads + 1) return;
  // Particles a second per thread; a run too short to time (or a thread
  // without particles) leaves the shares as they were. (Two passes, so
  // that a step allocates nothing.)
  auto speed = [&](unsigned t) {
    const std::uint32_t a = first_[t], b = first_[t + 1];
    const double particles = a < b ? double(B.chunks[b - 1].particles_end - B.chunks[a].particles_begin) : 0.0;
    return particles > 0 && busy[t] > 0 ? particles / busy[t] : 0.0;
  };
  double sum = 0, time = 0;
  for (unsigned t = 0; t < threads; ++t) {
    if (!(speed(t) > 0)) return;
    sum += speed(t);
    time += busy[t];
  }
  if (time < 20e-6 * threads) return;
  // A moving average over runs (a fifth of the new one), no share below a
  // quarter of an equal one, so that a thread stopped once is not dropped.
  double total = 0;
  for (unsigned t = 0; t < threads; ++t) {
    share_[t] = std::max(0.8 * share_[t] + 0.2 * speed(t) / sum, 0.25 / threads);
    total += share_[t];
  }
  for (double& s : share_) s /= total;
}

}  // namespace tendril
