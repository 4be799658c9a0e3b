#pragma once
// The undo log behind transactions (DESIGN principle 2): while recording,
// every write to the model's storage first saves the old value, so a failed
// production is rolled back exactly, at a cost proportional to what it
// touched, never to the size of the model. Outside a transaction logging is
// one branch.
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <vector>

#include "model/edit_list.hpp"

namespace tendril {

class UndoLog {
 public:
  bool recording() const { return recording_; }
  void begin() {
    if (recording_) throw std::logic_error("transactions do not nest");
    recording_ = true;
    entries_.clear();
  }
  void commit() {
    recording_ = false;
    entries_.clear();
  }
  void rollback() {
    recording_ = false;
    for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) (*it)();
    entries_.clear();
  }
  std::size_t size() const { return entries_.size(); }

  template <class T>
  void value(std::vector<T>& v, std::size_t i) {
    if (recording_) entries_.push_back([&v, i, old = v[i]] { v[i] = old; });
  }
  template <class T>
  void length(std::vector<T>& v) {
    if (recording_) entries_.push_back([&v, n = v.size()] { v.resize(n); });
  }
  template <class T>
  void whole(std::vector<T>& v) {
    if (recording_) entries_.push_back([&v, old = v] { v = old; });
  }
  template <class T>
  void scalar(T& x) {
    if (recording_) entries_.push_back([&x, old = x] { x = old; });
  }

 private:
  bool recording_ = false;
  std::vector<std::function<void()>> entries_;
};

// A vector whose writes through operator[] (and growth, shrinking) are
// logged while a transaction records, and listed in an EditList when one
// watches it. Hot loops use data() and raw(), which bypass both: the solver
// never runs inside a transaction and never writes what it watches.
template <class T>
class LoggedVector {
 public:
  void attach(UndoLog* log) { log_ = log; }
  void watch(EditList* edits) { edits_ = edits; }
  const T& operator[](std::size_t i) const { return v_[i]; }
  T& operator[](std::size_t i) {
    if (log_) log_->value(v_, i);
    if (edits_) edits_->touch(i);
    return v_[i];
  }
  void push_back(const T& x) {
    if (log_) log_->length(v_);
    if (edits_) edits_->touch(v_.size());
    v_.push_back(x);
  }
  void pop_back() {
    if (log_) {
      log_->value(v_, v_.size() - 1);
      log_->length(v_);
    }
    if (edits_) edits_->touch(v_.size() - 1);
    v_.pop_back();
  }
  void clear() {
    if (log_) log_->whole(v_);
    if (edits_) edits_->lose();
    v_.clear();
  }
  const T& back() const { return v_.back(); }
  std::size_t size() const { return v_.size(); }
  bool empty() const { return v_.empty(); }
  T* data() { return v_.data(); }
  const T* data() const { return v_.data(); }
  auto begin() const { return v_.begin(); }
  auto end() const { return v_.end(); }
  std::vector<T>& raw() { return v_; }
  const std::vector<T>& raw() const { return v_; }
  operator const std::vector<T>&() const { return v_; }
  bool operator==(const LoggedVector& o) const { return v_ == o.v_; }

 private:
  std::vector<T> v_;
  UndoLog* log_ = nullptr;
  EditList* edits_ = nullptr;
};

}  // namespace tendril
