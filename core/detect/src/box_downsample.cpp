#include "box_downsample.hpp"

#include "box_downsample_avx2.hpp"

#include <algorithm>
#include <array>
#include <cstdint>

namespace fieldlines {
namespace {

// One output row in steps that vectorise: the F rows of a chunk of output pixels summed byte by
// byte into 16-bit column sums (a cell's sum is at most 255 * F * F), then each with those of
// the next F - 1 pixels of its channel (3 bytes on), then each cell's total, at its first byte,
// divided and rounded. Summing a cell's F x F bytes for each output byte takes 1.6 times as long
// (a 640 x 240 band at F = 3). Chunks on the stack: no buffer to keep. Output pixels [from, w).
template <int F>
void cells_of_row(const cv::Mat& band, int y, int from, int w, std::uint8_t* out) {
  constexpr int kCell = F * F, kChunk = 64;  // output pixels per chunk
  std::array<std::uint16_t, 3 * F * kChunk> columns;
  std::array<std::uint16_t, 3 * F * kChunk> cells;
  const std::uint8_t* rows[F];
  for (int dy = 0; dy < F; ++dy) rows[dy] = band.ptr<std::uint8_t>(y * F + dy);
  for (int x0 = from; x0 < w; x0 += kChunk) {
    const int n = std::min(kChunk, w - x0), bytes = 3 * F * n;
    const std::uint8_t* first[F];
    for (int dy = 0; dy < F; ++dy) first[dy] = rows[dy] + 3 * F * x0;
    for (int i = 0; i < bytes; ++i) {
      unsigned sum = 0;
      for (int dy = 0; dy < F; ++dy) sum += first[dy][i];
      columns[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(sum);
    }
    for (int i = 0; i + 3 * (F - 1) < bytes; ++i) {
      unsigned sum = kCell / 2;
      for (int dx = 0; dx < F; ++dx) sum += columns[static_cast<std::size_t>(i + 3 * dx)];
      cells[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(sum);
    }
    const std::uint16_t* cell = cells.data();
    for (std::uint8_t* o = out + 3 * x0; o < out + 3 * (x0 + n); o += 3, cell += 3 * F) {
      o[0] = static_cast<std::uint8_t>(cell[0] / kCell);
      o[1] = static_cast<std::uint8_t>(cell[1] / kCell);
      o[2] = static_cast<std::uint8_t>(cell[2] / kCell);
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

void box_downsample(const cv::Mat& band, int f, cv::Mat& out, bool avx2) {
  const int w = band.cols / f, h = band.rows / f;
  out.create(h, w, CV_8UC3);  // no allocation when the size is the last frame's
  for (int y = 0; y < h; ++y) {
    std::uint8_t* o = out.ptr<std::uint8_t>(y);
    switch (f) {
      case 2: cells_of_row<2>(band, y, 0, w, o); break;
      case 3: {
        const auto row = [&](int dy) { return band.ptr<std::uint8_t>(3 * y + dy); };
        cells_of_row<3>(band, y, avx2 ? avx2::cells3_row(row(0), row(1), row(2), w, o) : 0, w, o);
        break;
      }
      case 4: cells_of_row<4>(band, y, 0, w, o); break;
      default: cells_of_row(band, f, y, w, o);
    }
  }
}

}  // namespace fieldlines
