#pragma once
// Which elements each thread evaluates when an element loop (spline-beam
// hinges, 6-DOF beams, CST triangles) runs on threads. Thread t owns the
// particles with ids in [bound[t], bound[t + 1]) (the bar step's split of
// the particle chunks) and takes, in the model's order, every element with
// an end it owns; it adds the element's forces into the ends it owns only.
// Every particle is thus summed by one thread, in the model's order of its
// elements, as one thread sums it: the thread count changes the speed,
// never the numbers. An element with ends on two threads is evaluated by
// both (a few along each boundary), rather than kept in a buffer. The fused
// step shares its CST triangles and projected corners out the same way, by
// chunk instead of by thread.
// Derived again when its source moves (a stamp that moves whenever the
// elements' ends may have: the model's revision, or a plan's generation)
// or the split does; a split that only gained parts past its end (new
// particles past the last chunk, which no element reaches) is extended.
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "model/model.hpp"

namespace tendril {

// The particles a thread adds into: every one on one thread; on threads
// (kShared), the ids in [lo, hi) it owns.
template <bool kShared>
struct Owned {
  ParticleId lo, hi;
  bool operator()(ParticleId p) const { return !kShared || p - lo < hi - lo; }
};

struct ElementShares {
  std::vector<ParticleId> bound;     // threads + 1 particle id bounds
  std::vector<std::uint32_t> begin;  // threads + 1, into items
  std::vector<std::uint32_t> items;  // element indices, thread by thread, each in the model's order

  bool current(std::uint64_t source, const std::vector<ParticleId>& split) const {
    return source_ == source && bound == split;
  }
  // Up to date for the split, extended when it only gained parts at its end.
  bool follow(std::uint64_t source, const std::vector<ParticleId>& split) {
    if (source_ != source || split.size() < bound.size() || !std::equal(bound.begin(), bound.end(), split.begin()))
      return false;
    bound = split;
    begin.resize(bound.size(), begin.back());
    return true;
  }
  // ends(e, out) writes element e's particles into out[0..3) and returns
  // how many it has. Also for many parts (the fused step's chunks): each
  // element is placed once per distinct owner of its ends.
  template <class Ends>
  void derive(std::uint64_t source, const std::vector<ParticleId>& split, std::uint32_t n, Ends ends) {
    bound = split;
    const unsigned parts = unsigned(bound.size()) - 1;
    // The owner of p: how many of bound[1 .. parts) are <= p.
    auto owner = [&](ParticleId p) {
      return unsigned(std::upper_bound(bound.begin() + 1, bound.end() - 1, p) - (bound.begin() + 1));
    };
    auto owners = [&](std::uint32_t e, unsigned (&out)[3]) {
      ParticleId at[3];
      const int k = ends(e, at);
      int distinct = 0;
      for (int c = 0; c < k; ++c) {
        const unsigned t = owner(at[c]);
        bool seen = false;
        for (int d = 0; d < distinct; ++d) seen |= out[d] == t;
        if (!seen) out[distinct++] = t;
      }
      return distinct;
    };
    begin.assign(parts + 1, 0);
    unsigned at_part[3];
    for (std::uint32_t e = 0; e < n; ++e) {
      const int d = owners(e, at_part);
      for (int c = 0; c < d; ++c) ++begin[at_part[c] + 1];
    }
    for (unsigned t = 0; t < parts; ++t) begin[t + 1] += begin[t];
    items.resize(begin[parts]);
    std::vector<std::uint32_t> next(begin.begin(), begin.end() - 1);
    for (std::uint32_t e = 0; e < n; ++e) {
      const int d = owners(e, at_part);
      for (int c = 0; c < d; ++c) items[next[at_part[c]]++] = e;
    }
    source_ = source;
  }

 private:
  std::uint64_t source_ = ~std::uint64_t(0);
};

// A stamp no other call returns (a plan's generation, ElementShares' source).
inline std::uint64_t new_stamp() {
  static std::atomic<std::uint64_t> stamps{std::uint64_t(1) << 62};  // apart from any model revision
  return ++stamps;
}

}  // namespace tendril
