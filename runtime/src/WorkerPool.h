#ifndef KSE_RUNTIME_SRC_WORKER_POOL_H
#define KSE_RUNTIME_SRC_WORKER_POOL_H

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace statechart_engine::detail {

/// A fixed set of threads running posted tasks in FIFO order. Tasks must not throw.
/// The destructor runs the tasks still queued, then joins the threads.
class WorkerPool {
 public:
  explicit WorkerPool(std::size_t threads);
  ~WorkerPool();
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  void Post(std::function<void()> task);
  std::size_t Size() const noexcept { return threads_.size(); }
  /// Stops taking tasks and joins the threads that end by the deadline; the others (in a task
  /// that does not return) are detached, and the pool must then outlive them: never destroy
  /// it. Returns how many were detached.
  std::size_t Close(std::chrono::steady_clock::time_point deadline);

 private:
  void Run(std::size_t index);

  std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::function<void()>> tasks_;
  bool stopping_ = false;
  std::vector<bool> ended_;  // by thread
  std::vector<std::thread> threads_;
};

}  // namespace statechart_engine::detail

#endif
