#pragma once
// A 2-dimensional generalized map (thesis 4.2.2-4.2.4): darts are compact
// integer indices, the involutions alpha0..alpha2 are arrays, and a free
// involution is a fixed point (a boundary). Deleted darts are recycled.
#include <array>
#include <cstdint>
#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include "model/undo_log.hpp"

namespace tendril {

using Dart = std::uint32_t;
inline constexpr Dart kNoDart = 0xffffffffu;

// A column of per-dart data that follows the map through creation, deletion
// and reuse of darts (CGoGN style). Columns are registered with the map.
// Writes are logged while the map's undo log records a transaction.
class ColumnBase {
 public:
  virtual ~ColumnBase() = default;
  virtual void grow() = 0;  // one more dart, holding the fill value
  virtual void reset(Dart d) = 0;
};

template <class T>
class DartColumn final : public ColumnBase {
 public:
  DartColumn(T fill, UndoLog* log) : fill_(fill) { data_.attach(log); }
  T& operator[](Dart d) { return data_[d]; }
  const T& operator[](Dart d) const { return data_[d]; }
  void grow() override { data_.push_back(fill_); }
  void reset(Dart d) override { data_[d] = fill_; }
  std::size_t size() const { return data_.size(); }

 private:
  T fill_;
  LoggedVector<T> data_;
};

// Bit mask of involutions spanning an orbit: vertex <a1,a2>, edge <a0,a2>,
// face <a0,a1>, connected component <a0,a1,a2>.
enum OrbitMask : unsigned { kA0 = 1, kA1 = 2, kA2 = 4 };
inline constexpr unsigned kVertexOrbit = kA1 | kA2;
inline constexpr unsigned kEdgeOrbit = kA0 | kA2;
inline constexpr unsigned kFaceOrbit = kA0 | kA1;
inline constexpr unsigned kComponentOrbit = kA0 | kA1 | kA2;

class GMap {
 public:
  Dart create_dart();
  void delete_dart(Dart d);  // the dart must be free for every involution
  bool alive(Dart d) const { return d < alive_.size() && alive_[d]; }

  Dart alpha(int i, Dart d) const { return alpha_[i][d]; }
  bool is_free(int i, Dart d) const { return alpha_[i][d] == d; }
  // Makes alpha_i(a) = b and alpha_i(b) = a; both must be i-free.
  void link(int i, Dart a, Dart b);
  // Frees d and its alpha_i image.
  void unlink(int i, Dart d);

  // Visits every dart of the orbit of d spanned by `mask`, in a deterministic
  // breadth-first order starting at d. Returns early when f returns false.
  // Small orbits (vertices, edges, faces) are traversed without allocating.
  template <class F>
  void for_orbit(unsigned mask, Dart d, F&& f) const;
  std::vector<Dart> orbit(unsigned mask, Dart d) const;
  std::size_t orbit_size(unsigned mask, Dart d) const;

  std::size_t dart_count() const { return live_; }
  std::size_t capacity() const { return alive_.size(); }

  // Involution and quasi-manifold checks (alpha0 o alpha2 is an involution).
  // Returns an empty string when valid, otherwise the first violation.
  std::string check() const;

  // The log every change of the map (and of models built on it) goes through.
  UndoLog& undo_log() { return log_; }

  template <class T>
  DartColumn<T>& add_column(T fill) {
    auto c = std::make_unique<DartColumn<T>>(fill, &log_);
    for (std::size_t k = 0; k < alive_.size(); ++k) c->grow();
    auto& ref = *c;
    columns_.push_back(std::move(c));
    return ref;
  }

 GMap();
  GMap(const GMap&) = delete;  // columns and logs point into the map
  GMap& operator=(const GMap&) = delete;

 private:
  UndoLog log_;
  std::array<LoggedVector<Dart>, 3> alpha_;
  LoggedVector<std::uint8_t> alive_;
  LoggedVector<Dart> free_list_;
  std::vector<std::unique_ptr<ColumnBase>> columns_;
  std::size_t live_ = 0;
  bool visit_once(Dart y, std::uint32_t epoch, std::vector<Dart>* seen) const;
  // Scratch for orbit traversal: a visit stamp per dart avoids clearing.
  mutable std::vector<std::uint32_t> stamp_;
  mutable std::uint32_t epoch_ = 0;
  mutable bool in_traversal_ = false;
};

template <class F>
void GMap::for_orbit(unsigned mask, Dart d, F&& f) const {
  // Visit stamps make a traversal linear in the orbit size. A traversal
  // started from inside another one (f calling for_orbit) must not disturb
  // the outer stamps, so it keeps a sorted visited list instead.
  constexpr std::size_t kInline = 32;
  Dart inline_queue[kInline];
  std::vector<Dart> heap_queue;
  std::size_t size = 0;
  auto push = [&](Dart x) {
    if (size < kInline) inline_queue[size] = x;
    else {
      if (heap_queue.empty()) heap_queue.assign(inline_queue, inline_queue + kInline);
      heap_queue.push_back(x);
    }
    ++size;
  };
  auto at = [&](std::size_t k) { return size <= kInline ? inline_queue[k] : heap_queue[k]; };
  const bool nested = in_traversal_;
  std::vector<Dart> seen;
  std::uint32_t epoch = 0;
  if (!nested) {
    if (++epoch_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      epoch_ = 1;
    }
    epoch = epoch_;
  }
  visit_once(d, epoch, nested ? &seen : nullptr);
  push(d);
  struct Restore {  // also when f throws
    bool& flag;
    bool value;
    ~Restore() { flag = value; }
  } restore{in_traversal_, nested};
  in_traversal_ = true;
  for (std::size_t head = 0; head < size; ++head) {
    const Dart x = at(head);
    if (!f(x)) break;
    for (int i = 0; i < 3; ++i)
      if ((mask & (1u << i)) && visit_once(alpha_[i][x], epoch, nested ? &seen : nullptr)) push(alpha_[i][x]);
  }
}

}  // namespace tendril
