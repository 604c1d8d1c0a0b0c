#include "gui/model/missed_paint_view.hpp"

#include "fieldlines/data/palette.hpp"

namespace fieldlines::studio {

bool MissedPaintView::update(const cv::Mat& bgr, std::span<const Segment> segments, std::size_t generation) {
  // Re-detection replaces the segment vector: its address and size tell that it changed.
  if (generation == generation_ && segments.data() == segments_data_ && segments.size() == segments_size_)
    return false;
  generation_ = generation;
  segments_data_ = segments.data();
  segments_size_ = segments.size();
  found_ = {};
  tinted_.release();
  if (bgr.empty() || bgr.type() != CV_8UC3) return true;
  found_ = find_missed_paint(bgr, segments);
  tinted_ = bgr.clone();
  constexpr palette::Rgb c = palette::kMissedPaint;
  tinted_.setTo(cv::Scalar(c.b, c.g, c.r), found_.mask);
  return true;
}

}  // namespace fieldlines::studio
