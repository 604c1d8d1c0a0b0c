#pragma once
// Private: the ELSED pipeline (smoothing, gradients, anchors, drawing, validation) with the
// method's colour-gradient extraction. Owns every buffer so repeated calls do not allocate.
#include <vector>

#include <opencv2/core/mat.hpp>

#include "edge_drawer.hpp"
#include "elsed_types.hpp"
#include "fieldlines/detect/detector.hpp"

namespace fieldlines {

class ElsedEngine {
 public:
  // bgr: 8-bit, 3 channels, at least 3x3. Appends unclassified segments to `out`.
  void run(const cv::Mat& bgr, const DetectorParams& params, std::vector<Segment>& out);

 private:
  void compute_gradients(const DetectorParams& params);
  void find_anchors(int scan_interval, int threshold);

  cv::Mat gray_, blurred_, dx_mat_, dy_mat_;
  elsed::GradientMaps maps_;
  std::vector<elsed::Mark> marks_;
  std::vector<elsed::Pixel> anchors_;
  elsed::EdgeDrawer drawer_;
};

}  // namespace fieldlines
