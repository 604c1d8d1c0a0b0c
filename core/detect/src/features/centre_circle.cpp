#include "fieldlines/detect/centre_circle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <opencv2/core.hpp>  // Matx::solve is defined in operations.hpp

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
constexpr float kMinSemiAxisPx = 4;
constexpr float kMaxAxisRatio = 12;  // a circle seen at 5 degrees above the turf

// A conic A u^2 + B uv + C v^2 + D u + E v + F = 0 in coordinates centred on (mx, my) and scaled
// by s (u = (x - mx) / s), and the ellipse it is.
struct Fit {
  double a = 0, b = 0, c = 0, d = 0, e = 0, f = 0;
  double mx = 0, my = 0, s = 1;
  MarkingEllipse ellipse;
  float theta = 0, semi_a = 0, semi_b = 0;  // radians, px
};

float length(const Marking& m) { return std::hypot(m.x1 - m.x0, m.y1 - m.y0); }

// Sampson's first-order distance of (x, y) from the conic, in px.
float distance(const Fit& fit, float x, float y) {
  const double u = (x - fit.mx) / fit.s, v = (y - fit.my) / fit.s;
  const double q = fit.a * u * u + fit.b * u * v + fit.c * v * v + fit.d * u + fit.e * v + fit.f;
  const double gu = 2 * fit.a * u + fit.b * v + fit.d, gv = fit.b * u + 2 * fit.c * v + fit.e;
  const double g = std::hypot(gu, gv);
  return g > 0 ? static_cast<float>(std::abs(q) / g * fit.s) : 1e9f;
}

// Least squares over the points marked inlier; false when they make no ellipse.
bool fit_conic(const std::vector<Point>& points, Fit& fit) {
  double mx = 0, my = 0;
  int n = 0;
  for (const Point& p : points)
    if (p.inlier) mx += p.x, my += p.y, ++n;
  if (n < 6) return false;
  mx /= n, my /= n;
  double spread = 0;
  for (const Point& p : points)
    if (p.inlier) spread += (p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my);
  const double s = std::sqrt(spread / n / 2);
  if (!(s > 1e-3)) return false;
  cv::Matx<double, 5, 5> m = cv::Matx<double, 5, 5>::zeros();
  cv::Matx<double, 5, 1> rhs = cv::Matx<double, 5, 1>::zeros();
  for (const Point& p : points) {
    if (!p.inlier) continue;
    const double u = (p.x - mx) / s, v = (p.y - my) / s;
    const cv::Matx<double, 5, 1> r(u * u - v * v, u * v, u, v, 1);
    m += r * r.t();
    rhs += r * (-v * v);
  }
  if (std::abs(cv::determinant(m)) < 1e-12) return false;
  const cv::Matx<double, 5, 1> x = m.solve(rhs, cv::DECOMP_LU);
  fit = Fit{};
  fit.a = x(0), fit.b = x(1), fit.c = 1 - x(0), fit.d = x(2), fit.e = x(3), fit.f = x(4);
  fit.mx = mx, fit.my = my, fit.s = s;
  if (fit.b * fit.b - 4 * fit.a * fit.c >= 0) return false;  // a parabola or hyperbola
  const double det = 4 * fit.a * fit.c - fit.b * fit.b;
  const double u0 = (fit.b * fit.e - 2 * fit.c * fit.d) / det, v0 = (fit.b * fit.d - 2 * fit.a * fit.e) / det;
  const double f0 = fit.a * u0 * u0 + fit.b * u0 * v0 + fit.c * v0 * v0 + fit.d * u0 + fit.e * v0 + fit.f;
  const double theta = 0.5 * std::atan2(fit.b, fit.a - fit.c);
  const double co = std::cos(theta), si = std::sin(theta);
  const double la = fit.a * co * co + fit.b * co * si + fit.c * si * si;
  const double lb = fit.a * si * si - fit.b * co * si + fit.c * co * co;
  if (!(-f0 / la > 0) || !(-f0 / lb > 0)) return false;  // imaginary
  fit.theta = static_cast<float>(theta);
  fit.semi_a = static_cast<float>(std::sqrt(-f0 / la) * s);
  fit.semi_b = static_cast<float>(std::sqrt(-f0 / lb) * s);
  fit.ellipse = {.cx = static_cast<float>(mx + u0 * s), .cy = static_cast<float>(my + v0 * s),
                 .width = 2 * fit.semi_a, .height = 2 * fit.semi_b,
                 .angle_deg = static_cast<float>(theta * 180 / std::numbers::pi)};
  const float lo = std::min(fit.semi_a, fit.semi_b), hi = std::max(fit.semi_a, fit.semi_b);
  return std::isfinite(hi) && lo >= kMinSemiAxisPx && hi <= kMaxAxisRatio * lo;
}

// The share of the ellipse's turn (seen from its centre, in its own axes) the inliers cover.
float coverage(const std::vector<Point>& points, const Fit& fit) {
  std::array<bool, kCoverageBins> seen{};
  const float co = std::cos(fit.theta), si = std::sin(fit.theta);
  for (const Point& p : points) {
    if (!p.inlier) continue;
    const float dx = p.x - fit.ellipse.cx, dy = p.y - fit.ellipse.cy;
    const float phi = std::atan2((-dx * si + dy * co) / fit.semi_b, (dx * co + dy * si) / fit.semi_a);
    const int bin = static_cast<int>((phi + std::numbers::pi_v<float>) / (2 * std::numbers::pi_v<float>) * kCoverageBins);
    seen[static_cast<std::size_t>(std::clamp(bin, 0, kCoverageBins - 1))] = true;
  }
  return static_cast<float>(std::count(seen.begin(), seen.end(), true)) / kCoverageBins;
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
float fit_and_check(std::vector<Point>& points, float tolerance, Fit& fit) {
  if (!fit_conic(points, fit)) return 0;
  for (const float cut : {6.f, 4.f, 2.f, 2.f}) {
    for (Point& p : points) p.inlier = distance(fit, p.x, p.y) <= cut * tolerance;
    if (!fit_conic(points, fit)) return 0;
  }
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
  return share >= kMinCoverage ? share : 0;
}

}  // namespace

void find_centre_circle(std::span<const Marking> pieces, CircleWorkspace& work, std::vector<MarkingEllipse>& out) {
  out.clear();
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

  // The tolerance of a chain: half its mean line width, at least 2.5 px (a piece is a chord: its
  // middle lies inside the curve).
  const auto tolerance_of = [&](int chain) {
    float sum = 0;
    int count = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (root(work.parent, static_cast<int>(i)) == chain) sum += pieces[i].width, ++count;
    return std::max(2.5f, sum / static_cast<float>(std::max(count, 1)) / 2);
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
      const float share = fit_and_check(work.points, tolerance_of(static_cast<int>(r)), fit);
      if (share > best_share) best_share = share, best_chain = static_cast<int>(r), best_partner = alone ? -1 : static_cast<int>(q);
    }
  }
  if (best_chain < 0) return;

  // The seed's ellipse, then every other chain whose points lie on it with the seed's (the circle
  // cut by the halfway line or a robot is several chains): each joins when the fit of both still
  // passes and covers more of the turn.
  const float tolerance = tolerance_of(best_chain);
  const auto reset = [&] {
    for (Point& p : work.points) p.inlier = 1;
  };
  work.points.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const int chain = root(work.parent, static_cast<int>(i));
    if (chain == best_chain || chain == best_partner) add_samples(pieces[i], work.points), work.on_ellipse[i] = 1;
  }
  Fit fit;
  float share = fit_and_check(work.points, tolerance, fit);
  if (share <= 0) return;
  for (std::size_t r = 0; r < n; ++r) {
    if (static_cast<int>(r) == best_chain || static_cast<int>(r) == best_partner || work.chain_size[r] == 0) continue;
    const std::size_t before = work.points.size();
    for (std::size_t i = 0; i < n; ++i)
      if (root(work.parent, static_cast<int>(i)) == static_cast<int>(r)) add_samples(pieces[i], work.points);
    reset();
    Fit joined;
    const float joined_share = fit_and_check(work.points, tolerance, joined);
    if (joined_share > share) {
      fit = joined, share = joined_share;
      for (std::size_t i = 0; i < n; ++i)
        if (root(work.parent, static_cast<int>(i)) == static_cast<int>(r)) work.on_ellipse[i] = 1;
    } else {
      work.points.resize(before);
    }
  }
  out.push_back(fit.ellipse);
  out.back().confidence = share;
}

}  // namespace fieldlines
