#pragma once
// ELSED line segments with per-segment colour gradients, classified as field features.
//
// Usage (OpenCV style):  fieldlines::LineDetector det;  auto segs = det.detect(bgr);
// A LineDetector owns its working buffers and reuses them between calls, so keep one per thread.
// Once it has seen a frame as large as the current one, detect(image, out) allocates nothing
// for 8-bit BGR input (tests/detect_allocation_test.cpp counts every heap call).

#include <memory>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/segment.hpp"

namespace fieldlines {

struct DetectorParams {
  // Defaults are the configuration the method's authors ran (reference/README.md).
  int gaussian_kernel = 7;           // odd kernel size; < 3 disables smoothing
  double gaussian_sigma = 1.0;
  int gradient_threshold = 30;       // L1 Sobel magnitude below this is no edge
  int anchor_threshold = 8;          // anchor must exceed its neighbours by this much
  int scan_interval = 10;            // anchors are looked for every k-th row and column
  int min_line_length = 40;          // pixels before a line is fitted
  double line_fit_error = 0.2;       // max mean squared fit error to accept a line
  double px_to_segment_dist = 1.5;   // max distance of an inlier pixel to the line
  double validation_threshold = 0.15;// max gradient-orientation error (rad) of a valid pixel
  bool validate = true;              // false: keep every drawn segment, saliency = length
  bool treat_junctions = true;       // jump over discontinuities along the line
  std::vector<int> junction_sizes{5, 7, 9};
  // Threads for the gradient pass, which then runs in row bands (frames too short for bands of
  // a useful height keep one). Speed only: the results are the same bits for any count, so it
  // is not written into thresholds or project files. Workers start on the first detect.
  int threads = 1;
  bool operator==(const DetectorParams&) const = default;
};

// Validates ranges; throws fieldlines::Error naming the bad field.
void validate(const DetectorParams& params);

class LineDetector {
 public:
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
  const Thresholds& thresholds() const { return thresholds_; }
  void set_thresholds(const Thresholds& t) { thresholds_ = t; }

 private:
  struct Impl;
  const cv::Mat* normalise(const cv::Mat& image);  // to 8-bit BGR; nullptr if smaller than 3x3
  DetectorParams params_;
  Thresholds thresholds_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fieldlines
