#pragma once
// ELSED line segments with per-segment colour gradients, classified as field features.
//
// Usage (OpenCV style):  fieldlines::LineDetector det;  auto segs = det.detect(bgr);
// A LineDetector owns its working buffers and reuses them between calls, so keep one per thread.
// Once it has seen a frame as large as the current one, detect(image, out) allocates nothing
// for 8-bit BGR input (tests/detect_allocation_test.cpp counts every heap call).

#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/field_boundary.hpp"
#include "fieldlines/detect/field_features.hpp"
#include "fieldlines/detect/ground_camera.hpp"
#include "fieldlines/detect/ground_features.hpp"
#include "fieldlines/detect/segment.hpp"
#include "fieldlines/detect/turf_colours.hpp"

namespace fieldlines {

class LineDetector {
 public:
  // Throws fieldlines::Error when `params` fail validate() (detector_params.hpp).
  explicit LineDetector(DetectorParams params = {}, Thresholds thresholds = {});
  ~LineDetector();
  LineDetector(LineDetector&&) noexcept;
  LineDetector& operator=(LineDetector&&) noexcept;

  // Accepts 8-bit or 16-bit, 1-, 3- (BGR) or 4-channel (BGRA) images. Images smaller than 3x3
  // give no segments. Throws fieldlines::Error on an empty image or an unsupported depth.
  std::vector<Segment> detect(const cv::Mat& image);
  // Same, writing into `out` (cleared first) so a caller's vector keeps its capacity.
  void detect(const cv::Mat& image, std::vector<Segment>& out);

  // The first stage alone, as detect() runs it: grey, Gaussian, Sobel x/y, |dx| + |dy| (zero
  // below gradient_threshold). For benchmarks (the "gradients only" row) and tests. The views
  // (CV_16SC1, no copy) stay valid until the next call on this detector. Same inputs as detect();
  // an image smaller than 3x3 gives empty views.
  struct GradientViews {
    cv::Mat dx, dy, magnitude;
  };
  GradientViews compute_gradients(const cv::Mat& image);

  const DetectorParams& params() const { return params_; }
  // Throws fieldlines::Error when `params` fail validate(), keeping the ones it had.
  void set_params(const DetectorParams& params);
  const Thresholds& thresholds() const { return thresholds_; }
  void set_thresholds(const Thresholds& t) { thresholds_ = t; }

  // The field boundary of the last detect() (field_boundary.hpp): found when asked for here,
  // when the thresholds keep markings below it, or when junctions or the centre circle are on
  // (their pieces are drawn below it); empty otherwise, or when the frame has no field.
  void set_find_field_boundary(bool on) { find_boundary_ = on; }
  const FieldBoundary& field_boundary() const;
  // The field colour of the last detect() (light.hpp), measured once when the light adaptation,
  // the field boundary or the stripes needed it; empty otherwise, or when the frame shows no field.
  const std::optional<Rgb>& field_colour() const;
  // What the stripes tested turf against: that colour, with the frame's turf colours when
  // DetectorParams::stripe_turf_colours is on. Valid until the next detect().
  FieldColours stripe_colours() const;
  // The field features of the last detect() (field_features.hpp): the stripes' centre lines
  // when DetectorParams::stripes is on (stripes.hpp), the junctions when intersections is on
  // (intersections.hpp), the field boundary as field_boundary() has it; empty otherwise.
  const FieldFeatures& features() const;
  // Where the last detect()'s segments along lines' centres begin (the thin-line pass's and its
  // far lines along the field boundary come last): those from this index on are no edge of the
  // field, so never a boundary; the segments' count when there are none.
  std::size_t centre_lines_from() const { return centre_lines_from_; }

  // The camera over the field for the next detect() calls (ground_camera.hpp): with it, the
  // centre circle is also fitted on the turf as a circle of DetectorParams::centre_circle_radius,
  // which finds a circle the frame shows one arc of. Set it per frame when the pose changes (a
  // walking robot's); none (the default): image fits alone. Throws fieldlines::Error when it
  // fails validate().
  void set_camera(const std::optional<GroundCamera>& camera);
  const std::optional<GroundCamera>& camera() const { return camera_; }
  // The field features of the last detect() on the ground (ground_features.hpp), in metres,
  // when a camera is set; empty otherwise.
  const GroundFeatures& ground_features() const;
  // How the ground features weigh the camera's angle noise and how far they reach. Throws
  // fieldlines::Error when they fail validate().
  void set_ground_params(const GroundFeatureParams& params);
  const GroundFeatureParams& ground_params() const { return ground_params_; }

 private:
  struct Impl;
  const cv::Mat* normalise(const cv::Mat& image);  // to 8-bit BGR; nullptr if smaller than 3x3
  // Junctions and the circle; `segments`: the detector's own, labelled.
  void find_pieces(const cv::Mat& bgr, std::optional<float> gain, std::span<const Segment> segments);
  // The coarse pass of DetectorParams::coarse_scale: its segments where the full scale has none.
  void add_coarse(const cv::Mat& bgr, int gradient_threshold, std::vector<Segment>& out);
  // The thin-line pass of DetectorParams::thin_reach: its segments where no two edges are.
  void add_thin(const cv::Mat& bgr, std::vector<Segment>& out);
  // ...and its far lines along the field boundary (DetectorParams::thin_along_boundary).
  void add_along_boundary(const cv::Mat& bgr, int gradient_threshold, std::optional<float> gain,
                          std::vector<Segment>& out);
  DetectorParams params_;
  Thresholds thresholds_;
  bool find_boundary_ = false;
  std::size_t centre_lines_from_ = 0;
  std::optional<GroundCamera> camera_;
  GroundFeatureParams ground_params_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fieldlines
