#include "fieldlines/train/frame_lines.hpp"

#include <utility>

#include "fieldlines/data/image_io.hpp"

namespace fieldlines {
namespace {

DetectorParams with_stripes(DetectorParams params) {
  params.stripes = true;
  return params;
}

}  // namespace

FrameLinesDetector::FrameLinesDetector(DetectorParams params, const Thresholds& thresholds)
    : detector_(with_stripes(std::move(params)), thresholds) {}

FrameLines FrameLinesDetector::detect(const std::filesystem::path& image) {
  const cv::Mat frame = load_image(image);
  detector_.detect(frame, segments_);
  return {detector_.features().markings, frame.cols, frame.rows, image.filename().string()};
}

}  // namespace fieldlines
