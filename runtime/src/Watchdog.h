#ifndef KSE_RUNTIME_SRC_WATCHDOG_H
#define KSE_RUNTIME_SRC_WATCHDOG_H

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace statechart_engine::detail {

class EngineCore;

/// What kind of user code a watched call runs.
enum class CallKind : std::uint8_t {
  Activity,
  ActivityInit,
  Guard,
  GuardInit,
  Action,
  ActionInit,
  Entry,
  Exit,
  Observer
};

/// One caller's current call into user code: the engine's thread has one (guards, actions,
/// hooks, inline activities), every activity run by a worker has one. The caller writes it
/// without a lock or a clock (guards are evaluated far too often for a clock read each); the
/// watchdog samples it. A sequence number that stays odd and the same across samples spanning
/// the limit is a call that overruns.
struct CallSlot {
  std::atomic<std::uint64_t> sequence{0};  // odd while inside a call
  std::atomic<const void*> subject{nullptr};  // the State or TransitionSegmentBase of the call
  std::atomic<CallKind> kind{CallKind::Activity};

  // The watchdog's bookkeeping, used by its thread only.
  std::uint64_t seen = 0;
  std::chrono::steady_clock::time_point since{};
  std::uint64_t overrun = 0;  // the overrun reported for `seen`, 0 when none
  std::string call;           // what it reported

  // Only one thread at a time calls through a slot (the engine's lock or the activity's
  // hand-over orders them), so the sequence needs no read-modify-write.
  // Release stores (plain moves on x86): a reader that sees this call's kind or subject also
  // sees the end of the previous call, so its seqlock check cannot pair one call's kind with
  // another's subject.
  std::uint64_t Begin(CallKind what, const void* on) noexcept {
    kind.store(what, std::memory_order_release);
    subject.store(on, std::memory_order_release);
    const std::uint64_t inside = sequence.load(std::memory_order_relaxed) + 1;
    sequence.store(inside, std::memory_order_release);
    return inside;
  }
  void End(std::uint64_t inside) noexcept { sequence.store(inside + 1, std::memory_order_release); }
  bool Busy() const noexcept { return (sequence.load(std::memory_order_acquire) & 1U) != 0; }
};

/// Marks a call into user code for as long as it runs (also when it throws).
class WatchedCall {
 public:
  WatchedCall(CallSlot& slot, CallKind kind, const void* subject) noexcept
      : slot_(slot), inside_(slot.Begin(kind, subject)) {}
  ~WatchedCall() { slot_.End(inside_); }
  WatchedCall(const WatchedCall&) = delete;
  WatchedCall& operator=(const WatchedCall&) = delete;

 private:
  CallSlot& slot_;
  std::uint64_t inside_;
};

/// One thread for the whole process samples the call slots of every activated statechart, as
/// often as a tenth of the shortest limit (between 5 and 100 ms), and hands overruns to the
/// statechart's reporter. It is started by the first statechart and never ends.
class Watchdog {
 public:
  static Watchdog& Instance();

  void Watch(EngineCore* core);
  /// After it returns the watchdog neither samples the core nor is calling its reporter.
  void Unwatch(EngineCore* core);
  /// A limit changed: look again at how often to sample.
  void LimitsChanged();
  static std::uint64_t NextOverrunId() noexcept;

 private:
  Watchdog() = default;
  void Run();

  std::mutex mutex_;
  std::condition_variable cv_;
  std::vector<EngineCore*> cores_;
  EngineCore* delivering_ = nullptr;
  bool changed_ = false;
  std::thread thread_;
  std::thread::id thread_id_;
};

}  // namespace statechart_engine::detail

#endif
