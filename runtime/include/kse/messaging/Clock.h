#ifndef KSE_MESSAGING_CLOCK_H
#define KSE_MESSAGING_CLOCK_H

#include <atomic>
#include <chrono>

namespace kse::messaging {

using TimePoint = std::chrono::steady_clock::time_point;
using Duration = std::chrono::steady_clock::duration;

/// The time source of a MessageHub, its blackboards (message time stamps, timers) and the engine.
class Clock {
 public:
  using TimePoint = kse::messaging::TimePoint;

  Clock() = default;
  Clock(const Clock&) = delete;
  Clock& operator=(const Clock&) = delete;
  virtual ~Clock();

  virtual TimePoint Now() const = 0;
};

/// Real monotonic time (std::chrono::steady_clock).
class SteadyClock final : public Clock {
 public:
  /// The process-wide instance (the default clock of MessageHub).
  static const SteadyClock& Instance();

  TimePoint Now() const override;
};

/// A clock that moves only when told to: for tests and simulation. Thread-safe.
class ManualClock final : public Clock {
 public:
  explicit ManualClock(TimePoint start = TimePoint{});

  TimePoint Now() const override;
  void Set(TimePoint now);
  void Advance(Duration by);

 private:
  std::atomic<Duration::rep> ticks_;
};

}  // namespace kse::messaging

#endif
