#ifndef KSE_MESSAGING_RECYCLED_H
#define KSE_MESSAGING_RECYCLED_H

#include <atomic>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace kse::messaging {

/// The messages of one class that a publisher makes again and again (a robot's WorldInfo every
/// cycle, an activity's walk command every run), each used again once the publisher's reference
/// is the only one left: the blackboards that showed it have let it go (a Data history keeps the
/// last 100 entries, a signal queue up to 1,000 unread signals) and nobody else kept it. A new
/// message costs allocations (the message, its strings and arrays) and, a thousand publishes
/// later, as many frees of memory long out of the caches; one used again costs neither.
///
/// A message someone keeps stays theirs: when `limit` messages are out and the oldest is still
/// held, it is left to its holders and a new one made. Not thread-safe itself (one publisher
/// owns it); the messages it hands out may be read and let go on any thread.
template <class T>
class Recycled {
 public:
  explicit Recycled(std::size_t limit) : limit_(limit < 1 ? 1 : limit) {}
  Recycled(const Recycled&) = delete;
  Recycled& operator=(const Recycled&) = delete;

  /// A message to fill and publish: the oldest one given before, as it was then (set every field
  /// the publisher ever sets, or Clear() it first), once nobody else holds it; else a new one.
  T& Next() {
    if (size_ > 0 && ring_[head_].use_count() == 1) {
      // use_count() is a relaxed load: the fence orders whatever the last other owner did with
      // the message before it let go (a release, in the count) before our writes. ThreadSanitizer
      // does not model fences and would report them; its runs publish on one thread.
#ifndef __SANITIZE_THREAD__
      std::atomic_thread_fence(std::memory_order_acquire);
#endif
      std::shared_ptr<T> oldest = std::move(ring_[head_]);
      head_ = Index(1);
      ring_[Index(size_ - 1)] = std::move(oldest);  // the newest now
    } else {
      if (size_ == ring_.size()) {
        if (ring_.size() < limit_) {
          Grow();
        } else {
          ring_[head_].reset();  // the oldest stays with whoever holds it
          head_ = Index(1);
          --size_;
        }
      }
      ring_[Index(size_)] = std::make_shared<T>();
      ++size_;
    }
    return *ring_[Index(size_ - 1)];
  }

  /// The message Next() gave, to publish.
  const std::shared_ptr<T>& Last() const { return ring_[Index(size_ - 1)]; }

  /// Messages made and not let go of.
  std::size_t Size() const noexcept { return size_; }

 private:
  std::size_t Index(std::size_t i) const noexcept {  // i < the capacity
    const std::size_t at = head_ + i;
    return at < ring_.size() ? at : at - ring_.size();
  }

  // The storage grows as messages stay out (twice as large, up to the limit), oldest first.
  void Grow() {
    std::size_t capacity = ring_.empty() ? 4 : 2 * ring_.size();
    if (capacity > limit_) capacity = limit_;
    std::vector<std::shared_ptr<T>> ring(capacity);
    for (std::size_t i = 0; i < size_; ++i) ring[i] = std::move(ring_[Index(i)]);
    ring_.swap(ring);
    head_ = 0;
  }

  std::vector<std::shared_ptr<T>> ring_;
  std::size_t head_ = 0;  // the oldest
  std::size_t size_ = 0;
  std::size_t limit_;
};

}  // namespace kse::messaging

#endif
