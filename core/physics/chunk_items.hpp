#pragma once
// A chunk's items after a patch of a chunked copy (hinge_chunks.hpp,
// beam6_chunks.hpp): the sequence a fresh derivation would give it.
#include <algorithm>
#include <cstdint>
#include <vector>

namespace tendril {

// The items the chunk held at places [begin, end) (held(at): the model's
// index there) that no change touched, merged in model order with the
// touched items (ascending; those from `now` on are gone) that it holds
// now (holds(e)).
template <class Held, class Holds>
void chunk_items(std::uint32_t begin, std::uint32_t end, Held held, const std::vector<std::uint32_t>& touched,
                 std::size_t now, Holds holds, std::vector<std::uint32_t>& out) {
  out.clear();
  for (std::uint32_t at = begin; at < end; ++at)
    if (!std::binary_search(touched.begin(), touched.end(), held(at))) out.push_back(held(at));
  const std::size_t kept = out.size();
  for (std::uint32_t e : touched) {
    if (e >= now) break;
    if (holds(e)) out.push_back(e);
  }
  // Both runs are in model order already: merge them.
  std::inplace_merge(out.begin(), out.begin() + std::ptrdiff_t(kept), out.end());
}

}  // namespace tendril
