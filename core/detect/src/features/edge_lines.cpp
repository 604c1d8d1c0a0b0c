#include "edge_lines.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>

#include "field_pixel.hpp"
#include "paint_profile.hpp"

namespace fieldlines {
namespace {

using namespace paint;

constexpr int kBack = kOuterPx + 2;  // the profile starts this far on the edge's dark side
constexpr int kTurfPx = 3;           // field samples past the paint: a sliver of turf is no field
// The paint begins at most this far from the surround, and its half-way crossing this far from
// the segment: a line a few px inside the field has the turf's own edge outside it. Held-out
// venues (docs/detector.md): at 1 px the rule finds almost nothing, at 3 px Humanoid and Bangkok
// lose precision to the turf's edge beside a line.
constexpr int kEdgeFadePx = 2;
constexpr int kMaxSteps = 256;  // a profile's samples (the widest plausible paint is far narrower)

struct EdgePaint {
  float offset = 0, width = 0;  // px along the normal: the paint's centre from the segment, its width
};

// One profile from (px, py) along the unit normal (sx, sy) into the bright side, `max_width` the
// widest plausible paint there.
std::optional<EdgePaint> edge_paint(const cv::Mat& bgr, const FieldPixel& pixel, float px, float py, float sx,
                                    float sy, float max_width) {
  const int steps = kBack + static_cast<int>(std::ceil(max_width)) + kMaxBlurPx + kTurfPx + 1;
  if (steps > kMaxSteps) return std::nullopt;
  std::array<const std::uint8_t*, kMaxSteps> at{};
  std::array<float, kMaxSteps> b{};
  for (int i = 0; i < steps; ++i) {
    const float t = float(i - kBack);
    const long x = std::lround(px + t * sx), y = std::lround(py + t * sy);
    if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) return std::nullopt;
    at[static_cast<std::size_t>(i)] = bgr.ptr<std::uint8_t>(static_cast<int>(y)) + 3 * x;
    b[static_cast<std::size_t>(i)] = brightness(at[static_cast<std::size_t>(i)]);
  }
  const auto field = [&](int i) { return pixel.field(at[static_cast<std::size_t>(i)]); };
  const auto v = [&](int i) { return b[static_cast<std::size_t>(i)]; };
  // The turf past the paint: the first field sample after the peak that lies less than half-way
  // from the turf after it up to the peak.
  int peak = kBack - 1, turf = kBack;
  for (;; ++turf) {
    if (turf + kTurfPx >= steps) return std::nullopt;
    if (v(turf) > v(peak)) peak = turf;
    if (turf > peak && field(turf) && v(turf) < 0.5f * (v(peak) + v(turf + 1))) break;
  }
  for (int i = turf; i <= turf + kTurfPx; ++i)
    if (!field(i)) return std::nullopt;
  const float beyond = 0.5f * (v(turf + 1) + v(turf + 2));
  // The surround: before the peak, no field and darker than half the turf beyond the paint.
  int outside = peak - 1;
  while (outside >= 0 && !(v(outside) < 0.5f * beyond && !field(outside))) --outside;
  if (outside < 0) return std::nullopt;
  // Paint: brighter than the turf by the stripes' contrast; in the field colour only as grey
  // blended into it (a line thinner than a pixel).
  if (v(peak) < kPaintContrast * beyond) return std::nullopt;
  if (field(peak) && !blended_paint(at[static_cast<std::size_t>(peak)], at[static_cast<std::size_t>(turf + 1)]))
    return std::nullopt;
  // Its extent: brighter than half-way from the turf to the peak, on both sides.
  const float level = 0.5f * (v(peak) + beyond);
  int lo = peak, hi = peak;
  while (lo - 1 > outside && v(lo - 1) >= level) --lo;
  while (hi + 1 < turf && v(hi + 1) >= level) ++hi;
  const float near_edge = crossing(b, lo - 1, level), far_edge = crossing(b, hi, level);
  if (lo - outside > kEdgeFadePx || std::abs(near_edge - float(kBack)) > kEdgeFadePx) return std::nullopt;
  const float width = far_edge - near_edge;
  if (width < kMinWidthPx || width > max_width) return std::nullopt;
  return EdgePaint{0.5f * (near_edge + far_edge) - float(kBack), width};
}

}  // namespace

bool edge_line(const cv::Mat& bgr, const FieldPixel& pixel, const Segment& s, const DetectorParams& params,
               StripeWorkspace::Candidate& c) {
  const float dx = s.x1 - s.x0, dy = s.y1 - s.y0, len = std::hypot(dx, dy);
  if (!(len > 0.f)) return false;
  c.ux = dx / len, c.uy = dy / len;
  const auto [nx, ny] = bright_side(bgr, s, c.ux, c.uy);
  constexpr float kMinDown = 0.5f;  // within 60 degrees of straight down the frame
  if (!(ny > kMinDown)) return false;
  c.sx = nx, c.sy = ny;
  const int samples = std::clamp(params.stripe_samples, 1, 32);
  std::array<float, 32> widths{}, offsets{};
  int n = 0;
  for (int k = 0; k < samples; ++k) {
    const float f = (float(k) + 0.5f) / float(samples);
    const float py = s.y0 + f * dy;
    const float max_width = static_cast<float>(params.stripe_max_width) * width_scale(py, bgr.rows);
    if (const auto e = edge_paint(bgr, pixel, s.x0 + f * dx, py, nx, ny, max_width)) {
      widths[static_cast<std::size_t>(n)] = e->width, offsets[static_cast<std::size_t>(n)] = e->offset;
      ++n;
    }
  }
  if (2 * n <= samples) return false;
  c.width = median(widths, n);
  c.offset0 = c.offset1 = median(offsets, n);
  c.bow = 0;
  c.edge0 = c.edge1 = c.edge_median = c.edge_spread = 0;  // on its edge: never moved (snap_to_edge)
  return true;
}

}  // namespace fieldlines
