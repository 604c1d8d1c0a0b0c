#include "colour_gradients.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <opencv2/core/hal/intrin.hpp>

#include "angles.hpp"

namespace fieldlines::elsed {
namespace {

constexpr double kPi = std::numbers::pi;

// Bilinear interpolation of dx and dy at (x, y), clamped to the image; the corners and weights
// are found once for both maps.
struct Gradient {
  float gx, gy;
};
Gradient sample(const GradientMaps& maps, float x, float y) {
  const int w = maps.width, h = maps.height;
  const int x0 = std::clamp(static_cast<int>(x), 0, w - 1), y0 = std::clamp(static_cast<int>(y), 0, h - 1);
  const int x1 = std::clamp(static_cast<int>(x + 1), 0, w - 1), y1 = std::clamp(static_cast<int>(y + 1), 0, h - 1);
  const float tx = x - static_cast<int>(x), ty = y - static_cast<int>(y);
  const int i00 = y0 * w + x0, i01 = y0 * w + x1, i10 = y1 * w + x0, i11 = y1 * w + x1;
  const auto at = [&](const std::int16_t* m) {
    const float top = m[i00] + (m[i01] - m[i00]) * tx;
    const float bottom = m[i10] + (m[i11] - m[i10]) * tx;
    return top + (bottom - top) * ty;
  };
  return {at(maps.dx.data()), at(maps.dy.data())};
}

// A thin line's colours (ValidationParams::ridge_reach), summed over its pixels: each against
// the mean of the pixels reach + 1 px to either side across it, just past the widest line the
// ridge takes.
class ThinLineColours {
 public:
  ThinLineColours(int reach, double nx, double ny)
      : step_x_(static_cast<int>(std::lround((reach + 1) * nx))), step_y_(static_cast<int>(std::lround((reach + 1) * ny))),
        nx_(static_cast<float>(nx)), ny_(static_cast<float>(ny)) {}
  // Skips a pixel whose sides leave the frame.
  void add(const cv::Mat& bgr, Pixel px) {
    const int ax = px.x - step_x_, ay = px.y - step_y_, bx = px.x + step_x_, by = px.y + step_y_;
    if (std::min(ax, bx) < 0 || std::max(ax, bx) >= bgr.cols || std::min(ay, by) < 0 || std::max(ay, by) >= bgr.rows) return;
    const std::uint8_t* c = bgr.ptr<std::uint8_t>(px.y) + 3 * px.x;
    const std::uint8_t* a = bgr.ptr<std::uint8_t>(ay) + 3 * ax;
    const std::uint8_t* b = bgr.ptr<std::uint8_t>(by) + 3 * bx;
    for (int ch = 0; ch < 3; ++ch) line_[2 - ch] += float(c[ch]) - 0.5f * (float(a[ch]) + float(b[ch]));
    ++count_;
  }
  // The colour transition from the sides to the line, along the segment's normal: what an edge
  // of the line carries.
  void set_gradients(Segment& out) const {
    const float inv = count_ > 0 ? 1.f / static_cast<float>(count_) : 0.f;
    for (int ch = 0; ch < 3; ++ch) out.grad_x[ch] = line_[ch] * inv * nx_, out.grad_y[ch] = line_[ch] * inv * ny_;
  }

 private:
  int step_x_, step_y_;
  float nx_, ny_;
  Rgb line_{};
  int count_ = 0;
};

}  // namespace

bool validate_segment(const LineModel& seg, const std::vector<Pixel>& chain, const GradientMaps& maps,
                      const cv::Mat& bgr, const ValidationParams& params, Segment& out, SegmentFilter keep) {
  const int w = maps.width, h = maps.height;
  const auto& e = seg.endpoints();
  out.x0 = e[0];
  out.y0 = e[1];
  out.x1 = e[2];
  out.y1 = e[3];
  if (params.validate && seg.count() < 2) return false;
  if (!std::isfinite(e[0]) || !std::isfinite(e[1]) || !std::isfinite(e[2]) || !std::isfinite(e[3])) return false;

  // Normal orientation of the segment in [0, pi), from its endpoints.
  const float sdx = e[2] - e[0], sdy = e[3] - e[1];
  const float along = e[2] > e[0] ? std::atan2(sdy, sdx) : std::atan2(-sdy, -sdx);
  const double normal = wrap_half_turn(along + kPi / 2);
  const double nx = std::cos(normal), ny = std::sin(normal);
  const double cos_max = std::cos(params.max_angle_error), sin_max = std::sin(params.max_angle_error);
  // Line through the endpoints, normalised, to re-project pixels onto it.
  float la = e[1] - e[3], lb = e[2] - e[0], lc = e[0] * e[3] - e[1] * e[2];
  const float ln = std::sqrt(la * la + lb * lb);
  la /= ln, lb /= ln, lc /= ln;

  const int trim = static_cast<int>(std::min(5.0, seg.count() * 0.1));
  const Pixel first = seg.first(), last = seg.last();
  // Running sum of the 3x3 BGR windows, row-major, channel-interleaved. The method sums in float;
  // while every sum stays below 2^24 (fewer than 65793 windows of bytes) that is exact, so exact
  // integer sums give the same floats for less work. Longer segments keep the float sums.
  std::array<float, 27> window{};
  std::array<std::uint32_t, 27> int_window{};
  const bool int_sums = seg.last_index() - seg.first_index() < 65000;
#if CV_SIMD128
  // The integer sums in vectors: per window row, bytes 0-3 and 4-7 in two, byte 8 alone.
  cv::v_uint32x4 sum_lo[3] = {cv::v_setzero_u32(), cv::v_setzero_u32(), cv::v_setzero_u32()};
  cv::v_uint32x4 sum_hi[3] = {cv::v_setzero_u32(), cv::v_setzero_u32(), cv::v_setzero_u32()};
#endif
  int window_count = 0, inliers = 0, outliers = 0;

  // Visits the segment's inlier pixels, ends trimmed: those both tests count.
  const auto for_each_pixel = [&](auto&& visit) {
    for (int i = seg.first_index(); i <= seg.last_index(); ++i) {
      const Pixel px = chain[i];
      if (i + 8 <= seg.last_index()) {
        // The pixels are known ahead: have their gradient and colour rows in flight.
        const Pixel ahead = chain[i + 8];
        const int a = ahead.y * w + ahead.x, below = std::min(ahead.y + 1, h - 1) * w + ahead.x;
        __builtin_prefetch(maps.dx.data() + a);
        __builtin_prefetch(maps.dy.data() + a);
        __builtin_prefetch(maps.dx.data() + below);
        __builtin_prefetch(maps.dy.data() + below);
        __builtin_prefetch(bgr.ptr<std::uint8_t>(std::max(ahead.y - 1, 0)) + 3 * ahead.x);
        __builtin_prefetch(bgr.ptr<std::uint8_t>(ahead.y) + 3 * ahead.x);
        __builtin_prefetch(bgr.ptr<std::uint8_t>(std::min(ahead.y + 1, h - 1)) + 3 * ahead.x);
      }
      if (mark_of(maps.state[px.y * w + px.x]) != Mark::Inlier) continue;  // junction and dropped pixels do not count
      const int to_end = seg.horizontal() ? std::min(std::abs(px.x - last.x), std::abs(px.x - first.x))
                                          : std::min(std::abs(px.y - last.y), std::abs(px.y - first.y));
      if (to_end < trim) continue;
      visit(px);
    }
  };
  const auto test_angle = [&](Pixel px) {
    // The gradient orientation on the line itself (bilinear), not at the discrete pixel.
    const float dist = la * px.x + lb * px.y + lc;
    const float qx = px.x - la * dist, qy = px.y - lb * dist;
    const auto [gx, gy] = sample(maps, qx, qy);
    // The method's test is orientation_distance(normal, atan2(gy, gx)) > max_angle_error. Its
    // sign is that of |g| sin(delta - max): |n x g| cos(max) - |n . g| sin(max), a few
    // multiplications instead of an atan2. Only within 1e-4 rad of the threshold, where the
    // float atan2's error could matter, is the method's own expression evaluated.
    const double cross = std::abs(nx * gy - ny * gx), dot = std::abs(nx * gx + ny * gy);
    const double side = cross * cos_max - dot * sin_max;
    const double margin = 1e-4 * (std::abs(gx) + std::abs(gy));
    bool outlier = side > 0;
    if (std::abs(side) <= margin) {
      double angle = std::atan2(gy, gx);
      if (angle < 0) angle += kPi;
      if (angle >= kPi) angle -= kPi;
      outlier = orientation_distance(normal, angle) > params.max_angle_error;
    }
    outlier ? ++outliers : ++inliers;
  };
  const auto add_window = [&](Pixel px) {
    if (px.x < 1 || px.x >= w - 1 || px.y < 1 || px.y >= h - 1) return;
    for (int r = 0; r < 3; ++r) {
      const std::uint8_t* row = bgr.ptr<std::uint8_t>(px.y - 1 + r) + 3 * (px.x - 1);
      if (int_sums) {
#if CV_SIMD128
        cv::v_uint32x4 lo, hi;
        cv::v_expand(cv::v_load_expand(row), lo, hi);  // 8 bytes, unaligned: one 64-bit load
        sum_lo[r] = sum_lo[r] + lo;
        sum_hi[r] = sum_hi[r] + hi;
        int_window[r * 9 + 8] += row[8];
#else
        std::uint32_t* dst = &int_window[r * 9];
        for (int k = 0; k < 9; ++k) dst[k] += row[k];
#endif
      } else {
        float* dst = &window[r * 9];
        for (int k = 0; k < 9; ++k) dst[k] += row[k];
      }
    }
    ++window_count;
  };
  ThinLineColours thin(params.ridge_reach, nx, ny);
  const auto colours = [&](Pixel px) { params.ridge_reach > 0 ? thin.add(bgr, px) : add_window(px); };
  // Sobel of the mean window / 4, in R,G,B order; y is the image-down derivative.
  const auto set_gradients = [&] {
    if (params.ridge_reach > 0) return thin.set_gradients(out);
    if (int_sums) {
#if CV_SIMD128
      for (int r = 0; r < 3; ++r) {
        cv::v_store(&int_window[r * 9], sum_lo[r]);
        cv::v_store(&int_window[r * 9 + 4], sum_hi[r]);
      }
#endif
      for (int k = 0; k < 27; ++k) window[k] = static_cast<float>(int_window[k]);
    }
    out.grad_x = {0, 0, 0};
    out.grad_y = {0, 0, 0};
    if (window_count > 0) {
      const float inv = 1.f / static_cast<float>(window_count);
      const auto at = [&](int r, int col, int ch) { return window[r * 9 + col * 3 + ch] * inv; };
      for (int ch = 0; ch < 3; ++ch) {
        const float gx = (at(0, 2, ch) - at(0, 0, ch)) + 2 * (at(1, 2, ch) - at(1, 0, ch)) + (at(2, 2, ch) - at(2, 0, ch));
        const float gy = (at(2, 0, ch) - at(0, 0, ch)) + 2 * (at(2, 1, ch) - at(0, 1, ch)) + (at(2, 2, ch) - at(0, 2, ch));
        out.grad_x[2 - ch] = gx / 4;
        out.grad_y[2 - ch] = gy / 4;
      }
    }
  };

  if (keep.test == nullptr) {
    // One visit for both tests.
    for_each_pixel([&](Pixel px) {
      test_angle(px);
      colours(px);
    });
    set_gradients();
  } else {
    // The colours first: a segment they rule out skips the angle test.
    for_each_pixel(colours);
    set_gradients();
    out.saliency = 0;
    if (!keep.test(keep.context, out)) return false;
    for_each_pixel(test_angle);
  }
  if (!params.validate) {
    out.saliency = std::hypot(sdx, sdy);
    return true;
  }
  out.saliency = static_cast<float>(inliers);
  return inliers > outliers;
}

}  // namespace fieldlines::elsed
