#ifndef KSE_RUNTIME_SRC_ENGINE_LOCK_H
#define KSE_RUNTIME_SRC_ENGINE_LOCK_H

#include <atomic>
#include <cstdint>

#if defined(__has_builtin) && (defined(__x86_64__) || defined(__aarch64__))
#if __has_builtin(__builtin_thread_pointer)
#define KSE_ENGINE_LOCK_THREAD_POINTER 1
#endif
#endif

namespace statechart_engine::detail {

/// The engine's lock (ADR 0022): it guards the configuration against a second thread that
/// steps, reads ActiveStates() or changes the observer. Every Step() takes it, so its cost is
/// paid on each transition of a single-threaded user, who never waits for it: taking it is one
/// compare-and-swap, giving it back one release store and a look at whether anyone waits
/// (std::recursive_mutex: two locked instructions and two calls into the C library).
///
/// It is recursive, as the mutex was: user code called inside a step may call back into the
/// statechart (ActiveStates(), Step()).
///
/// A thread that finds it taken spins a little, then queues itself as the next owner (one at a
/// time; the others wait for the queue) and sleeps on a condition variable that the holder
/// signals when it gives the lock back and sees someone queued. While a thread is queued, every
/// other thread, the holder coming back for more included, leaves the lock to it: an engine
/// thread that steps without end cannot starve a caller of ActiveStates(). The holder's look at
/// the queue is not ordered with the waiter's queueing, so a signal can be missed: a waiter
/// therefore also looks again after at most a millisecond.
class EngineLock {
 public:
  EngineLock() = default;
  EngineLock(const EngineLock&) = delete;
  EngineLock& operator=(const EngineLock&) = delete;

  void lock() noexcept {
    const std::uintptr_t self = Self();
    if (owner_.load(std::memory_order_relaxed) == self) {
      ++depth_;  // only its owner gets here, and only the owner touches depth_
      return;
    }
    std::uintptr_t expected = 0;
    if (queued_.load(std::memory_order_relaxed) != 0 ||
        !owner_.compare_exchange_strong(expected, self, std::memory_order_acquire,
                                        std::memory_order_relaxed)) {
      LockSlow(self);
    }
    depth_ = 1;
  }

  void unlock() noexcept {
    if (--depth_ == 0) {
      owner_.store(0, std::memory_order_release);
      if (queued_.load(std::memory_order_relaxed) != 0) WakeWaiters();
    }
  }

 private:
  void LockSlow(std::uintptr_t self) noexcept;
  void WakeWaiters() noexcept;

  /// A value that tells the live threads apart (the thread pointer: no call, no TLS lookup).
  static std::uintptr_t Self() noexcept {
#ifdef KSE_ENGINE_LOCK_THREAD_POINTER
    return reinterpret_cast<std::uintptr_t>(__builtin_thread_pointer());
#else
    static thread_local char token;
    return reinterpret_cast<std::uintptr_t>(&token);
#endif
  }

  std::atomic<std::uintptr_t> owner_{0};   // 0: free
  std::atomic<std::uintptr_t> queued_{0};  // the thread the lock goes to next, 0: none
  unsigned depth_ = 0;
};

}  // namespace statechart_engine::detail

#endif
