#include "fieldlines/train/calibration_inputs.hpp"

#include "fieldlines/detect/light.hpp"
#include "fieldlines/train/percentile.hpp"

namespace fieldlines {

void CalibrationInputs::add_image(LineDetector& detector, const cv::Mat& image) {
  Thresholds raw = detector.thresholds();
  if (raw.light.enabled) {
    raw.light = {};
    detector.set_thresholds(raw);
  }
  detector.set_find_field_boundary(true);
  detector.detect(image, found_);
  ++frames_;
  // A segment along a line's centre (the thin-line pass's) is no edge of the field.
  const std::size_t centres = detector.centre_lines_from();
  if (const std::optional<Rgb>& field = detector.field_colour()) {
    const FieldBoundary& boundary = detector.field_boundary();
    std::size_t kept = 0;
    for (std::size_t i = 0; i < found_.size(); ++i) {
      const BoundaryPlace place = place_of(found_[i], boundary);
      if (place == BoundaryPlace::Above) continue;
      boundary_candidate_.push_back(place == BoundaryPlace::Along && i < centres);
      found_[kept++] = found_[i];
    }
    found_.resize(kept);
    fields_.push_back({segments_.size(), segments_.size() + found_.size(), *field});
  } else {
    for (std::size_t i = 0; i < found_.size(); ++i) boundary_candidate_.push_back(i < centres);
  }
  add_marking_candidates(image, detector.stripe_colours());
  segments_.insert(segments_.end(), found_.begin(), found_.end());
}

void CalibrationInputs::add_marking_candidates(const cv::Mat& image, const FieldColours& field) {
  // Unchecked (every segment may be a marking) where the robot would not check either: stripes
  // off, or a frame without a field or in another pixel format, where the check keeps nothing.
  if (!stripe_params_.stripes || !stripe_check_.run(image, field, found_, stripe_params_)) {
    marking_candidate_.insert(marking_candidate_.end(), found_.size(), 1);
    width_share_.insert(width_share_.end(), found_.size(), 0.f);
    return;
  }
  marking_candidate_.insert(marking_candidate_.end(), stripe_check_.flags().begin(), stripe_check_.flags().end());
  width_share_.insert(width_share_.end(), stripe_check_.width_shares().begin(), stripe_check_.width_shares().end());
}

void CalibrationInputs::add_segments(std::span<const Segment> segments) {
  segments_.insert(segments_.end(), segments.begin(), segments.end());
  boundary_candidate_.insert(boundary_candidate_.end(), segments.size(), 1);
  marking_candidate_.insert(marking_candidate_.end(), segments.size(), 1);
  width_share_.insert(width_share_.end(), segments.size(), 0.f);
}

Thresholds CalibrationInputs::image_settings(Thresholds start, bool light) {
  start.light = {};
  start.field_boundary_gate = !fields_.empty();
  if (fields_.empty() || !light) return start;
  Rgb reference{};
  for (int c = 0; c < 3; ++c) {
    std::vector<double> channel;
    for (const Field& f : fields_) channel.push_back(f.colour[c]);
    reference[c] = static_cast<float>(median(channel));
  }
  for (const Field& f : fields_)
    apply_light_gain(std::span(segments_).subspan(f.begin, f.end - f.begin), light_gain(reference, f.colour));
  start.light = {true, reference};
  return start;
}

}  // namespace fieldlines
