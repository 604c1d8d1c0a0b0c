#pragma once
// Drawing detected segments over their image, coloured by label, for a human to check.
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct OverlayParams {
  // BGR colours picked to stand out from green carpet, white lines and a dark wall.
  cv::Scalar marking_colour{255, 0, 255};    // magenta
  cv::Scalar boundary_colour{0, 140, 255};   // orange
  cv::Scalar none_colour{255, 160, 0};       // azure
  cv::Scalar unlabelled_colour{160, 160, 160};
  int thickness = 0;      // line width in pixels; 0 picks one from the image size (>= 1)
  bool endpoints = true;  // small dots at the endpoints show where segments split
  bool legend = true;     // label names and counts in the top-left corner (skipped if it won't fit)
};

cv::Scalar label_colour(Label label, const OverlayParams& params = {});

// Returns an 8-bit BGR copy of `image` (any type load_image accepts) with the segments drawn.
cv::Mat draw_overlay(const cv::Mat& image, std::span<const Segment> segments,
                     const OverlayParams& params = {});

}  // namespace fieldlines
