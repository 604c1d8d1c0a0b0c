#include "box_downsample.hpp"

#include <cstdint>

namespace fieldlines {
namespace {

// One output row: each byte the rounded mean of its cell's F x F bytes of the same channel.
// F known at compile time for the scales the detector uses, so the loops unroll.
template <int F>
void cells_of_row(const cv::Mat& band, int y, int w, std::uint8_t* out) {
  constexpr int kCell = F * F;
  const std::uint8_t* rows[F];
  for (int dy = 0; dy < F; ++dy) rows[dy] = band.ptr<std::uint8_t>(y * F + dy);
  for (int x = 0; x < w; ++x) {
    const int base = 3 * F * x;
    for (int c = 0; c < 3; ++c) {
      int sum = kCell / 2;
      for (int dy = 0; dy < F; ++dy)
        for (int dx = 0; dx < F; ++dx) sum += rows[dy][base + 3 * dx + c];
      out[3 * x + c] = static_cast<std::uint8_t>(sum / kCell);
    }
  }
}

void cells_of_row(const cv::Mat& band, int f, int y, int w, std::uint8_t* out) {
  const int cell = f * f;
  for (int x = 0; x < w; ++x)
    for (int c = 0; c < 3; ++c) {
      int sum = cell / 2;
      for (int dy = 0; dy < f; ++dy) {
        const std::uint8_t* p = band.ptr<std::uint8_t>(y * f + dy) + 3 * f * x + c;
        for (int dx = 0; dx < f; ++dx) sum += p[3 * dx];
      }
      out[3 * x + c] = static_cast<std::uint8_t>(sum / cell);
    }
}

}  // namespace

void box_downsample(const cv::Mat& band, int f, cv::Mat& out) {
  const int w = band.cols / f, h = band.rows / f;
  out.create(h, w, CV_8UC3);  // no allocation when the size is the last frame's
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    switch (f) {
      case 2: cells_of_row<2>(band, y, w, o); break;
      case 3: cells_of_row<3>(band, y, w, o); break;
      case 4: cells_of_row<4>(band, y, w, o); break;
      default: cells_of_row(band, f, y, w, o);
    }
  }
}

}  // namespace fieldlines
