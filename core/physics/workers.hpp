#pragma once
// The solver's threads (DESIGN "Parallel and still deterministic"): a small
// pool that runs one task per thread and waits for all of them. The work is
// partitioned by the caller into fixed chunks that do not depend on the
// number of threads, and every sum over chunks is reduced in chunk order, so
// the thread count changes the speed, never the numbers.
// Idle threads spin for 100 us, then sleep on a futex (std::atomic::wait):
// a step at 10K particles lasts ~150 us, and a wake-up from sleep costs a
// noticeable part of that (workers.cpp).
#include <atomic>
#include <concepts>
#include <cstdint>
#include <exception>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

namespace tendril {

// A callable passed down without copying or allocating (a step allocates
// nothing): it refers to the caller's lambda, which must outlive the call.
template <class Signature>
class FunctionRef;
template <class R, class... Args>
class FunctionRef<R(Args...)> {
 public:
  template <class F>
    requires(!std::same_as<std::remove_cvref_t<F>, FunctionRef> && std::invocable<F&, Args...>)
  FunctionRef(F&& f)
      : object_(const_cast<void*>(static_cast<const void*>(std::addressof(f)))),
        call_([](void* o, Args... a) -> R { return (*static_cast<std::remove_reference_t<F>*>(o))(a...); }) {}
  R operator()(Args... a) const { return call_(object_, a...); }

 private:
  void* object_;
  R (*call_)(void*, Args...);
};

// Returns once `a` holds `value` or more (spinning first, as the idle
// threads do).
void wait_for(std::atomic<std::uint64_t>& a, std::uint64_t value);

class Workers {
 public:
  Workers() = default;
  Workers(const Workers&) = delete;
  Workers& operator=(const Workers&) = delete;
  ~Workers();
  // task(t) for t = 0 .. n-1 at once (t = 0 on the caller); returns when all
  // are done and rethrows the exception of the lowest t that threw.
  void run(unsigned n, FunctionRef<void(unsigned)> task);

 private:
  void resize(unsigned helpers);
  void loop(unsigned t);
  std::vector<std::thread> threads_;
  std::vector<std::exception_ptr> errors_;
  FunctionRef<void(unsigned)>* task_ = nullptr;
  std::atomic<unsigned> generation_{0};
  std::atomic<unsigned> remaining_{0};
  bool stop_ = false;
};

}  // namespace tendril
