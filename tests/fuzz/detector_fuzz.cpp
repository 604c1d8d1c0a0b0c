// Fuzzes LineDetector::detect with small images of any size, channel count and depth.
// Layout of the input: width, height, type selector, then pixel bytes (repeated to fill).
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <cstring>

#include <opencv2/core.hpp>

#include "fieldlines/detector.hpp"
#include "fieldlines/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  const int width = 1 + data[0] % 96, height = 1 + data[1] % 96;
  static const int kTypes[] = {CV_8UC1, CV_8UC3, CV_8UC4, CV_16UC1, CV_16UC3, CV_16UC4, CV_8UC2, CV_32FC3};
  const int type = kTypes[data[2] % 8];
  cv::Mat image(height, width, type);
  const std::uint8_t* pixels = data + 3;
  const std::size_t n = size - 3;
  auto* dst = image.ptr<std::uint8_t>();
  const std::size_t bytes = image.total() * image.elemSize();
  for (std::size_t i = 0; i < bytes; ++i) dst[i] = pixels[i % n];
  if (image.depth() == CV_32F) cv::patchNaNs(image, 0.0);
  static fieldlines::LineDetector detector;  // reused across inputs, as a robot would
  try {
    for (const fieldlines::Segment& s : detector.detect(image)) {
      // Every output must be finite and inside (or on) the image's extended bounds.
      if (!std::isfinite(s.x0) || !std::isfinite(s.saliency) || !std::isfinite(s.grad_x[0])) __builtin_trap();
    }
  } catch (const fieldlines::Error&) {
    // Unsupported types are reported, not crashed on.
  }
  return 0;
}
