#include "Watchdog.h"

#include <algorithm>
#include <utility>

#include "EngineCore.h"

namespace statechart_engine::detail {

namespace {

constexpr auto kFastestLook = std::chrono::milliseconds(5);
constexpr auto kSlowestLook = std::chrono::milliseconds(100);
constexpr auto kIdleLook = std::chrono::seconds(1);  // every chart has the watchdog off

}  // namespace

Watchdog& Watchdog::Instance() {
  // Never destroyed: statecharts destroyed during static destruction still unwatch, and the
  // thread may be waiting when the process exits.
  static Watchdog* const instance = new Watchdog();
  return *instance;
}

std::uint64_t Watchdog::NextOverrunId() noexcept {
  static std::atomic<std::uint64_t> last{0};
  return last.fetch_add(1, std::memory_order_relaxed) + 1;
}

void Watchdog::Watch(EngineCore* core) {
  std::lock_guard<std::mutex> lock(mutex_);
  cores_.push_back(core);
  changed_ = true;
  if (!thread_.joinable()) {
    thread_ = std::thread([this] { Run(); });
    thread_id_ = thread_.get_id();
  }
  cv_.notify_all();
}

void Watchdog::Unwatch(EngineCore* core) {
  std::unique_lock<std::mutex> lock(mutex_);
  cores_.erase(std::remove(cores_.begin(), cores_.end(), core), cores_.end());
  if (std::this_thread::get_id() == thread_id_) {
    return;  // a reporter that destroys its statechart: the delivery in progress is this call
  }
  cv_.wait(lock, [&] { return delivering_ != core; });
}

void Watchdog::LimitsChanged() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    changed_ = true;
  }
  cv_.notify_all();
}

void Watchdog::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  std::vector<std::pair<EngineCore*, EngineReport>> reports;
  for (;;) {
    std::chrono::steady_clock::duration look = kIdleLook;
    for (const EngineCore* core : cores_) {
      const auto shortest = core->ShortestWatchdogLimit();
      if (shortest.count() > 0) look = std::min<std::chrono::steady_clock::duration>(look, shortest / 10);
    }
    look = std::clamp<std::chrono::steady_clock::duration>(look, kFastestLook, kIdleLook);
    if (look > kSlowestLook && look < kIdleLook) look = kSlowestLook;
    cv_.wait_for(lock, look, [this] { return changed_; });
    changed_ = false;

    const auto now = std::chrono::steady_clock::now();
    for (EngineCore* core : cores_) {
      core->Inspect(now, [&](EngineReport report) { reports.emplace_back(core, std::move(report)); });
    }
    // Reporters run without the lock (they may be slow, and Watch/Unwatch must not wait on
    // them), but never for a core that has been unwatched meanwhile.
    for (auto& [core, report] : reports) {
      if (std::find(cores_.begin(), cores_.end(), core) == cores_.end()) continue;
      delivering_ = core;
      lock.unlock();
      core->Deliver(report);
      lock.lock();
      delivering_ = nullptr;
      cv_.notify_all();
    }
    reports.clear();
  }
}

}  // namespace statechart_engine::detail
