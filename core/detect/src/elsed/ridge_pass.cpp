#include "ridge_pass.hpp"

#include <algorithm>
#include <cstdlib>

#include <opencv2/core/hal/intrin.hpp>

#include "gradient_rows_avx2.hpp"
#include "ridge_rows_avx2.hpp"

namespace fieldlines::elsed {
namespace {

constexpr PixelState kVertical = with_mark(static_cast<PixelState>(EdgeDir::Vertical), Mark::Free);
constexpr PixelState kHorizontal = with_mark(static_cast<PixelState>(EdgeDir::Horizontal), Mark::Free);
static_assert(kVertical == 0 && kHorizontal == 1, "the AVX2 rows write the direction bit alone");

}  // namespace

namespace {

// Columns [x0, x1) of a row of the smoothed grey `g` (rows above and below at multiples of
// `stride`), for lines up to 2 R - 1 px wide: the ridges across x and y in grey levels, 4 per
// level in the Sobel's units, dy's sign from the diagonals; every column written (zero below the
// threshold, the direction vertical when the ridge across x is the larger), the span listed.
template <int R>
void write_block(const std::uint8_t* g, std::ptrdiff_t stride, int x0, int x1, int threshold, const RidgeRow& out) {
  constexpr int D = R * 7 / 10 > 1 ? R * 7 / 10 : 1;  // R / sqrt(2), at least 1
  for (int x = x0; x < x1; ++x) {
    const int c = g[x];
    int ax = 0, ay = 0, f = 0, r = 0;
    for (int d = 1; d <= R; ++d) {
      ax = std::max(ax, std::min(c - g[x - d], c - g[x + d]));
      ay = std::max(ay, std::min(c - g[x - d * stride], c - g[x + d * stride]));
    }
    for (int d = 1; d <= D; ++d) {
      f = std::max(f, std::min(c - g[x - d * stride - d], c - g[x + d * stride + d]));  // across (1, 1)
      r = std::max(r, std::min(c - g[x - d * stride + d], c - g[x + d * stride - d]));  // across (1, -1)
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

// The same for a whole row: blocks of columns tested at once in bytes (a saturating difference
// is the ridge's clamp at zero); only a block with a pixel that may reach the threshold (the
// byte sum of its ridges at least a quarter of it) is written.
template <int R>
void ridge_row(const std::uint8_t* g, std::ptrdiff_t stride, int x0, int x1, int threshold, bool use_avx2,
               const RidgeRow& out) {
  int x = use_avx2 ? avx2::ridge_row(g, stride, R, x0, x1, threshold, out) : x0;
#if CV_SIMD128
  const int least = std::min((threshold + 3) / 4, 255);
  const cv::v_uint8x16 floor = cv::v_setall_u8(static_cast<std::uint8_t>(least));
  const auto block = [&](int b) {
    const auto at = [&](std::ptrdiff_t offset) { return cv::v_load(g + b + offset); };
    // The most over d of the lesser rise, c - max(side, other side), as c less the least such
    // max (uint8 operator- saturates: the clamp at zero).
    cv::v_uint8x16 sx = cv::v_max(at(-1), at(1)), sy = cv::v_max(at(-stride), at(stride));
    for (int d = 2; d <= R; ++d) {
      sx = cv::v_min(sx, cv::v_max(at(-d), at(d)));
      sy = cv::v_min(sy, cv::v_max(at(-d * stride), at(d * stride)));
    }
    const cv::v_uint8x16 c = at(0), ax = c - sx, ay = c - sy;
    if (cv::v_check_any((ax + ay) >= floor)) write_block<R>(g, stride, b, b + 16, threshold, out);
  };
  if (x < x1 && x1 - x0 >= 16) {
    for (; x + 16 <= x1; x += 16) block(x);
    if (x < x1) block(x1 - 16);  // the row's last columns, in a block overlapping the one before
    x = x1;
  }
#endif
  if (x < x1) write_block<R>(g, stride, x, x1, threshold, out);
}

using RowFn = void (*)(const std::uint8_t*, std::ptrdiff_t, int, int, int, bool, const RidgeRow&);
constexpr RowFn kRows[RidgePass::kMaxReach] = {ridge_row<1>, ridge_row<2>, ridge_row<3>, ridge_row<4>,
                                               ridge_row<5>, ridge_row<6>, ridge_row<7>, ridge_row<8>};

}  // namespace

// FIELDLINES_NO_AVX2 forces the SSE2/NEON kernels, as for the gradient pass, so that their bits
// are tested on AVX2 machines.
RidgePass::RidgePass() : use_avx2_(avx2::available() && std::getenv("FIELDLINES_NO_AVX2") == nullptr) {}

void RidgePass::run(const GradientMaps& frame, int rows, int reach, int threshold, GradientMaps& maps) {
  const int w = frame.width, h = std::clamp(rows, 0, frame.height);
  const auto n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  // The maps stay cleared between frames but for the blocks the last one wrote: only those are
  // cleared again (a frame writes a few percent of its pixels), unless the size changed.
  if (maps.width != w || maps.height != h || maps.mag.size() != n) {
    maps.width = w, maps.height = h;
    maps.dx.assign(n, 0);
    maps.dy.assign(n, 0);
    maps.mag.assign(n, 0);
    maps.state.assign(n, kVertical);
  } else {
    for (std::size_t k = 0; k < block_count_; ++k) {
      const std::size_t from = blocks_[k], to = std::min(from + kRidgeBlock, n);
      std::fill(maps.dx.begin() + from, maps.dx.begin() + to, 0);
      std::fill(maps.dy.begin() + from, maps.dy.begin() + to, 0);
      std::fill(maps.mag.begin() + from, maps.mag.begin() + to, 0);
      std::fill(maps.state.begin() + from, maps.state.begin() + to, kVertical);
    }
  }
  block_count_ = 0;
  reach = std::clamp(reach, 1, kMaxReach);
  threshold = std::clamp(threshold, 1, 32767);
  if (frame.smooth.size() < n || w <= 2 * reach) return;  // no smoothed grey kept: no ridge anywhere
  // Room for every block of every row: a block per 16 columns and the overlapping last one.
  blocks_.resize(std::max(blocks_.size(), static_cast<std::size_t>(h) * static_cast<std::size_t>(w / 16 + 2)));
  // Rows and columns within `reach` of the frame's border get none; the band's last rows read
  // the frame's rows below it.
  for (int y = reach; y < std::min(h, frame.height - reach); ++y) {
    const std::size_t first = static_cast<std::size_t>(y) * static_cast<std::size_t>(w);
    const RidgeRow row{maps.dx.data() + first, maps.dy.data() + first, maps.mag.data() + first, maps.state.data() + first,
                       static_cast<std::uint32_t>(first), blocks_.data(), &block_count_};
    kRows[reach - 1](frame.smooth.data() + first, w, reach, w - reach, threshold, use_avx2_, row);
  }
}

}  // namespace fieldlines::elsed
