#include "kse/messaging/Clock.h"

#include "kse/messaging/Kind.h"

namespace kse::messaging {

const char* ToString(Kind kind) noexcept {
  switch (kind) {
    case Kind::Signal:
      return "Signal";
    case Kind::State:
      return "State";
    case Kind::Data:
      return "Data";
  }
  return "?";
}

Clock::~Clock() = default;

const SteadyClock& SteadyClock::Instance() {
  static const SteadyClock instance;
  return instance;
}

TimePoint SteadyClock::Now() const { return std::chrono::steady_clock::now(); }

ManualClock::ManualClock(TimePoint start) : ticks_(start.time_since_epoch().count()) {}

TimePoint ManualClock::Now() const {
  return TimePoint(Duration(ticks_.load(std::memory_order_acquire)));
}

void ManualClock::Set(TimePoint now) {
  ticks_.store(now.time_since_epoch().count(), std::memory_order_release);
}

void ManualClock::Advance(Duration by) { ticks_.fetch_add(by.count(), std::memory_order_acq_rel); }

}  // namespace kse::messaging
