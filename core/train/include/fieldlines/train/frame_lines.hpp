#pragma once
// One frame's painted lines as fit_camera (camera_fit.hpp) takes them: the detector's stripes
// (the lines' centre lines) with the stripes stage on whatever the parameters say, the image
// size and its file name. `fieldlines calibrate-camera` and the studio's Camera tab detect their
// frames through this one detector, so both fit the same lines.
#include <filesystem>
#include <vector>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/train/camera_fit.hpp"

namespace fieldlines {

class FrameLinesDetector {
 public:
  // `params` with stripes on; throws fieldlines::Error when they fail validate().
  FrameLinesDetector(DetectorParams params, const Thresholds& thresholds);
  // Loads and detects `image`; throws fieldlines::Error naming it when it cannot be read.
  FrameLines detect(const std::filesystem::path& image);

 private:
  LineDetector detector_;
  std::vector<Segment> segments_;  // reused from frame to frame
};

}  // namespace fieldlines
