#pragma once
// Per-segment classifier features computed once (structure of arrays), so that scoring a
// threshold set is one tight, vectorisable loop with no square roots or acos.
#include <cstdint>
#include <span>
#include <vector>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/train/metrics.hpp"

namespace fieldlines {

// Per segment, parallel to the segments given (each empty: every one may): may the robot's
// detector call it a marking, a boundary edge, whatever its colours (its stripes check, its
// field boundary gate)? A segment it may not be is never predicted that class: training then
// scores what the robot will do, and a none the detector drops anyway does not shrink the box.
struct LabelledCandidates {
  std::span<const std::uint8_t> marking, boundary;
};

class FeatureTable {
 public:
  // `segments[i].label` is the human label (Unlabelled rows are skipped). The colour classes,
  // gradient mode and pi convention of `base` fix the features; its thresholds are not used.
  // Throws fieldlines::Error when a non-empty candidates span is not parallel to `segments`.
  FeatureTable(std::span<const Segment> segments, const Thresholds& base, const LabelledCandidates& candidates = {});
  FeatureTable() = default;

  std::size_t size() const { return length.size(); }
  // Same counts as evaluate()/classify() on the original segments, for any thresholds that
  // share `base`'s colour classes and mode.
  Counts count(const ClassThresholds& boundary, const ClassThresholds& marking) const;

  // The rows that `boundary` does NOT classify as boundary, keeping the full table's positive
  // counts: training the marking class with fixed boundary thresholds then skips rows whose
  // prediction can never change (count() must then be given a boundary that never passes).
  FeatureTable without_boundary_hits(const ClassThresholds& boundary) const;

  // Features (marking_proj[1] / marking_angle[1] are the grad_x test of GradientMode::Axes;
  // set so that they never pass in Normal mode).
  std::vector<float> length, boundary_proj, boundary_angle;
  std::vector<float> marking_proj[2], marking_angle[2];
  std::vector<Label> truth;
  std::vector<std::int32_t> is_marking, is_boundary;  // 0/1 copies of truth: keep the loop 32-bit wide
  long positives_marking = 0, positives_boundary = 0;
};

}  // namespace fieldlines
