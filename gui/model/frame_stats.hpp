#pragma once
// Rolling frame-time statistics fed from glfwGetTime() deltas (seconds in, milliseconds out).
#include <cstddef>
#include <vector>

#include "fieldlines/train/percentile.hpp"

namespace fieldlines::studio {

class FrameStats {
 public:
  explicit FrameStats(std::size_t capacity = 240) : capacity_(capacity ? capacity : 1) {}
  void add(double seconds);
  std::size_t size() const { return samples_.size(); }
  double last_ms() const { return last_ * 1000; }
  double median_ms() const;  // 0 when empty
  // Samples in arrival order (oldest first) for a plot, in milliseconds.
  std::vector<float> history_ms() const;

 private:
  std::size_t capacity_;
  std::size_t next_ = 0;
  double last_ = 0;
  std::vector<double> samples_;
};

using fieldlines::median;  // 0 when empty; mean of the two middles when even

}  // namespace fieldlines::studio
