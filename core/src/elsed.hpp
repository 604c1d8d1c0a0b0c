#pragma once
// Private: the ELSED pipeline (smoothing, gradients, anchors, drawing, validation) with the
// method's colour-gradient extraction. Owns every buffer so repeated calls do not allocate.
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detector.hpp"

namespace fieldlines {

class ElsedEngine {
 public:
  // bgr: 8-bit, 3 channels, at least 3x3. Appends unclassified segments to `out`.
  void run(const cv::Mat& bgr, const DetectorParams& params, std::vector<Segment>& out);

 private:
  cv::Mat gray_, blurred_;
};

}  // namespace fieldlines
