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
// Units: gradients are the detector's, Sobel |dx| + |dy| of the smoothed grey image.
#include <cstddef>
#include <vector>

#include <nlohmann/json.hpp>
#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/detector_params.hpp"

namespace fieldlines {

struct DetectorCalibrationParams {
  int gaussian_kernel = 5;          // ELSED's defaults: the recall ceiling rises (see the header)
  int scan_interval = 2;
  int min_line_length = 25;
  double texture_percentile = 90;   // of the gradient on a frame's green pixels: its turf texture
  double paint_percentile = 99.5;   // of the same: its strongest edges, the paint's
  double paint_share = 0.25;        // the threshold keeps edges of this share of the paint's contrast
  double texture_margin = 1.5;      // and stays this far above the turf's texture
  int min_gradient_threshold = 8;   // below: sensor noise on any field
  bool follow_contrast = false;     // the threshold from the contrast, below: measured mixed
};

// The field's contrast per frame: percentiles of the gradient on its green pixels
// (field_green.hpp), smoothed as the calibrated detector will smooth.
class FieldContrast {
 public:
  explicit FieldContrast(const DetectorCalibrationParams& params = {}, double gaussian_sigma = 1.0);
  // A frame without green pixels (no field in view) adds nothing.
  void add_image(const cv::Mat& bgr);
  std::size_t frames() const { return texture_.size(); }
  double texture() const;  // medians over the frames; 0 when none showed a field
  double paint() const;

 private:
  DetectorCalibrationParams params_;
  double sigma_;
  std::vector<double> texture_, paint_;
  cv::Mat grey_, smooth_, dx_, dy_;
};

// `given` with the anchor grid, minimum length and smoothing of `params` and the stripes stage
// on: the choice below when a frame showed a field and follow_contrast is off.
DetectorParams field_detector(const DetectorParams& given, const DetectorCalibrationParams& params = {});

// field_detector(given, params); with follow_contrast, the gradient threshold from `contrast`: paint_share of the paint's
// contrast, at least texture_margin times the turf's texture, never above the given threshold.
// Without a frame that showed a field, `given` unchanged.
DetectorParams calibrated_detector(const DetectorParams& given, const FieldContrast& contrast,
                                   const DetectorCalibrationParams& params = {});

// The parameters to detect calibration frames with: `chosen` without the stages that only
// relabel (stripes, and what builds on them), which the fit, reading no label, does not need.
DetectorParams for_fitting(DetectorParams chosen);

// What the thresholds file's provenance records of it: the measured contrasts and the choice.
nlohmann::json detector_provenance(const FieldContrast& contrast, const DetectorParams& chosen, bool calibrated);

}  // namespace fieldlines
