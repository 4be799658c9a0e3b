#include "physics/workers.hpp"

#include <chrono>

namespace tendril {

namespace {
// Spins this long before sleeping: about a 10K-particle step and the
// solver's serial work between two steps, so that a helper stays awake from
// one step to the next. Woken from a futex, a helper on the 2-core virtual
// development machine started late enough to cost the bar net at 10K most
// of its second thread (docs/performance.md, stop 33).
constexpr auto kSpin = std::chrono::microseconds(100);

// Tells the core this is a spin loop (lets the other hardware thread run).
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

template <class T, class Done>
void wait_until(std::atomic<T>& a, Done&& done) {
  const auto until = std::chrono::steady_clock::now() + kSpin;
  for (int k = 0;; ++k) {
    if (done(a.load(std::memory_order_acquire))) return;
    if ((k & 63) == 63 && std::chrono::steady_clock::now() > until) break;
    relax();
  }
  for (T v = a.load(std::memory_order_acquire); !done(v); v = a.load(std::memory_order_acquire)) a.wait(v);
}
}  // namespace

void wait_for(std::atomic<std::uint64_t>& a, std::uint64_t value) {
  wait_until(a, [value](std::uint64_t v) { return v >= value; });
}

Workers::~Workers() { resize(0); }

void Workers::resize(unsigned helpers) {
  if (helpers == threads_.size()) return;
  if (!threads_.empty()) {
    stop_ = true;
    generation_.fetch_add(1, std::memory_order_release);
    generation_.notify_all();
    for (std::thread& t : threads_) t.join();
    threads_.clear();
    stop_ = false;
  }
  errors_.assign(helpers + 1, nullptr);
  for (unsigned t = 0; t < helpers; ++t) threads_.emplace_back([this, t] { loop(t + 1); });
}

void Workers::loop(unsigned t) {
  unsigned seen = 0;
  for (;;) {
    wait_until(generation_, [seen](unsigned g) { return g != seen; });
    seen = generation_.load(std::memory_order_acquire);
    if (stop_) return;
    try {
      (*task_)(t);
    } catch (...) {
      errors_[t] = std::current_exception();
    }
    if (remaining_.fetch_sub(1, std::memory_order_acq_rel) == 1) remaining_.notify_one();
  }
}

void Workers::run(unsigned n, FunctionRef<void(unsigned)> task) {
  if (n <= 1) {
    task(0);
    return;
  }
  resize(n - 1);
  for (std::exception_ptr& e : errors_) e = nullptr;
  task_ = &task;
  remaining_.store(n - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  generation_.notify_all();
  try {
    task(0);
  } catch (...) {
    errors_[0] = std::current_exception();
  }
  wait_until(remaining_, [](unsigned r) { return r == 0; });
  for (const std::exception_ptr& e : errors_)
    if (e) std::rethrow_exception(e);
}

}  // namespace tendril
