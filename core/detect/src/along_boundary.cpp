#include "along_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>

#include <opencv2/core/hal/intrin.hpp>

namespace fieldlines {
namespace {

constexpr int kWindowPx = 16;  // columns averaged per window: the noise falls 4-fold
constexpr int kStepPx = kWindowPx / 2;
constexpr int kReach = kAlongBoundaryReach;
constexpr int kAbove = kReach + 1;  // the profile starts this far above the boundary, for the ridge's sides
// A ridge's centre at least this far below the boundary: nearer, it is the wall's or the boards'
// foot catching the light (the SSL lab's wall: false markings at 1.8 and 2.1 px), not paint.
constexpr float kMinOffsetPx = 2.5f;
// A ridge reaches at least this many times the window's noise: the median of its profile's second
// differences' size, which a few ridges and a ramp's bends leave out (a frame of random pixels
// has no lines).
constexpr float kNoiseRidges = 3;
constexpr float kLinkPx = 1.5f;     // a line's offset from one window to the next
constexpr float kStraightPx = 1.f;  // a segment's hits off its line at most
constexpr int kMinWindows = 4;      // a segment spans at least this many windows (32 px)

using Hit = AlongBoundary::Hit;

// Per column [from, to) (from at or right of the boundary's first point), the row kAbove px above
// the boundary's row there, rounded: the profile's first. One walk along the hull's pieces rather
// than a search per column.
void profile_tops(const FieldBoundary& boundary, int from, int to, std::vector<int>& tops) {
  tops.clear();
  const std::vector<FieldBoundary::Point>& p = boundary.points;
  std::size_t piece = 0;
  for (int x = from; x < to; ++x) {
    const float fx = static_cast<float>(x);
    while (piece + 1 < p.size() && p[piece + 1].x < fx) ++piece;
    float y = p[piece].y;  // as FieldBoundary::y_at: linear between points, flat past the ends
    if (piece + 1 < p.size() && fx > p[piece].x && p[piece + 1].x > p[piece].x)
      y += (p[piece + 1].y - p[piece].y) * (fx - p[piece].x) / (p[piece + 1].x - p[piece].x);
    tops.push_back(static_cast<int>(std::floor(y + 0.5f)) - kAbove);  // rounded; lround, a libm call, cost 5 µs a frame
  }
}

// The sum of `n` bytes from `p`: sixteen at a time in a vector where there is one (a block's row
// of 8 pixels is 24 bytes), then eight at a time in a 64-bit word; the compiler leaves a byte loop
// of unknown length scalar.
std::uint32_t byte_sum(const std::uint8_t* p, int n) {
  std::uint32_t sum = 0;
  int i = 0;
#if CV_SIMD128
  const cv::v_uint8x16 zero = cv::v_setzero_u8();
  for (; i + 16 <= n; i += 16) sum += cv::v_reduce_sad(cv::v_load(p + i), zero);
#endif
  constexpr std::uint64_t kEvenBytes = 0x00FF00FF00FF00FFull, kLanes = 0x0001000100010001ull;
  for (; i + 8 <= n; i += 8) {
    std::uint64_t v;
    std::memcpy(&v, p + i, 8);
    const std::uint64_t pairs = (v & kEvenBytes) + ((v >> 8) & kEvenBytes);  // four 16-bit sums
    sum += static_cast<std::uint32_t>((pairs * kLanes) >> 48);
  }
  for (; i < n; ++i) sum += p[i];
  return sum;
}

// Per block of kStepPx columns from column `from` (whole blocks only) and per offset k from the
// columns' profiles' first rows (`tops`, from `from` on), the block's summed brightness
// (B + G + R) at its rows top + k, clamped to the frame: `sums[block * offsets + k]`. The columns
// of a block that share a first row (the boundary's slope is gentle) are one run of bytes per row.
void sum_blocks(const cv::Mat& bgr, std::span<const int> tops, int from, int blocks, std::size_t offsets,
                std::vector<AlongBoundary::Run>& runs, std::vector<std::uint32_t>& sums) {
  runs.clear();
  const int columns = blocks * kStepPx;
  for (int a = 0; a < columns;) {
    const int top = tops[static_cast<std::size_t>(a)], block = a / kStepPx, block_end = (block + 1) * kStepPx;
    int b = a + 1;
    while (b < block_end && tops[static_cast<std::size_t>(b)] == top) ++b;
    runs.push_back({3 * (from + a), 3 * (b - a), top, block});
    a = b;
  }
  sums.assign(static_cast<std::size_t>(blocks) * offsets, 0u);
  const int n = static_cast<int>(offsets);
  const std::size_t step = bgr.step;
  for (const AlongBoundary::Run& r : runs) {
    std::uint32_t* out = sums.data() + static_cast<std::size_t>(r.block) * offsets;
    if (r.top >= 0 && r.top + n <= bgr.rows) {  // the whole profile inside the frame
      const std::uint8_t* p = bgr.ptr<std::uint8_t>(r.top) + r.byte;
      for (int k = 0; k < n; ++k, p += step) out[k] += byte_sum(p, r.bytes);
    } else {
      for (int k = 0; k < n; ++k) out[k] += byte_sum(bgr.ptr<std::uint8_t>(std::clamp(r.top + k, 0, bgr.rows - 1)) + r.byte, r.bytes);
    }
  }
}

// The median size of the profile's second differences, in steps of kBendStep grey levels (a
// histogram: a selection per window cost a third of the pass), at most kBendBins steps.
constexpr float kBendStep = 0.125f;
constexpr int kBendBins = 64;
float median_bend(std::span<const float> grey) {
  std::array<int, kBendBins> bins{};
  const int n = static_cast<int>(grey.size());
  for (int k = 1; k + 1 < n; ++k) {
    const float bend = std::abs(grey[static_cast<std::size_t>(k)] -
                                0.5f * (grey[static_cast<std::size_t>(k - 1)] + grey[static_cast<std::size_t>(k + 1)]));
    ++bins[static_cast<std::size_t>(std::min(static_cast<int>(bend / kBendStep), kBendBins - 1))];
  }
  const int half = (n - 2) / 2;
  int below = 0;
  for (int b = 0; b < kBendBins; ++b)
    if ((below += bins[static_cast<std::size_t>(b)]) > half) return (static_cast<float>(b) + 0.5f) * kBendStep;
  return kBendBins * kBendStep;
}

// The window's hits (centre column xc): its ridges of at least `threshold` grey levels and
// kNoiseRidges times its noise, kMinOffsetPx or more below the boundary.
void add_hits(std::span<const float> grey, float xc, float boundary_y, float threshold, std::vector<Hit>& hits) {
  const auto at = [&](int k) { return grey[static_cast<std::size_t>(k)]; };
  const int n = static_cast<int>(grey.size());
  // The ridge at k when it is a maximum there (the upper one of a flat top), else 0.
  const auto ridge_at = [&](int k) {
    const float c = at(k);
    if (c < at(k - 1) || c <= at(k + 1)) return 0.f;
    float ridge = 0;
    for (int d = 1; d <= kReach; ++d) ridge = std::max(ridge, std::min(c - at(k - d), c - at(k + d)));
    return ridge;
  };
  const int first = std::max(kReach, kAbove + static_cast<int>(std::ceil(kMinOffsetPx)) - 1), end = n - kReach;
  bool any = false;
  for (int k = first; k < end && !any; ++k) any = ridge_at(k) >= threshold;
  if (!any) return;  // the noise is measured only where some ridge may be kept: most windows have none
  threshold = std::max(threshold, kNoiseRidges * median_bend(grey));
  for (int k = first; k < end; ++k) {
    if (ridge_at(k) < threshold) continue;
    const float up = at(k - 1), c = at(k), down = at(k + 1);
    const float curve = up - 2 * c + down;  // < 0 at a strict maximum
    const float shift = curve < 0 ? std::clamp(0.5f * (up - down) / curve, -0.5f, 0.5f) : 0.f;
    const float offset = static_cast<float>(k - kAbove) + shift;
    if (offset < kMinOffsetPx) continue;
    hits.push_back({xc, boundary_y + offset, offset});
  }
}

// The least-squares line y = a + b x through points, its sums kept as points join.
struct Fit {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  void add(const AlongBoundary::Point& p) { n += 1, sx += p.x, sy += p.y, sxx += double(p.x) * p.x, sxy += double(p.x) * p.y; }
  double slope() const {
    const double den = n * sxx - sx * sx;
    return den > 0 ? (n * sxy - sx * sy) / den : 0;
  }
  double at(double x) const {
    const double b = slope();
    return (sy - b * sx) / n + b * x;
  }
};
Fit fit_of(std::span<const AlongBoundary::Point> points) {
  Fit f;
  for (const AlongBoundary::Point& p : points) f.add(p);
  return f;
}
bool straight(const Fit& f, std::span<const AlongBoundary::Point> points) {
  return std::all_of(points.begin(), points.end(), [&](const AlongBoundary::Point& p) { return std::abs(f.at(p.x) - p.y) <= kStraightPx; });
}

// The segment through `points` (a chain's piece), from half a step before the first window's
// centre to half a step past the last's, with the line's colour against its sides' (kAbove px off).
Segment segment_of(const cv::Mat& bgr, std::span<const AlongBoundary::Point> points) {
  const Fit f = fit_of(points);
  Segment s;
  s.x0 = std::max(0.f, points.front().x - 0.5f * kStepPx);
  s.x1 = std::min(static_cast<float>(bgr.cols - 1), points.back().x + 0.5f * kStepPx);
  s.y0 = static_cast<float>(f.at(s.x0)), s.y1 = static_cast<float>(f.at(s.x1));
  s.saliency = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  std::array<float, 3> line{}, sides{};  // B, G, R sums
  int count = 0;
  const auto add = [&](std::array<float, 3>& sum, int x, double y, float weight) {
    const int row = static_cast<int>(std::floor(y + 0.5));
    const std::uint8_t* p = bgr.ptr<std::uint8_t>(std::clamp(row, 0, bgr.rows - 1)) + 3 * x;
    for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += weight * static_cast<float>(p[ch]);
  };
  constexpr int kColourStepPx = 4;  // the colours' mean over every 4th column: a line's colour is steady along it
  for (int x = static_cast<int>(std::ceil(s.x0)); x <= static_cast<int>(s.x1); x += kColourStepPx, ++count) {
    const double y = f.at(x);
    add(line, x, y, 1.f), add(sides, x, y - kAbove, 0.5f), add(sides, x, y + kAbove, 0.5f);
  }
  const float per = 1.f / static_cast<float>(std::max(count, 1));
  const float b = static_cast<float>(f.slope()), norm = std::hypot(b, 1.f);
  const float nx = -b / norm, ny = 1.f / norm;  // the normal pointing down
  for (std::size_t ch = 0; ch < 3; ++ch) {  // R, G, B from B, G, R
    const float excess = (line[2 - ch] - sides[2 - ch]) * per;
    s.grad_x[ch] = excess * nx, s.grad_y[ch] = excess * ny;
  }
  return s;
}

}  // namespace

void find_lines_along_boundary(const cv::Mat& bgr8, const FieldBoundary& boundary, int depth, float threshold,
                               AlongBoundary& work, std::vector<Segment>& out) {
  out.clear();
  work.hits.clear();
  work.window_start.clear();
  if (boundary.empty() || bgr8.empty() || depth < 1) return;
  const auto offsets = static_cast<std::size_t>(kAbove + depth + kReach + 1);
  work.window.resize(offsets);
  const int from = std::max(0, static_cast<int>(std::ceil(boundary.points.front().x)));
  const int to = std::min(bgr8.cols, static_cast<int>(boundary.points.back().x) + 1);
  // Windows of two blocks of kStepPx columns, one block on from the last.
  const int blocks = (to - from) / kStepPx;
  if (blocks < 2) return;
  profile_tops(boundary, from, to, work.tops);
  sum_blocks(bgr8, work.tops, from, blocks, offsets, work.runs, work.sums);
  for (int block = 1; block < blocks; ++block) {
    constexpr float kPerColumn = 1.f / (3 * kWindowPx);  // grey levels per column
    const std::uint32_t* left = work.sums.data() + static_cast<std::size_t>(block - 1) * offsets;
    const std::uint32_t* right = left + offsets;
    for (std::size_t k = 0; k < offsets; ++k) work.window[k] = static_cast<float>(left[k] + right[k]) * kPerColumn;
    const float xc = static_cast<float>(from + block * kStepPx) - 0.5f;  // the window's centre
    work.window_start.push_back(static_cast<int>(work.hits.size()));
    add_hits(work.window, xc, boundary.y_at(xc), threshold, work.hits);
  }
  work.window_start.push_back(static_cast<int>(work.hits.size()));
  // Links: each hit of a window to the free one of the next nearest to its offset from the
  // boundary (where the boundary's slope carries it).
  std::vector<Hit>& hits = work.hits;
  for (std::size_t w = 0; w + 2 < work.window_start.size(); ++w)
    for (int i = work.window_start[w]; i < work.window_start[w + 1]; ++i) {
      Hit& h = hits[static_cast<std::size_t>(i)];
      float best = kLinkPx;
      for (int j = work.window_start[w + 1]; j < work.window_start[w + 2]; ++j) {
        const Hit& g = hits[static_cast<std::size_t>(j)];
        const float off = std::abs(g.offset - h.offset);
        if (!g.linked && off <= best) best = off, h.next = j;
      }
      if (h.next >= 0) hits[static_cast<std::size_t>(h.next)].linked = true;
    }
  // Chains from their heads, cut into straight pieces (consecutive pieces share a hit).
  std::vector<AlongBoundary::Point>& chain = work.chain;
  for (std::size_t head = 0; head < hits.size(); ++head) {
    if (hits[head].linked) continue;
    chain.clear();
    for (int i = static_cast<int>(head); i >= 0; i = hits[static_cast<std::size_t>(i)].next)
      chain.push_back({hits[static_cast<std::size_t>(i)].x, hits[static_cast<std::size_t>(i)].y});
    const std::span<const AlongBoundary::Point> all(chain);
    std::size_t first = 0;
    Fit f;
    f.add(chain[0]);
    for (std::size_t i = 1; i <= chain.size(); ++i) {
      if (i < chain.size()) {
        Fit g = f;
        g.add(chain[i]);
        if (straight(g, all.subspan(first, i + 1 - first))) {
          f = g;
          continue;
        }
      }
      if (i - first >= static_cast<std::size_t>(kMinWindows)) out.push_back(segment_of(bgr8, all.subspan(first, i - first)));
      if (i == chain.size()) break;
      first = i - 1;  // the next piece starts at this one's last hit
      f = fit_of(all.subspan(first, 2));
    }
  }
}

}  // namespace fieldlines
