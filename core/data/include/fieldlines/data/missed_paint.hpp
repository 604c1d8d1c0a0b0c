#pragma once
// Line paint the detector found no segment for: bright, colourless pixels on turf that lie
// away from every segment. ELSED misses parts of tight curves (the centre circle at a distance)
// and faint or worn lines; those have nothing to label, so the studio shows them instead, and a
// user sees where to lower the detector's thresholds or accept that the robot will miss them.
#include <cstddef>
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct MissedPaintParams {
  int window = 31;              // box (odd, px) over which the local turf is measured
  int max_line_width = 15;      // px: brighter structures wider than this are not paint
  int min_contrast = 40;        // paint: darkest channel this far above its surroundings
  int green_margin = 8;         // turf: the box's mean green exceeds its mean red and blue by this
  float segment_radius = 8;     // pixels this close to a segment are explained by it
  int min_blob = 25;            // leftovers smaller than this (px) are noise, not a line
};

struct MissedPaint {
  cv::Mat mask;  // CV_8U, 255 where paint has no segment, the image's size
  std::size_t pixels = 0, blobs = 0;
};

// `bgr`: 8-bit BGR. Throws fieldlines::Error on another type or invalid params.
MissedPaint find_missed_paint(const cv::Mat& bgr, std::span<const Segment> segments,
                              const MissedPaintParams& params = {});

}  // namespace fieldlines
