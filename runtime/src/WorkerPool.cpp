#include "WorkerPool.h"

#include <utility>

namespace statechart_engine::detail {

WorkerPool::WorkerPool(std::size_t threads) {
  if (threads == 0) {
    threads = 1;
  }
  ended_.assign(threads, false);
  threads_.reserve(threads);
  for (std::size_t i = 0; i < threads; ++i) {
    threads_.emplace_back([this, i] { Run(i); });
  }
}

WorkerPool::~WorkerPool() { Close(std::chrono::steady_clock::time_point::max()); }

std::size_t WorkerPool::Close(std::chrono::steady_clock::time_point deadline) {
  std::unique_lock<std::mutex> lock(mutex_);
  stopping_ = true;
  ready_.notify_all();
  auto all_ended = [this] {
    for (const bool ended : ended_) {
      if (!ended) return false;
    }
    return true;
  };
  if (deadline == std::chrono::steady_clock::time_point::max()) {
    ready_.wait(lock, all_ended);
  } else {
    ready_.wait_until(lock, deadline, all_ended);
  }
  std::size_t detached = 0;
  for (std::size_t i = 0; i < threads_.size(); ++i) {
    if (!threads_[i].joinable()) continue;
    if (ended_[i]) {
      threads_[i].join();  // it has left Run(): no lock needed, none taken
    } else {
      threads_[i].detach();
      ++detached;
    }
  }
  return detached;
}

void WorkerPool::Post(std::function<void()> task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    tasks_.push_back(std::move(task));
  }
  ready_.notify_one();
}

void WorkerPool::Run(std::size_t index) {
  for (;;) {
    std::function<void()> task;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return stopping_ || !tasks_.empty(); });
      if (tasks_.empty()) {
        ended_[index] = true;  // stopping and drained
        ready_.notify_all();
        return;
      }
      task = std::move(tasks_.front());
      tasks_.pop_front();
    }
    task();
  }
}

}  // namespace statechart_engine::detail
