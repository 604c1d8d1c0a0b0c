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
  // > 0: the segment runs along a thin line's centre (ridge_pass.hpp), and its colours are the
  // line's: per channel, each pixel against the mean of the two pixels ridge_reach + 1 px to
  // either side across the segment, averaged, along the segment's normal (pointing down, or
  // right when it stands upright). So a thin line's segment carries the colour transition from
  // turf to paint, which the colour classes test as they test an edge's. (Tried: dropping lines
  // whose two sides differ, a wall's foot, or that still fall past them, a wide line's soft
  // middle: no venue's figures changed, or precision fell; docs/detector.md.)
  int ridge_reach = 0;
};

// A caller's test of a segment's endpoints and colour gradients (saliency 0): false drops it.
struct SegmentFilter {
  bool (*test)(const void* context, const Segment& segment) = nullptr;  // null: keep every one
  const void* context = nullptr;
};

// Checks a drawn segment: it is kept when more of its inlier pixels (ends trimmed) have a
// gradient orientation within the threshold of its normal than not. While visiting them, the
// 3x3 BGR windows around those pixels are summed; the mean window is Sobel-filtered once (a
// thin line's segment: its colours as ValidationParams::ridge_reach says).
// Fills `out` (endpoints, saliency, gradients; label untouched) and returns whether it is valid.
// With a `keep` test, the windows are summed first and a segment it drops is not validated
// (false); the segments it keeps come out as without it.
bool validate_segment(const LineModel& seg, const std::vector<Pixel>& chain, const GradientMaps& maps,
                      const cv::Mat& bgr, const ValidationParams& params, Segment& out, SegmentFilter keep = {});

}  // namespace fieldlines::elsed

#pragma GCC visibility pop
