#include "along_boundary.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>

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
constexpr int kMinWindows = 4;      // a segment spans at least this many windows (40 px)

using Hit = AlongBoundary::Hit;

// The summed brightness (B + G + R) of columns [x0, x1) at each offset from kAbove px above the
// boundary, each column read at its own boundary row, rows clamped to the frame.
void sum_columns(const cv::Mat& bgr, const FieldBoundary& boundary, int x0, int x1, std::vector<float>& sums) {
  std::fill(sums.begin(), sums.end(), 0.f);
  const int n = static_cast<int>(sums.size());
  for (int x = x0; x < x1; ++x) {
    const int top = static_cast<int>(std::lround(boundary.y_at(static_cast<float>(x)))) - kAbove;
    for (int k = 0; k < n; ++k) {
      const std::uint8_t* p = bgr.ptr<std::uint8_t>(std::clamp(top + k, 0, bgr.rows - 1)) + 3 * x;
      sums[static_cast<std::size_t>(k)] += static_cast<float>(p[0] + p[1] + p[2]);
    }
  }
}

// The window's hits (centre column xc): its ridges of at least `threshold` grey levels and
// kNoiseRidges times its noise, kMinOffsetPx or more below the boundary.
void add_hits(std::span<const float> sums, float xc, float boundary_y, float threshold, std::vector<float>& bends,
              std::vector<Hit>& hits) {
  const auto at = [&](int k) { return sums[static_cast<std::size_t>(k)] / (3.f * kWindowPx); };  // grey per column
  const int n = static_cast<int>(sums.size());
  bends.clear();
  for (int k = 1; k + 1 < n; ++k) bends.push_back(std::abs(at(k) - 0.5f * (at(k - 1) + at(k + 1))));
  if (bends.empty()) return;
  std::nth_element(bends.begin(), bends.begin() + static_cast<std::ptrdiff_t>(bends.size() / 2), bends.end());
  threshold = std::max(threshold, kNoiseRidges * bends[bends.size() / 2]);
  for (int k = kReach; k < n - kReach; ++k) {
    const float c = at(k), up = at(k - 1), down = at(k + 1);
    if (c < up || c <= down) continue;  // a maximum (the upper one of a flat top)
    float ridge = 0;
    for (int d = 1; d <= kReach; ++d) ridge = std::max(ridge, std::min(c - at(k - d), c - at(k + d)));
    if (ridge < threshold) continue;
    const float curve = up - 2 * c + down;  // < 0 at a strict maximum
    const float shift = curve < 0 ? std::clamp(0.5f * (up - down) / curve, -0.5f, 0.5f) : 0.f;
    const float offset = static_cast<float>(k - kAbove) + shift;
    if (offset < kMinOffsetPx) continue;
    hits.push_back({xc, boundary_y + offset});
  }
}

// The least-squares line y = a + b x through hits [first .. last] along their links.
struct Fit {
  double a = 0, b = 0;
};
Fit fit(const std::vector<Hit>& hits, int first, int last) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (int i = first;; i = hits[static_cast<std::size_t>(i)].next) {
    const Hit& h = hits[static_cast<std::size_t>(i)];
    n += 1, sx += h.x, sy += h.y, sxx += double(h.x) * h.x, sxy += double(h.x) * h.y;
    if (i == last) break;
  }
  const double den = n * sxx - sx * sx;
  const double b = den > 0 ? (n * sxy - sx * sy) / den : 0;
  return {(sy - b * sx) / n, b};
}
bool straight(const std::vector<Hit>& hits, int first, int last) {
  const Fit f = fit(hits, first, last);
  for (int i = first;; i = hits[static_cast<std::size_t>(i)].next) {
    const Hit& h = hits[static_cast<std::size_t>(i)];
    if (std::abs(f.a + f.b * h.x - h.y) > kStraightPx) return false;
    if (i == last) return true;
  }
}

// The segment through hits [first .. last], from half a step before the first window's centre
// to half a step past the last's, with the line's colour against its sides' (kAbove px off).
Segment segment_of(const cv::Mat& bgr, const std::vector<Hit>& hits, int first, int last) {
  const Fit f = fit(hits, first, last);
  Segment s;
  s.x0 = std::max(0.f, hits[static_cast<std::size_t>(first)].x - 0.5f * kStepPx);
  s.x1 = std::min(static_cast<float>(bgr.cols - 1), hits[static_cast<std::size_t>(last)].x + 0.5f * kStepPx);
  s.y0 = static_cast<float>(f.a + f.b * s.x0), s.y1 = static_cast<float>(f.a + f.b * s.x1);
  s.saliency = std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  std::array<float, 3> line{}, sides{};  // B, G, R sums
  int count = 0;
  const auto add = [&](std::array<float, 3>& sum, int x, double y, float weight) {
    const std::uint8_t* p = bgr.ptr<std::uint8_t>(std::clamp(static_cast<int>(std::lround(y)), 0, bgr.rows - 1)) + 3 * x;
    for (std::size_t ch = 0; ch < 3; ++ch) sum[ch] += weight * static_cast<float>(p[ch]);
  };
  for (int x = static_cast<int>(std::ceil(s.x0)); x <= static_cast<int>(s.x1); ++x, ++count) {
    const double y = f.a + f.b * x;
    add(line, x, y, 1.f), add(sides, x, y - kAbove, 0.5f), add(sides, x, y + kAbove, 0.5f);
  }
  const float per = 1.f / static_cast<float>(std::max(count, 1));
  const float norm = std::hypot(static_cast<float>(f.b), 1.f);
  const float nx = -static_cast<float>(f.b) / norm, ny = 1.f / norm;  // the normal pointing down
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
  work.window.resize(offsets), work.previous.resize(offsets), work.current.resize(offsets);
  const int from = std::max(0, static_cast<int>(std::ceil(boundary.points.front().x)));
  const int to = std::min(bgr8.cols, static_cast<int>(boundary.points.back().x) + 1);
  // Windows of two blocks of kStepPx columns, one block on from the last.
  if (to - from < kWindowPx) return;
  sum_columns(bgr8, boundary, from, from + kStepPx, work.previous);
  for (int x = from + kStepPx; x + kStepPx <= to; x += kStepPx) {
    sum_columns(bgr8, boundary, x, x + kStepPx, work.current);
    for (std::size_t k = 0; k < offsets; ++k) work.window[k] = work.previous[k] + work.current[k];
    std::swap(work.previous, work.current);
    const float xc = static_cast<float>(x) - 0.5f;  // the window's centre: columns x - kStepPx .. x + kStepPx - 1
    work.window_start.push_back(static_cast<int>(work.hits.size()));
    add_hits(work.window, xc, boundary.y_at(xc), threshold, work.bends, work.hits);
  }
  work.window_start.push_back(static_cast<int>(work.hits.size()));
  // Links: each hit of a window to the nearest free one of the next where the boundary's slope
  // carries it.
  std::vector<Hit>& hits = work.hits;
  for (std::size_t w = 0; w + 2 < work.window_start.size(); ++w)
    for (int i = work.window_start[w]; i < work.window_start[w + 1]; ++i) {
      Hit& h = hits[static_cast<std::size_t>(i)];
      float best = kLinkPx;
      for (int j = work.window_start[w + 1]; j < work.window_start[w + 2]; ++j) {
        const Hit& g = hits[static_cast<std::size_t>(j)];
        const float off = std::abs(g.y - (h.y + boundary.y_at(g.x) - boundary.y_at(h.x)));
        if (!g.linked && off <= best) best = off, h.next = j;
      }
      if (h.next >= 0) hits[static_cast<std::size_t>(h.next)].linked = true;
    }
  // Chains from their heads, cut into straight pieces (consecutive pieces share a hit).
  for (int head = 0; head < static_cast<int>(hits.size()); ++head) {
    if (hits[static_cast<std::size_t>(head)].linked) continue;
    int first = head, last = head, length = 1;
    for (int i = hits[static_cast<std::size_t>(head)].next;; i = hits[static_cast<std::size_t>(i)].next) {
      if (i >= 0 && straight(hits, first, i)) {
        last = i, ++length;
        continue;
      }
      if (length >= kMinWindows) out.push_back(segment_of(bgr8, hits, first, last));
      if (i < 0) break;
      first = last, last = i, length = 2;
    }
  }
}

}  // namespace fieldlines
