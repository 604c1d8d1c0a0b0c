#pragma once
// Private: ELSED's segment validation with the method's colour-gradient extraction fused in.
#include <vector>

#include <opencv2/core/mat.hpp>

#include "elsed_types.hpp"
#include "fieldlines/detect/segment.hpp"
#include "line_model.hpp"

#pragma GCC visibility push(hidden)  // private to the library (see line_model.hpp)

namespace fieldlines::elsed {

// DetectorParams::validation_threshold and DetectorParams::validate.
struct ValidationParams {
  double max_angle_error = 0;  // radians between a pixel's gradient and the segment normal
  bool validate = false;       // false: keep every segment, saliency = Euclidean length
};

// Checks a drawn segment: it is kept when more of its inlier pixels (ends trimmed) have a
// gradient orientation within the threshold of its normal than not. While visiting them, the
// 3x3 BGR windows around those pixels are summed; the mean window is Sobel-filtered once.
// Fills `out` (endpoints, saliency, gradients; label untouched) and returns whether it is valid.
bool validate_segment(const LineModel& seg, const std::vector<Pixel>& chain, const GradientMaps& maps,
                      const cv::Mat& bgr, const ValidationParams& params, Segment& out);

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
