#pragma once
// Which indices of a vector were written since a derived copy last caught
// up (DESIGN principle 1: a change costs what it touched), so that the copy
// is patched at a cost proportional to the change instead of derived again.
// Bounded: past kLimit entries, or after a clear, it only says "everything"
// until the consumer catches up again. A rollback needs nothing more: every
// write it undoes was listed when it was made.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tendril {

struct EditList {
  static constexpr std::size_t kLimit = 4096;
  std::vector<std::uint32_t> at;  // written indices, in write order, repeats kept
  bool everything = false;
  // The model revision at which the consumer last caught up (restart).
  std::uint64_t since = ~std::uint64_t(0);

  void touch(std::size_t i) {
    if (everything) return;
    if (at.size() == kLimit) return lose();
    at.push_back(std::uint32_t(i));
  }
  void lose() {
    everything = true;
    at.clear();
  }
  // What a consumer must look at again when the awake elements went from
  // `before` to `now` in number: the indices written and those that crossed
  // the border, ascending, once each. False when the border moved by more
  // than kLimit.
  bool touched(std::size_t before, std::size_t now, std::vector<std::uint32_t>& out) const {
    const std::size_t low = std::min(before, now), high = std::max(before, now);
    if (high - low > kLimit) return false;
    out.assign(at.begin(), at.end());
    for (std::size_t e = low; e < high; ++e) out.push_back(std::uint32_t(e));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return true;
  }
  // Whether every write since the consumer restarted the list at
  // `revision` is listed (it can be patched from the list), and whether
  // none was made (it is up to date).
  bool lists_since(std::uint64_t revision) const { return since == revision && !everything; }
  bool clean_since(std::uint64_t revision) const { return lists_since(revision) && at.empty(); }
  void restart(std::uint64_t revision) {
    everything = false;
    at.clear();
    since = revision;
  }
};

}  // namespace tendril
