#include "ridge_pass.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/core/hal/intrin.hpp>

#include "ridge_rows_avx2.hpp"

namespace fieldlines::elsed {
namespace {

constexpr PixelState kVertical = with_mark(static_cast<PixelState>(EdgeDir::Vertical), Mark::Free);
constexpr PixelState kHorizontal = with_mark(static_cast<PixelState>(EdgeDir::Horizontal), Mark::Free);
static_assert(kVertical == 0 && kHorizontal == 1, "the AVX2 rows write the direction bit alone");

// Columns [x0, x1) of a row from 2 R + 1 rows of the smoothed grey (`rows[R]` the row itself),
// for lines up to 2 R - 1 px wide: the ridges across x and y in grey levels, 4 per level in the
// Sobel's units, dy's sign from the diagonals; every column written (zero below the threshold,
// the direction vertical when the ridge across x is the larger), the span listed.
template <int R>
void write_block(const std::uint8_t* const* rows, int x0, int x1, int threshold, const RidgeRow& out) {
  constexpr int D = kRidgeDiagonal<R>;
  const std::uint8_t* g = rows[R];
  for (int x = x0; x < x1; ++x) {
    const int c = g[x];
    int ax = 0, ay = 0, f = 0, r = 0;
    for (int d = 1; d <= R; ++d) {
      ax = std::max(ax, std::min(c - g[x - d], c - g[x + d]));
      ay = std::max(ay, std::min(c - rows[R - d][x], c - rows[R + d][x]));
    }
    for (int d = 1; d <= D; ++d) {
      f = std::max(f, std::min(c - rows[R - d][x - d], c - rows[R + d][x + d]));  // across (1, 1)
      r = std::max(r, std::min(c - rows[R - d][x + d], c - rows[R + d][x - d]));  // across (1, -1)
    }
    const int gx = 4 * ax, gy = 4 * ay, m = gx + gy;
    const bool kept = m >= threshold;
    out.dx[x] = static_cast<std::int16_t>(kept ? gx : 0);
    out.dy[x] = static_cast<std::int16_t>(kept ? (f >= r ? gy : -gy) : 0);
    out.mag[x] = static_cast<std::int16_t>(kept ? m : 0);
    out.state[x] = kept && gy > gx ? kHorizontal : kVertical;
  }
  out.blocks[(*out.block_count)++] = out.first + static_cast<std::uint32_t>(x0);
}

// The same for a whole row: blocks of columns tested at once in bytes; only a block with a pixel
// that may reach the threshold is written. That pixel's ridges sum to at least a quarter of it
// in grey levels (`least`; a byte sum saturated at 255 always may).
template <int R>
void ridge_row_r(const std::uint8_t* const* rows, int x0, int x1, int threshold, bool use_avx2, const RidgeRow& out) {
  const int least = std::min((threshold + 3) / 4, 255);
  int x = use_avx2 ? avx2::ridge_row(rows, R, x0, x1, threshold, least, out) : x0;
#if CV_SIMD128
  const cv::v_uint8x16 floor = cv::v_setall_u8(static_cast<std::uint8_t>(least));
  const auto block = [&](int b) {
    // The most over d of the lesser rise, c - max(side, other side), as c less the least such
    // max (uint8 operator- saturates: the clamp at zero).
    const auto at = [&](int row, int offset) { return cv::v_load(rows[R + row] + b + offset); };
    cv::v_uint8x16 sx = cv::v_max(at(0, -1), at(0, 1)), sy = cv::v_max(at(-1, 0), at(1, 0));
    for (int d = 2; d <= R; ++d) {
      sx = cv::v_min(sx, cv::v_max(at(0, -d), at(0, d)));
      sy = cv::v_min(sy, cv::v_max(at(-d, 0), at(d, 0)));
    }
    const cv::v_uint8x16 c = at(0, 0), ax = c - sx, ay = c - sy;
    if (cv::v_check_any((ax + ay) >= floor)) write_block<R>(rows, b, b + 16, threshold, out);
  };
  if (x < x1 && x1 - x0 >= 16) {
    for (; x + 16 <= x1; x += 16) block(x);
    if (x < x1) block(x1 - 16);  // the row's last columns, in a block overlapping the one before
    x = x1;
  }
#endif
  if (x < x1) write_block<R>(rows, x, x1, threshold, out);
}

using RowFn = void (*)(const std::uint8_t* const*, int, int, int, bool, const RidgeRow&);
constexpr RowFn kRows[kMaxRidgeReach] = {ridge_row_r<1>, ridge_row_r<2>, ridge_row_r<3>, ridge_row_r<4>,
                                         ridge_row_r<5>, ridge_row_r<6>, ridge_row_r<7>, ridge_row_r<8>};

}  // namespace

void ready_ridge_maps(int width, int rows, GradientMaps& maps, std::vector<RidgeBlocks>& blocks) {
  // Only the blocks the last frame wrote hold anything: cleared at that frame's width, the maps
  // are clean everywhere, and a frame of another size resizes them, clearing nothing else (a
  // camera's stream keeps its size; a set of frames of two sizes cleared all of both before).
  if (maps.width > 0) {
    const auto w = static_cast<std::size_t>(maps.width);
    for (const RidgeBlocks& band : blocks)
      for (std::size_t k = 0; k < band.count; ++k) {
        const std::size_t from = band.starts[k], to = std::min<std::size_t>(from + kRidgeBlock, (from / w + 1) * w);
        std::fill(maps.dx.begin() + from, maps.dx.begin() + to, 0);
        std::fill(maps.dy.begin() + from, maps.dy.begin() + to, 0);
        std::fill(maps.mag.begin() + from, maps.mag.begin() + to, 0);
        std::fill(maps.state.begin() + from, maps.state.begin() + to, kVertical);  // the drawing's marks too
      }
  }
  for (RidgeBlocks& band : blocks) band.count = 0;
  const std::size_t n = static_cast<std::size_t>(std::max(width, 0)) * static_cast<std::size_t>(std::max(rows, 0));
  maps.width = width, maps.height = rows;
  maps.dx.resize(n, 0);  // grown: the new pixels clean too
  maps.dy.resize(n, 0);
  maps.mag.resize(n, 0);
  maps.state.resize(n, kVertical);
}

void ridge_row(const std::uint8_t* const* rows, int width, const RidgeTarget& target, const RidgeRow& out) {
  if (width <= 2 * target.reach) return;  // columns within `reach` of the border get no ridge
  kRows[target.reach - 1](rows, target.reach, width - target.reach, target.threshold, target.use_avx2, out);
}

int ridge_anchor_lattice(int min_line_length, int scan_interval) {
  const double apart = static_cast<double>(min_line_length) / std::numbers::sqrt2;  // the lattice lines' most
  return std::max(1, static_cast<int>(std::lround(apart / static_cast<double>(std::max(scan_interval, 1)))));
}

int thin_min_length(int min_line_length) {
  return std::max(3, static_cast<int>(std::lround(kThinLengthShare * min_line_length)));
}

std::size_t max_ridge_blocks(int width, int rows) {
  return static_cast<std::size_t>(std::max(rows, 0)) * static_cast<std::size_t>(std::max(width, 0) / 16 + 2);
}

}  // namespace fieldlines::elsed
