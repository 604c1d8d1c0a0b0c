#pragma once
// Hands results from a worker thread to the UI thread: the worker pushes, the UI drains once per
// frame, so the UI never waits on a worker and never sees a half-written result.
#include <deque>
#include <mutex>
#include <vector>

namespace fieldlines::studio {

template <typename T>
class MessageQueue {
 public:
  void push(T message) {
    const std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
  }
  // Everything queued so far, oldest first; leaves the queue empty.
  std::vector<T> drain() {
    std::deque<T> taken;
    {
      const std::lock_guard lock(mutex_);
      taken.swap(messages_);
    }
    return {std::make_move_iterator(taken.begin()), std::make_move_iterator(taken.end())};
  }

 private:
  std::mutex mutex_;
  std::deque<T> messages_;
};

}  // namespace fieldlines::studio
