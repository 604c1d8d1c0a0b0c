#include "gui/model/frame_stats.hpp"

#include <algorithm>

namespace fieldlines::studio {

void FrameStats::add(double seconds) {
  last_ = seconds;
  if (samples_.size() < capacity_) {
    samples_.push_back(seconds);
  } else {
    samples_[next_] = seconds;
  }
  next_ = (next_ + 1) % capacity_;
}

double FrameStats::median_ms() const { return median(samples_) * 1000; }

std::vector<float> FrameStats::history_ms() const {
  std::vector<float> out;
  out.reserve(samples_.size());
  const std::size_t start = samples_.size() < capacity_ ? 0 : next_;
  for (std::size_t i = 0; i < samples_.size(); ++i) {
    out.push_back(static_cast<float>(samples_[(start + i) % samples_.size()] * 1000));
  }
  return out;
}

}  // namespace fieldlines::studio
