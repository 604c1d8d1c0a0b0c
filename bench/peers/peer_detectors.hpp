#pragma once
// The detectors `fieldlines bench` and bench/detector_bench time against each other, each
// behind one call that takes the same 8-bit BGR image (grey conversion included in the call).
// A library of its own (fieldlines_peers) so both faces share one definition of every peer and
// the robot's library never links opencv_ximgproc.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"

namespace fieldlines::peers {

struct TimedDetector {
  std::string name;  // "fieldlines", "fieldlines+light", "fieldlines+stripes", "fieldlines+coarse",
                     // "fieldlines+junctions", "fieldlines+features", "fieldlines+ground",
                     // "edlines", "fld", "lsd",
                     // "gradients", "floor"
  std::string what;  // one line for tables and --help
  // Runs on a BGR image and returns the number of segments found. Owns its buffers and reuses
  // them between calls, so repeated calls measure the steady state.
  std::function<std::size_t(const cv::Mat& bgr)> run;
};

// In this order: ours (detect + classify), ours with the light adaptation, ours with the
// stripes, OpenCV's EdgeDrawing in EDLines mode (detectEdges +
// detectLines, default parameters), FastLineDetector and LSD (default parameters), our gradient
// stage alone (LineDetector::compute_gradients), and the floor every gradient-based detector
// pays: cvtColor + 5x5 Gaussian + Sobel x and y (16-bit).
std::vector<TimedDetector> make_timed_detectors(const DetectorParams& params = {},
                                                const Thresholds& thresholds = {});

}  // namespace fieldlines::peers
