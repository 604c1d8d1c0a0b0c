#include "fieldlines/detect/centre_circle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>

#include "conic_fit.hpp"
#include "field_pixel.hpp"
#include "ground_circle.hpp"

namespace fieldlines {
namespace {

using Point = CircleWorkspace::Point;

constexpr float kMinBendCos = 0.99863f;   // cos(3 degrees): less is a straight line broken in two
constexpr float kMaxBendCos = 0.76604f;   // cos(40 degrees): more is a corner
constexpr float kLinkWidths = 2, kLinkPx = 6;
constexpr int kMinChain = 3;
constexpr int kSamplesPerPiece = 3;
constexpr int kCoverageBins = 36;
constexpr float kMinCoverage = 150.f / 360;  // less was a corner and a stray piece as often as a circle
// Unless the frame cuts the ellipse: then this share of the turn inside the frame, and at least
// kMinCutCoverage (a circle whose centre lies beyond the frame's edge shows less than 150
// degrees of its turn). 100 degrees (a frame showing 30 % of the circle shows about 108) found
// no more circles on the tuning seeds and one more wrong ellipse with Kid thresholds calibrated.
constexpr float kFrameCoverShare = 0.8f;
constexpr float kMinCutCoverage = 120.f / 360;
// On the turf a circle of known radius needs less: pieces agreeing on its centre over 90 degrees
// of its turn (on the tuning seeds 120 degrees found 41 circles of 53, 90 degrees 43, 72 degrees
// no more).
constexpr float kMinGroundCoverage = 90.f / 360;
constexpr float kMaxTangentSin = 0.342f;  // sin(20 degrees)
// The longest pieces: pair hypotheses and their support. 16, from 24: the same held-out figures,
// one wrong ellipse fewer on the tuning seeds, one more Kid circle calibrated, the stage half as dear.
constexpr std::size_t kMaxPairPieces = 16;
constexpr int kMinSupport = 4;              // pieces along a pair's ellipse
// A pair's axes are tried turned from the image's by up to 9 degrees: the camera's roll is
// small, but a circle seen off the optical axis is an ellipse turned by several degrees, and an
// axis off by a few degrees misses a flat ellipse's ends.
constexpr int kRollSteps = 3;
constexpr float kRollStepDeg = 3;
// An ellipse over bare turf on more than this share of its points in the frame is refused. On
// the tuning seeds (Kid 1, 2, 3, 5) every circle found showed none; the wrong ellipses 0.09 to
// 0.46, and some none.
constexpr float kMaxBareTurf = 0.05f;

float length(const Marking& m) { return std::hypot(m.x1 - m.x0, m.y1 - m.y0); }

// How far off an ellipse its pieces may lie: half their mean line width, at least 2.5 px (a
// piece is a chord: its middle lies inside the curve). `width_sum` over `count` pieces.
float tolerance_of_widths(float width_sum, int count) {
  return std::max(2.5f, width_sum / static_cast<float>(std::max(count, 1)) / 2);
}

// The bin of the turn (kCoverageBins round the ellipse, seen from its centre in its own axes)
// that `p` lies in; co, si: the cosine and sine of fit.theta (the callers' loops compute them once).
int turn_bin(const Fit& fit, float co, float si, const Point& p) {
  const float dx = p.x - fit.ellipse.cx, dy = p.y - fit.ellipse.cy;
  const float phi = std::atan2((-dx * si + dy * co) / fit.semi_b, (dx * co + dy * si) / fit.semi_a);
  return std::clamp(static_cast<int>((phi + std::numbers::pi_v<float>) / (2 * std::numbers::pi_v<float>) * kCoverageBins), 0,
                    kCoverageBins - 1);
}

// The share of the ellipse's turn (seen from its centre, in its own axes) the inliers cover.
// Points come in runs of kSamplesPerPiece per piece: the turn between two inlier samples of one
// piece is covered too (a long chord of a flat ellipse spans several bins between its samples).
float coverage(const std::vector<Point>& points, const Fit& fit) {
  std::array<bool, kCoverageBins> seen{};
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  int previous = 0;  // the bin of points[i - 1] when that is an inlier
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].inlier) continue;
    const int bin = turn_bin(fit, co, si, points[i]);
    seen[static_cast<std::size_t>(bin)] = true;
    const bool after_inlier = i % kSamplesPerPiece != 0 && points[i - 1].inlier;
    const int from = previous;
    previous = bin;
    if (!after_inlier) continue;
    // The shorter way round from the previous sample's bin.
    int step = bin - from;
    if (step > kCoverageBins / 2) step -= kCoverageBins;
    if (step < -kCoverageBins / 2) step += kCoverageBins;
    for (int k = 1; k < std::abs(step); ++k) {
      const int b = (from + (step > 0 ? k : -k) + kCoverageBins) % kCoverageBins;
      seen[static_cast<std::size_t>(b)] = true;
    }
  }
  return static_cast<float>(std::count(seen.begin(), seen.end(), true)) / kCoverageBins;
}

// The point of the ellipse at `phi` round its centre in its own axes (turn_bin()'s angle); co, si
// as there.
cv::Point2f point_at(const Fit& fit, float co, float si, float phi) {
  const float u = fit.semi_a * std::cos(phi), v = fit.semi_b * std::sin(phi);
  return {fit.ellipse.cx + u * co - v * si, fit.ellipse.cy + u * si + v * co};
}

// The share of the ellipse's turn (kCoverageBins round it, as coverage() counts) whose points
// lie inside the frame; all of it when the frame is unknown (empty).
float in_frame_share(const Fit& fit, cv::Size frame) {
  if (frame.empty()) return 1;
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  int inside = 0;
  for (int b = 0; b < kCoverageBins; ++b) {
    const float phi = (static_cast<float>(b) + 0.5f) / kCoverageBins * 2 * std::numbers::pi_v<float> - std::numbers::pi_v<float>;
    const cv::Point2f q = point_at(fit, co, si, phi);
    inside += q.x >= 0 && q.y >= 0 && q.x < static_cast<float>(frame.width) && q.y < static_cast<float>(frame.height);
  }
  return static_cast<float>(inside) / kCoverageBins;
}

// The turn an ellipse's points must cover: kMinCoverage, less when the frame cuts the ellipse,
// down to `least`.
float required_coverage(const Fit& fit, cv::Size frame, float least = kMinCutCoverage) {
  return std::max(least, std::min(kMinCoverage, kFrameCoverShare * in_frame_share(fit, frame)));
}

int root(std::vector<int>& parent, int i) {
  while (parent[static_cast<std::size_t>(i)] != i) {
    parent[static_cast<std::size_t>(i)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(i)])];
    i = parent[static_cast<std::size_t>(i)];
  }
  return i;
}

// The same count of points for every piece, so that a long straight piece linked into a chain
// (the halfway line beside the circle) weighs no more than one arc piece and drops out as an
// outlier.
void add_samples(const Marking& m, std::vector<Point>& points) {
  for (int k = 0; k <= kSamplesPerPiece - 1; ++k) {
    const float t = static_cast<float>(k) / static_cast<float>(kSamplesPerPiece - 1);
    points.push_back({m.x0 + t * (m.x1 - m.x0), m.y0 + t * (m.y1 - m.y0), 1});
  }
}

// Fits the points, then again without those far off the fit (a straight piece linked into the
// chain pulls the first fit away: the cut starts loose and tightens over the rounds), and checks
// that they lie on the ellipse; its coverage, or 0 when it is no circle's image.
float fit_and_check(std::vector<Point>& points, float tolerance, Fit& fit, cv::Size frame) {
  if (!solve_conic(points, fit)) return 0;
  for (const float cut : {6.f, 4.f, 2.f, 2.f}) {
    for (Point& p : points) p.inlier = distance(fit, p.x, p.y) <= cut * tolerance;
    if (!solve_conic(points, fit)) return 0;
  }
  if (!to_ellipse(fit)) return 0;
  int inliers = 0, close = 0;
  for (Point& p : points) {
    const float d = distance(fit, p.x, p.y);
    p.inlier = d <= 2 * tolerance;
    inliers += p.inlier;
    close += d <= tolerance;
  }
  // Most points on it (the median within the tolerance), and few far off.
  if (2 * close < static_cast<int>(points.size()) || 4 * inliers < 3 * static_cast<int>(points.size())) return 0;
  const float share = coverage(points, fit);
  return share >= required_coverage(fit, frame) ? share : 0;
}

// Whether piece `m` lies along the fitted ellipse: its samples within twice the tolerance and
// its direction within 20 degrees of the tangent there (a line crossing the ellipse does not).
bool along(const Fit& fit, const Marking& m, float tolerance) {
  for (int k = 0; k < kSamplesPerPiece; ++k) {
    const float t = static_cast<float>(k) / static_cast<float>(kSamplesPerPiece - 1);
    if (distance(fit, m.x0 + t * (m.x1 - m.x0), m.y0 + t * (m.y1 - m.y0)) > 2 * tolerance) return false;
  }
  const ConicPoint c = conic_point(fit, (m.x0 + m.x1) / 2, (m.y0 + m.y1) / 2);
  const double dx = m.x1 - m.x0, dy = m.y1 - m.y0;
  const double norm = std::sqrt((c.gu * c.gu + c.gv * c.gv) * (dx * dx + dy * dy));
  return norm > 0 && std::abs(c.gu * dx + c.gv * dy) <= kMaxTangentSin * norm;
}

// Marks in `support` which of the `longest` longest pieces (work.order) lie along `fit` and
// gathers their samples; their count.
int gather_support(std::span<const Marking> pieces, const Fit& fit, float tolerance, std::size_t longest,
                   CircleWorkspace& work) {
  work.points.clear();
  int count = 0;
  for (std::size_t k = 0; k < longest; ++k) {
    const auto i = static_cast<std::size_t>(work.order[k]);
    work.support[i] = along(fit, pieces[i], tolerance);
    if (work.support[i]) add_samples(pieces[i], work.points), ++count;
  }
  return count;
}

// The hypotheses of pairs: every pair of the longest pieces, fitted with axes along the image's
// (the camera's roll is small; the general fit on the support lifts it), scored by the turn its
// support covers. A circle cut into pieces that do not chain (a flat ellipse, a far circle, one
// drawn in faint paint) is found from any two of its pieces. Returns the best ellipse's share
// (0: none) and leaves its pieces in `work.support`.
float fit_from_pairs(std::span<const Marking> pieces, CircleWorkspace& work, Fit& best, cv::Size frame) {
  const std::size_t n = pieces.size();
  work.order.resize(n);
  for (std::size_t i = 0; i < n; ++i) work.order[i] = static_cast<int>(i);
  const std::size_t m = std::min(n, kMaxPairPieces);
  // A piece of no finite length sorts last (NaN would break the ordering).
  const auto key = [&](int i) {
    const float l = length(pieces[static_cast<std::size_t>(i)]);
    return std::isfinite(l) ? l : -1.f;
  };
  std::partial_sort(work.order.begin(), work.order.begin() + static_cast<std::ptrdiff_t>(m), work.order.end(),
                    [&](int a, int b) { return key(a) > key(b); });
  work.support.assign(n, 0);
  float best_share = 0;
  int best_count = 0, best_i = -1, best_j = -1;
  float best_roll = 0;
  const auto tolerance_of = [&](int i, int j) {
    return tolerance_of_widths(pieces[static_cast<std::size_t>(i)].width + pieces[static_cast<std::size_t>(j)].width, 2);
  };
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = i + 1; j < m; ++j) {
      const float tolerance = tolerance_of(work.order[i], work.order[j]);
      work.points.clear();
      add_samples(pieces[static_cast<std::size_t>(work.order[i])], work.points);
      add_samples(pieces[static_cast<std::size_t>(work.order[j])], work.points);
      for (int r = -kRollSteps; r <= kRollSteps; ++r) {
        const float roll = static_cast<float>(r) * kRollStepDeg * std::numbers::pi_v<float> / 180;
        Fit fit;
        if (!fit_conic(work.points, fit, true, roll)) continue;
        // gather_support() reuses work.points: the pair's samples are put back after.
        const int count = gather_support(pieces, fit, tolerance, m, work);
        const float share = count < kMinSupport ? 0 : coverage(work.points, fit);
        if (share > 0 && (share > best_share || (share == best_share && count > best_count)))
          best_share = share, best_count = count, best_i = work.order[i], best_j = work.order[j], best_roll = roll;
        work.points.clear();
        add_samples(pieces[static_cast<std::size_t>(work.order[i])], work.points);
        add_samples(pieces[static_cast<std::size_t>(work.order[j])], work.points);
      }
    }
  }
  if (best_i < 0) return 0;
  // The best pair's support, fitted in full; its support again, and once more.
  const float tolerance = tolerance_of(best_i, best_j);
  work.points.clear();
  add_samples(pieces[static_cast<std::size_t>(best_i)], work.points);
  add_samples(pieces[static_cast<std::size_t>(best_j)], work.points);
  if (!fit_conic(work.points, best, true, best_roll)) return 0;
  float share = 0;
  for (int round = 0; round < 2; ++round) {
    if (gather_support(pieces, best, tolerance, n, work) < kMinSupport) return 0;
    Fit refined;
    share = fit_and_check(work.points, tolerance, refined, frame);
    if (share <= 0) return 0;
    best = refined;
  }
  return gather_support(pieces, best, tolerance, n, work) < kMinSupport ? 0 : share;
}

// The frame read across an ellipse at 72 points round it: kReadSteps, each `half` px either way
// along the ellipse's normal (read_half()).
constexpr int kReadSteps = 72;
constexpr int kMaxHalf = 31;
int read_half(float tolerance) { return std::min(kMaxHalf, static_cast<int>(std::ceil(std::max(4.f, 1.5f * tolerance)))); }
struct Across {
  float x = 0, y = 0, nx = 0, ny = 0;  // the ellipse's point and its unit normal
  std::array<const std::uint8_t*, 2 * kMaxHalf + 1> pixels{};  // from -half to half along the normal
  int lo = 0, hi = 0;  // the least and the most R + G + B among them
};
// Step k round the ellipse (co, si: of fit.theta); false when its point is far off any frame, its
// normal undefined, or its pixels leave the frame.
bool read_across(const cv::Mat& bgr, const Fit& fit, float co, float si, int k, int half, Across& a) {
  const float phi = -std::numbers::pi_v<float> + (static_cast<float>(k) + 0.5f) * 2 * std::numbers::pi_v<float> / kReadSteps;
  const auto [x, y] = point_at(fit, co, si, phi);
  if (!(std::abs(x) < 1e6f && std::abs(y) < 1e6f)) return false;  // far off any frame (or NaN)
  // The normal: the implicit function's gradient, in the ellipse's axes turned back.
  const float gx = std::cos(phi) / fit.semi_a, gy = std::sin(phi) / fit.semi_b;
  const float nx = gx * co - gy * si, ny = gx * si + gy * co, n = std::hypot(nx, ny);
  if (!(n > 0)) return false;
  a.x = x, a.y = y, a.nx = nx / n, a.ny = ny / n;
  a.lo = 1 << 30, a.hi = 0;
  for (int t = -half; t <= half; ++t) {
    const int px = static_cast<int>(std::lround(x + static_cast<float>(t) * a.nx));
    const int py = static_cast<int>(std::lround(y + static_cast<float>(t) * a.ny));
    if (px < 0 || py < 0 || px >= bgr.cols || py >= bgr.rows) return false;
    const std::uint8_t* q = bgr.ptr<std::uint8_t>(py) + 3 * px;
    a.pixels[static_cast<std::size_t>(t + half)] = q;
    const int v = q[0] + q[1] + q[2];
    a.lo = std::min(a.lo, v), a.hi = std::max(a.hi, v);
  }
  return true;
}
constexpr int kPaintStep = 30;  // R + G + B: less between the darkest and the brightest is no paint to see

using TurnBins = std::array<bool, kCoverageBins>;

// The bins of the turn (coverage()'s) that the inliers among `points` lie in.
TurnBins bins_of(const std::vector<Point>& points, const Fit& fit) {
  TurnBins seen{};
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  for (const Point& p : points)
    if (p.inlier) seen[static_cast<std::size_t>(turn_bin(fit, co, si, p))] = true;
  return seen;
}

// The paint's centre across the fitted ellipse, read in the frame, into work.refined: at 72
// points round it, on the bins of the turn `seen` (so no point is read where the circle is out
// of the frame or behind a robot), the middle of the pixels brighter than half-way from the
// darkest to the brightest within a few px along the normal. Only the points within `reach` px
// of the ellipse when it is given.
void read_paint(const cv::Mat& bgr, float tolerance, const TurnBins& seen, CircleWorkspace& work, const Fit& fit,
                float reach = std::numeric_limits<float>::infinity()) {
  const int half = read_half(tolerance);
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  std::vector<Point>& refined = work.refined;
  refined.clear();
  Across a;
  for (int k = 0; k < kReadSteps; ++k) {
    if (!seen[static_cast<std::size_t>(k * kCoverageBins / kReadSteps)]) continue;
    if (!read_across(bgr, fit, co, si, k, half, a) || a.hi - a.lo < kPaintStep) continue;
    const float level = 0.5f * static_cast<float>(a.lo + a.hi);
    float sum = 0, weight = 0;
    for (int t = -half; t <= half; ++t) {
      const std::uint8_t* q = a.pixels[static_cast<std::size_t>(t + half)];
      const float v = static_cast<float>(q[0] + q[1] + q[2]) - level;
      if (v > 0) sum += v * static_cast<float>(t), weight += v;
    }
    if (!(weight > 0)) continue;
    const float offset = sum / weight;
    if (std::abs(offset) <= reach) refined.push_back({a.x + offset * a.nx, a.y + offset * a.ny, 1});
  }
}
constexpr std::size_t kMinPaintPoints = 12;
// The refit on the paint follows it round the ellipse: each round also reads one bin beyond
// either end of the turn already read, and keeps the paint found there close to the ellipse.
constexpr int kFollowRounds = 6;

// The ellipse refitted to the paint read across it (read_paint()) by `refit` (paint, fit: true
// when it replaced `fit`). A piece is a chord or a tangent of the curve, so the first fit lies
// off the paint near a flat ellipse's sharp ends; the paint does not. And the pieces' ellipse
// is least sure where they end: the paint, followed a bin at a time past their ends, pins down
// the part of the ellipse they do not show.
template <typename Refit>
void follow_paint(const cv::Mat& bgr, float tolerance, CircleWorkspace& work, Fit& fit, Refit refit) {
  TurnBins seen = bins_of(work.points, fit);
  for (int round = 0; round <= kFollowRounds; ++round) {
    read_paint(bgr, tolerance, seen, work, fit, round == 0 ? std::numeric_limits<float>::infinity() : tolerance + 1);
    if (work.refined.size() < kMinPaintPoints || !refit(std::as_const(work.refined), fit)) return;
    // The bins the paint was found in, under the refit, and one beyond each.
    const TurnBins found = bins_of(work.refined, fit);
    for (int b = 0; b < kCoverageBins; ++b)
      seen[static_cast<std::size_t>(b)] = found[static_cast<std::size_t>(b)] ||
                                          found[static_cast<std::size_t>((b + 1) % kCoverageBins)] ||
                                          found[static_cast<std::size_t>((b + kCoverageBins - 1) % kCoverageBins)];
  }
}

// The image conic refit: an ellipse most of the paint's points lie on replaces `fit`.
bool refit_in_image(const std::vector<Point>& paint, float tolerance, Fit& fit) {
  Fit candidate;
  if (!fit_conic(paint, candidate) || !most_within(candidate, paint, tolerance)) return false;
  fit = candidate;
  return true;
}

// The share of the ellipse's points inside the frame (72 round it) where the frame shows bare
// turf across it: every pixel within a few px along the normal in the field colour, and no
// brighter stripe among them. A circle's image lies on paint wherever the frame shows it, save
// where a robot or a person hides it (no field colour there); an ellipse fitted to one arc and a
// stray piece runs over bare turf elsewhere.
float bare_turf_share(const cv::Mat& bgr, const FieldPixel& pixel, float tolerance, const Fit& fit) {
  const int half = read_half(tolerance);
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  int seen = 0, bare = 0;
  Across a;
  for (int k = 0; k < kReadSteps; ++k) {
    if (!read_across(bgr, fit, co, si, k, half, a)) continue;
    ++seen;
    const auto end = a.pixels.begin() + 2 * half + 1;
    bare += a.hi - a.lo < kPaintStep && std::all_of(a.pixels.begin(), end, [&](const std::uint8_t* q) { return pixel.field(q); });
  }
  return seen > 0 ? static_cast<float>(bare) / static_cast<float>(seen) : 0.f;
}

// The chains' ellipse: pieces that chain by small bends, the best seed of one chain or two, and
// every other chain that joins it; its share of the turn (0: none) into `fit`, its pieces in
// work.on_ellipse.
float fit_from_chains(std::span<const Marking> pieces, CircleWorkspace& work, Fit& fit, cv::Size frame) {
  const std::size_t n = pieces.size();
  work.on_ellipse.assign(n, 0);
  work.parent.resize(n);
  work.chain_size.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) work.parent[i] = static_cast<int>(i);
  for (std::size_t i = 0; i < n; ++i) {
    const Marking& a = pieces[i];
    const float la = length(a);
    if (!(la > 0)) continue;
    for (std::size_t j = i + 1; j < n; ++j) {
      const Marking& b = pieces[j];
      const float lb = length(b);
      if (!(lb > 0)) continue;
      const float cos = std::abs(((a.x1 - a.x0) * (b.x1 - b.x0) + (a.y1 - a.y0) * (b.y1 - b.y0)) / (la * lb));
      if (cos > kMinBendCos || cos < kMaxBendCos) continue;
      const float link = kLinkWidths * std::max(a.width, b.width) + kLinkPx;
      const float gap = std::min({std::hypot(a.x0 - b.x0, a.y0 - b.y0), std::hypot(a.x0 - b.x1, a.y0 - b.y1),
                                  std::hypot(a.x1 - b.x0, a.y1 - b.y0), std::hypot(a.x1 - b.x1, a.y1 - b.y1)});
      if (gap <= link) work.parent[static_cast<std::size_t>(root(work.parent, static_cast<int>(i)))] =
          root(work.parent, static_cast<int>(j));
    }
  }
  for (std::size_t i = 0; i < n; ++i) ++work.chain_size[static_cast<std::size_t>(root(work.parent, static_cast<int>(i)))];

  const auto tolerance_of = [&](int chain) {
    float sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (root(work.parent, static_cast<int>(i)) == chain) sum += pieces[i].width, ++count;
    return tolerance_of_widths(sum, count);
  };
  // The seed: one chain of at least kMinChain pieces, or two chains of at least two each (a flat
  // ellipse's far and near arcs, which do not chain round its sharply bending ends).
  const auto add_chain = [&](int chain) {
    for (std::size_t i = 0; i < n; ++i)
      if (root(work.parent, static_cast<int>(i)) == chain) add_samples(pieces[i], work.points);
  };
  int best_chain = -1, best_partner = -1;
  float best_share = 0;
  for (std::size_t r = 0; r < n; ++r) {
    if (work.chain_size[r] < 2) continue;
    for (std::size_t q = r; q < n; ++q) {
      const bool alone = q == r;
      if (alone ? work.chain_size[r] < kMinChain : work.chain_size[q] < 2) continue;
      work.points.clear();
      add_chain(static_cast<int>(r));
      if (!alone) add_chain(static_cast<int>(q));
      Fit fit;
      const float share = fit_and_check(work.points, tolerance_of(static_cast<int>(r)), fit, frame);
      if (share > best_share) best_share = share, best_chain = static_cast<int>(r), best_partner = alone ? -1 : static_cast<int>(q);
    }
  }
  // The seed's ellipse, then every other chain whose points lie on it with the seed's (the circle
  // cut by the halfway line or a robot is several chains): each joins when the fit of both still
  // passes and covers more of the turn.
  float share = 0;
  if (best_chain >= 0) {
    const float tolerance = tolerance_of(best_chain);
    work.points.clear();
    for (std::size_t i = 0; i < n; ++i) {
      const int chain = root(work.parent, static_cast<int>(i));
      if (chain == best_chain || chain == best_partner) add_samples(pieces[i], work.points), work.on_ellipse[i] = 1;
    }
    share = fit_and_check(work.points, tolerance, fit, frame);
    for (std::size_t r = 0; share > 0 && r < n; ++r) {
      if (static_cast<int>(r) == best_chain || static_cast<int>(r) == best_partner || work.chain_size[r] == 0) continue;
      const std::size_t before = work.points.size();
      for (std::size_t i = 0; i < n; ++i)
        if (root(work.parent, static_cast<int>(i)) == static_cast<int>(r)) add_samples(pieces[i], work.points);
      for (Point& p : work.points) p.inlier = 1;
      Fit joined;
      const float joined_share = fit_and_check(work.points, tolerance, joined, frame);
      if (joined_share > share) {
        fit = joined, share = joined_share;
        for (std::size_t i = 0; i < n; ++i)
          if (root(work.parent, static_cast<int>(i)) == static_cast<int>(r)) work.on_ellipse[i] = 1;
      } else {
        work.points.resize(before);
      }
    }
  }
  return share;
}

// A candidate ellipse and its pieces (flags per piece, into a workspace vector).
struct Candidate {
  Fit fit;
  float share = 0;
  const std::vector<std::uint8_t>* on = nullptr;
};

// Whether the frame confirms `c`: refitted to the paint (on the turf when `camera` is given, else
// as an image conic), and not over bare turf; its ellipse into `out` and its pieces into
// work.on_ellipse when it is kept.
bool accept(const Candidate& c, std::span<const Marking> pieces, const cv::Mat& bgr, const std::optional<Rgb>& field,
            const GroundCamera* camera, double radius_m, CircleWorkspace& work, std::vector<MarkingEllipse>& out) {
  if (c.share <= 0) return false;
  Fit candidate = c.fit;
  const std::vector<std::uint8_t>& on = *c.on;
  if (!bgr.empty() && bgr.type() == CV_8UC3) {
    // The turn the ellipse's pieces cover, and their tolerance.
    work.points.clear();
    float width = 0;
    int count = 0;
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (on[i]) add_samples(pieces[i], work.points), width += pieces[i].width, ++count;
    const float tolerance = tolerance_of_widths(width, count);
    // The paint's points refine the circle and the pose on the turf when the camera is given.
    if (count > 0)
      follow_paint(bgr, tolerance, work, candidate, [&](const std::vector<Point>& paint, Fit& fit) {
        return camera ? refit_on_ground(paint, *camera, radius_m, tolerance, work, fit)
                      : refit_in_image(paint, tolerance, fit);
      });
    if (field && bare_turf_share(bgr, FieldPixel(*field, FieldBoundaryParams{}), tolerance, candidate) > kMaxBareTurf)
      return false;
  }
  if (&on != &work.on_ellipse) work.on_ellipse = on;
  out.push_back(candidate.ellipse);
  out.back().confidence = c.share;
  return true;
}

}  // namespace

void find_centre_circle(std::span<const Marking> pieces, CircleWorkspace& work, std::vector<MarkingEllipse>& out,
                        const cv::Mat& bgr, const std::optional<Rgb>& field, const std::optional<GroundCamera>& camera,
                        double radius_m) {
  out.clear();
  const cv::Size frame = bgr.empty() ? cv::Size() : bgr.size();
  // The circle on the turf first when the camera is known; then the chains' ellipse and the
  // pairs', the one covering more of the turn first: the first the frame confirms is the circle.
  if (camera) {
    Candidate turf{{}, 0, &work.ground_support};
    turf.share = fit_on_ground(pieces, *camera, radius_m, work, turf.fit);
    if (turf.share >= required_coverage(turf.fit, frame, kMinGroundCoverage) &&
        accept(turf, pieces, bgr, field, &*camera, radius_m, work, out))
      return;
  }
  // The chains' pieces stay in work.on_ellipse, the pairs' in work.support, until one is kept.
  Candidate chained{{}, 0, &work.on_ellipse}, paired{{}, 0, &work.support};
  chained.share = fit_from_chains(pieces, work, chained.fit, frame);
  paired.share = fit_from_pairs(pieces, work, paired.fit, frame);
  const bool pairs_first = paired.share > chained.share;
  for (const Candidate* c : {pairs_first ? &paired : &chained, pairs_first ? &chained : &paired})
    if (accept(*c, pieces, bgr, field, nullptr, radius_m, work, out)) return;
  std::fill(work.on_ellipse.begin(), work.on_ellipse.end(), std::uint8_t{0});
}

}  // namespace fieldlines
