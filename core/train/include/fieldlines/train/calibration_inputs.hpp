#pragma once
// What a label-free calibration is fitted on: the segments of many frames and, for frames given
// as images, each frame's field colour, so that every face (CLI, Python, studio) maps the frames
// onto one exposure the same way before the fit and the robot then does it per frame
// (fieldlines/detect/light.hpp).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/stripes.hpp"

namespace fieldlines {

class CalibrationInputs {
 public:
  // Detects `image` with raw gradients (turns the detector's light adaptation off, since the
  // frames' light is what is measured, and its field boundary on) and keeps the frame's field
  // colour and its segments, but for those above its field boundary: what is beside the field
  // says nothing about paint.
  void add_image(LineDetector& detector, const cv::Mat& image);
  // Segments without an image (a project or reference CSV): no field colour, never rescaled.
  void add_segments(std::span<const Segment> segments);
  // With `params.stripes` on, each imaged frame's segments are checked as stripes (stripes.hpp,
  // with these parameters) as they are added: the robot's detector drops every marking that is
  // none, so the marking class is fitted on the stripes alone. Off (the default): no check.
  void check_stripes(const DetectorParams& params) { stripe_params_ = params; }

  // What the images add to `start`, call once after the last add. Where frames showed a field:
  // the field boundary gate on (field_boundary.hpp) and, with `light`, each imaged
  // frame's segments scaled onto the median field colour of those frames with light
  // adaptation on at that reference (light.hpp). Both off when no frame showed a field.
  Thresholds image_settings(Thresholds start, bool light);

  const std::vector<Segment>& segments() const { return segments_; }
  // Per segment: may it be a boundary edge (along its frame's field boundary, or from an input
  // without an image)? calibrate() fits the boundary class on these alone.
  const std::vector<std::uint8_t>& boundary_candidates() const { return boundary_candidate_; }
  // Per segment: may it be a marking (a stripe, or not checked: no stripe check, no image, no
  // field in its frame)? calibrate() fits the marking class on these alone.
  const std::vector<std::uint8_t>& marking_candidates() const { return marking_candidate_; }
  // Per segment: its paint's width as a share of the stripes' width scale (width_share in
  // stripes.hpp) where the stripe check found a stripe, 0 elsewhere. stripe_width.hpp reads it.
  const std::vector<float>& width_shares() const { return width_share_; }
  std::size_t frames() const { return frames_; }                         // every add_image
  std::size_t frames_with_field() const { return fields_.size(); }

 private:
  struct Field {
    std::size_t begin, end;  // the frame's segments
    Rgb colour;
  };
  void add_marking_candidates(const cv::Mat& image, const FieldColours& field);

  std::vector<Segment> segments_, found_;
  std::vector<std::uint8_t> boundary_candidate_, marking_candidate_;
  std::vector<float> width_share_;
  DetectorParams stripe_params_;
  StripeCheck stripe_check_;
  std::vector<Field> fields_;
  std::size_t frames_ = 0;
};

}  // namespace fieldlines
