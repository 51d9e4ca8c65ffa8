#ifndef KSE_MESSAGING_SPIN_LOCK_H
#define KSE_MESSAGING_SPIN_LOCK_H

#include <atomic>
#include <thread>

namespace kse::messaging {

/// The lock of a blackboard and of a hub (ADR 0025). What it guards is a few pointers and
/// counters, held for a few hundred nanoseconds at most and never across user code; a robot
/// takes such locks dozens of times a cycle, nearly always free. Taking it is one atomic
/// exchange, giving it back a release store (a std::mutex: two locked instructions and two calls
/// into the C library). A thread that finds it taken spins briefly, then yields its core.
class SpinLock {
 public:
  SpinLock() = default;
  SpinLock(const SpinLock&) = delete;
  SpinLock& operator=(const SpinLock&) = delete;

  void lock() noexcept {
    if (!taken_.exchange(true, std::memory_order_acquire)) return;
    LockSlow();
  }
  bool try_lock() noexcept {
    return !taken_.load(std::memory_order_relaxed) && !taken_.exchange(true, std::memory_order_acquire);
  }
  void unlock() noexcept { taken_.store(false, std::memory_order_release); }

 private:
  void LockSlow() noexcept {
    for (unsigned spins = 0;;) {
      // Look without writing until it is free, so that waiters do not fight over the line.
      while (taken_.load(std::memory_order_relaxed)) {
        if (++spins < 64) {
#if defined(__x86_64__) || defined(__i386__)
          __builtin_ia32_pause();
#endif
        } else {
          std::this_thread::yield();  // the holder may have been preempted: let it run
        }
      }
      if (!taken_.exchange(true, std::memory_order_acquire)) return;
    }
  }

  std::atomic<bool> taken_{false};
};

}  // namespace kse::messaging

#endif
