#pragma once
// The split of the bar chunks over threads: contiguous ranges, equal until
// measured (the element loops' owners, Solver::element_bounds), and in
// for_chunks each thread's as many particles as its measured speed earns. On a
// shared machine one core can run the step 1.4x slower than the other
// (another guest on its sibling), and equal ranges then left the faster
// thread waiting a quarter of a 10K step. The split never changes a number:
// every sum keeps its chunk order whoever runs the chunk.
#include <cstdint>
#include <vector>

#include "physics/bar_chunks.hpp"

namespace tendril {

class ChunkBalance {
 public:
  // The ranges for `threads` threads: thread t runs chunks [first[t], first[t + 1]).
  const std::vector<std::uint32_t>& split(const BarChunks& B, unsigned threads);
  // The last split (empty before the first).
  const std::vector<std::uint32_t>& first() const { return first_; }
  // After a run under the last split: each thread's busy seconds (its
  // waits taken out); moves each thread's share toward its speed.
  void measured(const BarChunks& B, const std::vector<double>& busy);

 private:
  std::vector<double> share_;  // of the particles, per thread, summing to 1
  std::vector<std::uint32_t> first_;
};

}  // namespace tendril
