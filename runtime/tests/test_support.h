#ifndef KSE_RUNTIME_TESTS_TEST_SUPPORT_H
#define KSE_RUNTIME_TESTS_TEST_SUPPORT_H

// Building blocks for the engine tests: an event log, probe states that log OnEntry/OnExit,
// conditions and actions driven by flags, and activities that count, block or throw.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "kse/messages/all.h"
#include "statechart_engine/statechart_engine.h"

namespace kse_test {

using namespace statechart_engine;
using kse::messaging::ManualClock;
using kse::messaging::MessageHub;

/// A thread-safe list of events.
class Log {
 public:
  void Add(std::string event) {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.push_back(std::move(event));
  }
  std::vector<std::string> Events() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return events_;
  }
  void Clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.clear();
  }

 private:
  mutable std::mutex mutex_;
  std::vector<std::string> events_;
};

/// A state of type Base that logs "enter <name>" and "exit <name>".
template <class Base>
class Probe : public Base {
 public:
  template <class... Extra>
  Probe(Log* log, std::string name, State* parent, Extra&&... extra)
      : Base(std::move(name), parent, std::forward<Extra>(extra)...), log_(log) {}
  void OnEntry() override { log_->Add("enter " + this->Name()); }
  void OnExit() override { log_->Add("exit " + this->Name()); }

 private:
  Log* log_;
};

/// A guard that returns a flag's value and counts its evaluations.
class FlagCondition : public ICondition {
 public:
  explicit FlagCondition(std::shared_ptr<std::atomic<bool>> flag,
                         std::shared_ptr<std::atomic<int>> evaluations = nullptr)
      : flag_(std::move(flag)), evaluations_(std::move(evaluations)) {}
  bool Eval() override {
    if (evaluations_) ++*evaluations_;
    return flag_->load();
  }

 private:
  std::shared_ptr<std::atomic<bool>> flag_;
  std::shared_ptr<std::atomic<int>> evaluations_;
};

inline std::shared_ptr<std::atomic<bool>> Flag(bool value) {
  return std::make_shared<std::atomic<bool>>(value);
}
inline std::shared_ptr<std::atomic<int>> Counter() { return std::make_shared<std::atomic<int>>(0); }

inline std::unique_ptr<ICondition> When(std::shared_ptr<std::atomic<bool>> flag,
                                        std::shared_ptr<std::atomic<int>> evaluations = nullptr) {
  return std::make_unique<FlagCondition>(std::move(flag), std::move(evaluations));
}
inline std::unique_ptr<ICondition> Always() { return When(Flag(true)); }
inline std::unique_ptr<ICondition> Never() { return When(Flag(false)); }

/// A guard from a function (which gets the condition's blackboard).
class LambdaCondition : public ICondition {
 public:
  LambdaCondition(std::function<bool(Blackboard&)> eval, std::vector<std::string> topics = {})
      : eval_(std::move(eval)), topics_(std::move(topics)) {}
  void UserInit() override {
    for (const auto& topic : topics_) _blk->Subscribe(topic);
  }
  bool Eval() override { return eval_(*_blk); }

 private:
  std::function<bool(Blackboard&)> eval_;
  std::vector<std::string> topics_;
};

inline std::unique_ptr<ICondition> If(std::function<bool(Blackboard&)> eval,
                                      std::vector<std::string> topics = {}) {
  return std::make_unique<LambdaCondition>(std::move(eval), std::move(topics));
}

/// `[TimeoutCheck(topic)]` as the generator writes it.
inline std::unique_ptr<ICondition> TimeoutCheck(std::string topic) {
  return std::make_unique<TimeoutCondition>(std::move(topic));
}

/// An action that logs a text.
class LogAction : public IAction {
 public:
  LogAction(Log* log, std::string text) : log_(log), text_(std::move(text)) {}
  void Execute() override { log_->Add(text_); }

 private:
  Log* log_;
  std::string text_;
};

inline std::unique_ptr<IAction> Logs(Log* log, std::string text) {
  return std::make_unique<LogAction>(log, std::move(text));
}

/// An activity that counts its runs and may log them.
class CountingActivity : public IActivity {
 public:
  explicit CountingActivity(std::shared_ptr<std::atomic<int>> runs, Log* log = nullptr,
                            std::string name = "Counting")
      : runs_(std::move(runs)), log_(log), name_(std::move(name)) {}
  int Execute() override {
    ++*runs_;
    if (log_ != nullptr) log_->Add("run " + name_);
    return 0;
  }
  std::string GetName() override { return name_; }

 private:
  std::shared_ptr<std::atomic<int>> runs_;
  Log* log_;
  std::string name_;
};

/// A gate activities can wait on (bounded, so a broken test cannot hang).
class Gate {
 public:
  void Open() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      open_ = true;
    }
    cv_.notify_all();
  }
  bool Wait(std::chrono::milliseconds limit = std::chrono::milliseconds(5000)) {
    std::unique_lock<std::mutex> lock(mutex_);
    return cv_.wait_for(lock, limit, [this] { return open_; });
  }

 private:
  std::mutex mutex_;
  std::condition_variable cv_;
  bool open_ = false;
};

/// An activity that signals it started, then waits for a gate.
class BlockingActivity : public IActivity {
 public:
  BlockingActivity(std::shared_ptr<Gate> gate, std::shared_ptr<std::atomic<int>> started)
      : gate_(std::move(gate)), started_(std::move(started)) {}
  int Execute() override {
    ++*started_;
    gate_->Wait();
    return 0;
  }
  std::string GetName() override { return "Blocking"; }

 private:
  std::shared_ptr<Gate> gate_;
  std::shared_ptr<std::atomic<int>> started_;
};

/// An activity that sleeps for a while.
class SleepingActivity : public IActivity {
 public:
  explicit SleepingActivity(std::chrono::milliseconds duration,
                            std::shared_ptr<std::atomic<int>> finished)
      : duration_(duration), finished_(std::move(finished)) {}
  int Execute() override {
    std::this_thread::sleep_for(duration_);
    ++*finished_;
    return 0;
  }
  std::string GetName() override { return "Sleeping"; }

 private:
  std::chrono::milliseconds duration_;
  std::shared_ptr<std::atomic<int>> finished_;
};

/// An activity that throws.
class ThrowingActivity : public IActivity {
 public:
  int Execute() override { throw std::runtime_error("activity failure for the test"); }
  std::string GetName() override { return "Throwing"; }
};

/// Polls a predicate until it holds or the limit passes.
template <class Pred>
bool WaitUntil(Pred pred, std::chrono::milliseconds limit = std::chrono::milliseconds(3000)) {
  const auto end = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < end) {
    if (pred()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return pred();
}

inline bool HasState(const std::vector<std::string>& names, const std::string& name) {
  for (const auto& n : names) {
    if (n == name) return true;
  }
  return false;
}

inline Options Inline() {
  Options options;
  options.inline_activities = true;
  return options;
}

inline Options Pooled(std::size_t threads = 2) {
  Options options;
  options.inline_activities = false;
  options.worker_threads = threads;
  return options;
}

}  // namespace kse_test

#endif
