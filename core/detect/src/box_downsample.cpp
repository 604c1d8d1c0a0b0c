#include "box_downsample.hpp"

#include <array>
#include <cstdint>

namespace fieldlines {

void box_downsample(const cv::Mat& band, int f, cv::Mat& out) {
  const int w = band.cols / f, h = band.rows / f;
  out.create(h, w, CV_8UC3);  // no allocation when the size is the last frame's
  const int cell = f * f, half = cell / 2;
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      std::array<int, 3> sum{};
      for (int dy = 0; dy < f; ++dy) {
        const std::uint8_t* p = band.ptr<std::uint8_t>(y * f + dy) + 3 * x * f;
        for (int dx = 0; dx < 3 * f; dx += 3)
          for (std::size_t c = 0; c < 3; ++c) sum[c] += p[dx + static_cast<int>(c)];
      }
      for (std::size_t c = 0; c < 3; ++c) o[3 * x + static_cast<int>(c)] = static_cast<std::uint8_t>((sum[c] + half) / cell);
    }
  }
}

}  // namespace fieldlines
