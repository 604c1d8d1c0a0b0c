#pragma once
// `fieldlines eval --draw`: one frame's detections against its truth, for a person to see which
// painted lines the detector misses and where the classification drops them.
#include <span>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/synth/gt_eval.hpp"

namespace fieldlines::cli {

// Over detect --draw's picture (the segments in the palette, faint above the detected field
// boundary, which is dashed white): every visible truth edge dotted (palette::kTruthFound where
// recall counts it, kTruthLost where only a segment of another label lies on it, kMissedPaint
// where none does), the hand-drawn field boundary (`hand_boundary_rows`: one row per column, -1
// where none; empty for synthetic truth) as a solid line in kTruthFound, and a legend
// bottom-left with each share of the edges' length.
cv::Mat draw_eval_overlay(const cv::Mat& image, std::span<const Segment> segments, const FieldBoundary& boundary,
                          const GtEdges& truth, std::span<const float> hand_boundary_rows);

}  // namespace fieldlines::cli
