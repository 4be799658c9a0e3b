#pragma once
// Which elements each thread evaluates when an element loop (spline-beam
// hinges, 6-DOF beams, CST triangles) runs on threads. Thread t owns the
// particles with ids in [bound[t], bound[t + 1]) (the bar step's split of
// the particle chunks) and takes, in the model's order, every element with
// an end it owns; it adds the element's forces into the ends it owns only.
// Every particle is thus summed by one thread, in the model's order of its
// elements, as one thread sums it: the thread count changes the speed,
// never the numbers. An element with ends on two threads is evaluated by
// both (a few along each boundary), rather than kept in a buffer.
// Derived again when the model's revision, its capacity or the split moves.
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

  bool current(const Model& m, const std::vector<ParticleId>& split) const {
    return model_ == &m && revision_ == m.revision && capacity_ == m.particles.capacity() && bound == split;
  }
  // ends(e, out) writes element e's particles into out[0..3) and returns
  // how many it has.
  template <class Ends>
  void derive(const Model& m, const std::vector<ParticleId>& split, std::uint32_t n, Ends ends) {
    bound = split;
    const unsigned threads = unsigned(bound.size()) - 1;
    begin.assign(threads + 1, 0);
    items.clear();
    auto owner = [&](ParticleId p) {
      unsigned t = 0;
      while (t + 1 < threads && p >= bound[t + 1]) ++t;
      return t;
    };
    for (unsigned t = 0; t < threads; ++t) {
      begin[t] = std::uint32_t(items.size());
      for (std::uint32_t e = 0; e < n; ++e) {
        ParticleId at[3];
        const int k = ends(e, at);
        bool mine = false;
        for (int c = 0; c < k; ++c) mine |= owner(at[c]) == t;
        if (mine) items.push_back(e);
      }
    }
    begin[threads] = std::uint32_t(items.size());
    model_ = &m;
    revision_ = m.revision;
    capacity_ = m.particles.capacity();
  }

 private:
  const Model* model_ = nullptr;
  std::uint64_t revision_ = ~std::uint64_t(0);
  std::size_t capacity_ = 0;
};

}  // namespace tendril
