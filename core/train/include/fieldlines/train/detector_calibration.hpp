#pragma once
// Detector parameters for a venue, from its pictures (the detector half of a label-free
// calibration; calibrate.hpp is the colour half).
//
// Why these, measured on the held-out venues (docs/calibration.md): with the method's detector
// (scan interval 10, minimum length 40) a half to three quarters of the line edges lie on any
// segment, so no thresholds can reach more; short arcs and far lines need ELSED's own anchor
// grid and smoothing (kernel 5, scan 2). The non-field pieces these let through are what the
// stripes stage (turf, paint, turf; stripes.hpp) removes, so it comes on with them; what it
// cannot remove is shortest, so the minimum length is 25 rather than ELSED's 15 (which lost
// 0.11 of marking precision on the SSL frames for no recall). The gradient threshold stays
// the given one by default: on every venue measured the contrast rule below gives it anyway (20
// or 30 scored the same, 50 lost recall), and on the same venues at a third of the exposure,
// where it lowers it, it won recall on one venue and lost 0.15 of precision on another
// (docs/calibration.md, "A dim field"). The field's contrast is measured and recorded either way.
//
// The stripes take their turf in every colour of the frame's own turf (stripe_turf_colours), as
// the field boundary does: on the held-out venues recall +0.019 to +0.041 on De Locht, Bordeaux
// and Humanoid, precision -0.017 on Bangkok (docs/calibration.md).
//
// The coarse pass (DetectorParams::coarse_scale) is chosen from the frames too: each frame is
// detected with and without it, every segment offered as a marking, and the length of the
// stripes (turf, paint, turf, below the field boundary) compared. Where wide near lines on
// textured turf break up at the full scale, the coarse pass adds a fifth or more to that length
// (Humanoid frames: 0.21, 0.26 on two halves); elsewhere less than a tenth (MSL 0.003-0.08, SSL
// 0), where it adds more clutter than lines
// (docs/detector.md, "The coarse pass").
//
// The thin-line pass (DetectorParams::thin_reach: far lines up to 3 px wide drawn along their
// centres) is on over the upper 0.6 of the frame unless the coarse pass is chosen: turf coarse
// enough for that pass fills the ridge maps with its blades, and on the Humanoid frames (the
// venue that chooses it) every figure held out is the same with the thin pass as without it,
// which cost a fifth more time on top of the coarse pass. Held out on the venues: marking recall
// +0.067 on Bangkok (0.696 -> 0.763) and +0.025 on SSL, the share of line edges on any segment
// +0.067 and +0.025; the others within 0.002, precision at most 0.008 lower (Bordeaux). Lines up
// to 5 px (reach 3) found more (Bangkok 0.779, SSL 0.801) but cost more: thin/fieldlines 1.29-1.42
// against 1.23-1.33 in the bench's worse order (target 1.25). Chosen per venue instead
// (on where the pass added stripes over the frames), the choice turned on a count of two to
// twelve stripes per half, and SSL's second half sat on the limit; the band's end from where
// those stripes lay swung from 0.25 to 0.46 between SSL's halves, while Bangkok's far lines need
// 0.6 (docs/detector.md, "The thin-line pass").
//
// Units: gradients are the detector's, Sobel |dx| + |dy| of the smoothed grey image.
#include <cstddef>
#include <memory>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/detector_params.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct DetectorCalibrationParams {
  int gaussian_kernel = 5;          // ELSED's defaults: the recall ceiling rises (see the header)
  int scan_interval = 2;
  int min_line_length = 25;
  bool stripe_turf_colours = true;  // the stripes' turf in every colour of the frame's own (see the header)
  double texture_percentile = 90;   // of the gradient on a frame's green pixels: its turf texture
  double paint_percentile = 99.5;   // of the same: its strongest edges, the paint's
  double paint_share = 0.25;        // the threshold keeps edges of this share of the paint's contrast
  double texture_margin = 1.5;      // and stays this far above the turf's texture
  int min_gradient_threshold = 8;   // below: sensor noise on any field
  bool follow_contrast = false;     // the threshold from the contrast, below: measured mixed
  int coarse_scale = 3;             // the coarse pass tried (3 recovered more than 2 on Humanoid)...
  double coarse_from = 0.5;         // ...from half the height down...
  // ...and above that from this share down, the lines it resolves (DetectorParams::
  // coarse_twins_from). Humanoid, held out: marking P / R 0.963 / 0.857 (none) -> 0.964 / 0.876
  // (0.4), 0.964 / 0.883 (0.3), 0.959 / 0.888 (0.2), 0.959 / 0.876 (0.1); the coarse pass's
  // cost 1.08 -> 1.12 of a plain detect at 0.3.
  double coarse_twins_from = 0.3;
  double min_coarse_gain = 0.2;     // ...and kept when it adds this share to the stripes' length
  int thin_reach = 2;               // the thin-line pass, on unless the coarse pass is (see the header)...
  double thin_to = 0.6;             // ...over the rows above this share of the height
};

// The field's contrast per frame: percentiles of the gradient on its green pixels
// (field_green.hpp), smoothed as the calibrated detector will smooth.
class LineDetector;

class FieldContrast {
 public:
  explicit FieldContrast(const DetectorCalibrationParams& params = {}, double gaussian_sigma = 1.0);
  // The same, and the coarse pass's gain measured with field_detector(given, params).
  FieldContrast(const DetectorCalibrationParams& params, const DetectorParams& given);
  ~FieldContrast();
  FieldContrast(FieldContrast&&) noexcept;
  FieldContrast& operator=(FieldContrast&&) noexcept;
  // A frame without green pixels (no field in view) adds nothing.
  void add_image(const cv::Mat& bgr);
  std::size_t frames() const { return texture_.size(); }
  double texture() const;  // medians over the frames; 0 when none showed a field
  double paint() const;
  // The stripes' length with the coarse pass over that without (at least 1 px), less 1, over all
  // frames; 0 when not measured (the first constructor) or no stripe was seen.
  double coarse_gain() const;

 private:
  DetectorCalibrationParams params_;
  double sigma_;
  std::vector<double> texture_, paint_;
  cv::Mat grey_, smooth_, dx_, dy_;
  std::unique_ptr<LineDetector> fine_, coarse_;  // both set, or neither
  std::vector<Segment> segments_;                 // their output, reused between frames
  double fine_px_ = 0, coarse_px_ = 0;
};

// `given` with the anchor grid, minimum length and smoothing of `params`, the stripes stage and
// the thin-line pass on: the choice below when a frame showed a field and follow_contrast is off.
DetectorParams field_detector(const DetectorParams& given, const DetectorCalibrationParams& params = {});

// field_detector(given, params), with the coarse pass where `contrast` measured it to add
// min_coarse_gain; with follow_contrast, the gradient threshold from `contrast`: paint_share of the paint's
// contrast, at least texture_margin times the turf's texture, never above the given threshold.
// Without a frame that showed a field, `given` unchanged.
DetectorParams calibrated_detector(const DetectorParams& given, const FieldContrast& contrast,
                                   const DetectorCalibrationParams& params = {});

// The parameters to detect calibration frames with: `chosen` without the stages that only
// relabel (stripes, and what builds on them), which the fit, reading no label, does not need.
DetectorParams for_fitting(DetectorParams chosen);

// What the thresholds file's provenance records of it: the measured contrasts and the choice,
// "calibrated" when some frame showed a field (calibrated_detector chose from them).
nlohmann::json detector_provenance(const FieldContrast& contrast, const DetectorParams& chosen);

}  // namespace fieldlines
