#pragma once
// What a label-free calibration is fitted on: the segments of many frames and, for frames given
// as images, each frame's field colour, so that every face (CLI, Python, studio) maps the frames
// onto one exposure the same way before the fit and the robot then does it per frame
// (fieldlines/detect/light.hpp).
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

class CalibrationInputs {
 public:
  // Detects `image` with raw gradients (any light adaptation of the detector's thresholds off:
  // the frames' light is what is measured) and keeps its segments and field colour.
  void add_image(LineDetector& detector, const cv::Mat& image);
  // Segments without an image (a project or reference CSV): no field colour, never rescaled.
  void add_segments(std::span<const Segment> segments);

  // Scales each imaged frame's segments onto the median field colour of those frames and
  // returns `start` with light adaptation on at that reference; `start` with it off when no
  // frame showed a field. Call once, after the last add.
  Thresholds adapt_light(Thresholds start);

  const std::vector<Segment>& segments() const { return segments_; }
  std::size_t frames() const { return frames_; }                         // every add_image
  std::size_t frames_with_field() const { return fields_.size(); }

 private:
  struct Field {
    std::size_t begin, end;  // the frame's segments
    Rgb colour;
  };
  std::vector<Segment> segments_, found_;
  std::vector<Field> fields_;
  std::size_t frames_ = 0;
};

}  // namespace fieldlines
