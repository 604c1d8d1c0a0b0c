#pragma once
// The studio's "paint with no segment" view: the current image with the paint the detector
// missed (fieldlines/data/missed_paint.hpp) tinted cyan, recomputed only when the image or its
// segments change, so toggling it on costs one computation, not one per frame.
#include <cstddef>
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/data/missed_paint.hpp"

namespace fieldlines::studio {

class MissedPaintView {
 public:
  // `generation`: StudioController::image_generation(). Returns true when the result changed
  // (the caller re-uploads its texture). An empty or unusable image gives an empty view.
  bool update(const cv::Mat& bgr, std::span<const Segment> segments, std::size_t generation);
  const cv::Mat& tinted() const { return tinted_; }  // 8-bit BGR, the image's size
  const MissedPaint& found() const { return found_; }

 private:
  std::size_t generation_ = static_cast<std::size_t>(-1);
  const Segment* segments_data_ = nullptr;
  std::size_t segments_size_ = 0;
  MissedPaint found_;
  cv::Mat tinted_;
};

}  // namespace fieldlines::studio
