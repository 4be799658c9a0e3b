#pragma once
// Four doubles in one vector (GCC's vector extension; two SSE2 registers in
// the portable copies of simd_clones.hpp, one AVX register in the others),
// and the 4 x 4 transpose that turns four rows (one particle's or bar's
// x, y, z and a fourth value each) into four columns (one quantity of the
// four each) and back.

namespace tendril {

using Lanes = double __attribute__((vector_size(32)));
using LaneBits = long long __attribute__((vector_size(32)));

// a, b, c, d turned into their columns, in place: afterwards a holds the
// first lanes of the four, b the second ones, and so on.
[[gnu::always_inline]] inline void transpose(Lanes& a, Lanes& b, Lanes& c, Lanes& d) {
  const Lanes t0 = __builtin_shufflevector(a, b, 0, 4, 2, 6);
  const Lanes t1 = __builtin_shufflevector(a, b, 1, 5, 3, 7);
  const Lanes t2 = __builtin_shufflevector(c, d, 0, 4, 2, 6);
  const Lanes t3 = __builtin_shufflevector(c, d, 1, 5, 3, 7);
  a = __builtin_shufflevector(t0, t2, 0, 1, 4, 5);
  b = __builtin_shufflevector(t1, t3, 0, 1, 4, 5);
  c = __builtin_shufflevector(t0, t2, 2, 3, 6, 7);
  d = __builtin_shufflevector(t1, t3, 2, 3, 6, 7);
}

}  // namespace tendril
