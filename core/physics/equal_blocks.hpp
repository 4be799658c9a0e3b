#pragma once
// The lean copies' blocks of elements that share their constants bit for
// bit (BarChunks::same, HingeChunks::same): the step reads such a block's
// first element's constants and streams none of the others'.
#include <algorithm>
#include <bit>
#include <cstdint>

namespace tendril {

inline bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

// Writes to `out`, per block of `block` elements of [begin, end), 1 where
// equal(e, first) holds for each of its elements e, else 0.
template <class Equal, class Out>
void mark_equal_blocks(std::uint32_t begin, std::uint32_t end, std::uint32_t block, Equal equal, Out out) {
  for (std::uint32_t e0 = begin; e0 < end; e0 += block) {
    const std::uint32_t last = std::min(e0 + block, end);
    bool all = true;
    for (std::uint32_t e = e0 + 1; e < last && all; ++e) all = equal(e, e0);
    *out++ = std::uint8_t(all ? 1 : 0);
  }
}

}  // namespace tendril
