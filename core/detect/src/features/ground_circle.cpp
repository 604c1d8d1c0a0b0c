#include "ground_circle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <opencv2/core.hpp>  // Matx::solve is defined in operations.hpp

namespace fieldlines {
namespace {

using GroundPiece = CircleWorkspace::GroundPiece;

constexpr double kPi = std::numbers::pi;
constexpr double kSeedTolerance = 0.25;  // of the radius, for the seed's support: the pose may be off
constexpr double kTolerance = 0.125;     // of the radius, for the refined circle's
constexpr double kMaxTangentSin = 0.342;  // sin(20 degrees): a piece runs along the circle
constexpr double kMaxChord = 2.6;         // radii: longer is no chord, even through a pose a little off
constexpr double kPoseSigma = 2 * kPi / 180;
constexpr double kRadiusSigma = 0.1;  // of the radius
constexpr double kPixelSigma = 3;     // px: a piece is a chord, its middle inside the curve
constexpr int kRounds = 8;
constexpr int kMinSupport = 2;  // pieces
constexpr int kBins = 36;
constexpr int kOutline = 36;  // points of the circle projected for its image ellipse

// Each piece's samples on the turf through `projection`.
void to_ground(std::span<const Marking> pieces, const GroundProjection& projection, double radius,
               std::vector<GroundPiece>& out) {
  out.resize(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Marking& m = pieces[i];
    GroundPiece& g = out[i];
    g.valid = true;
    for (int k = 0; k < 3 && g.valid; ++k) {
      const double t = 0.5 * k;
      const auto p = projection.to_ground(m.x0 + t * (m.x1 - m.x0), m.y0 + t * (m.y1 - m.y0));
      if (p) g.at[static_cast<std::size_t>(k)] = *p;
      g.valid = p.has_value();
    }
    const double chord = cv::norm(g.at[2] - g.at[0]);
    g.valid = g.valid && chord > 0 && chord <= kMaxChord * radius;
  }
}

// Whether piece `g` runs along the circle (centre c, radius r): its samples within `tolerance`
// of it, its chord within 20 degrees of the tangent at its middle, and its middle no further
// inside than the ends by more than an eighth of the radius (a piece is a short chord: a long
// one, a straight line's, spans much of the turn from ends near the circle; this holds however
// far off the pose moves the three).
bool along(const GroundPiece& g, cv::Point2d c, double r, double tolerance) {
  if (!g.valid) return false;
  std::array<double, 3> d{};
  for (std::size_t k = 0; k < 3; ++k) {
    d[k] = cv::norm(g.at[k] - c);
    if (std::abs(d[k] - r) > tolerance) return false;
  }
  if (0.5 * (d[0] + d[2]) - d[1] > kTolerance * r) return false;
  const cv::Point2d chord = g.at[2] - g.at[0], spoke = g.at[1] - c;
  return std::abs(chord.dot(spoke)) <= kMaxTangentSin * cv::norm(chord) * cv::norm(spoke);
}

// Marks the pieces along the circle in `support`; the share of its turn they cover (each piece
// from one end to the other, seen from the centre) and their count.
struct Cover {
  float share = 0;
  int pieces = 0;
};
Cover cover(std::span<const GroundPiece> ground, cv::Point2d c, double r, double tolerance,
            std::vector<std::uint8_t>& support) {
  std::array<bool, kBins> seen{};
  const auto bin = [](double angle) {
    return (static_cast<int>(std::floor((angle + kPi) / (2 * kPi) * kBins)) % kBins + kBins) % kBins;
  };
  Cover out;
  support.assign(ground.size(), 0);
  for (std::size_t i = 0; i < ground.size(); ++i) {
    if (!along(ground[i], c, r, tolerance)) continue;
    support[i] = 1;
    ++out.pieces;
    const double a0 = std::atan2(ground[i].at[0].y - c.y, ground[i].at[0].x - c.x);
    const double a1 = std::atan2(ground[i].at[2].y - c.y, ground[i].at[2].x - c.x);
    const double turn = std::remainder(a1 - a0, 2 * kPi);
    const int steps = static_cast<int>(std::ceil(std::abs(turn) / (2 * kPi) * kBins)) + 1;
    for (int k = 0; k <= steps; ++k) seen[static_cast<std::size_t>(bin(a0 + turn * k / steps))] = true;
  }
  out.share = static_cast<float>(std::count(seen.begin(), seen.end(), true)) / kBins;
  return out;
}

// The circle and the pose's correction: centre x, y (m), radius (m), pitch and roll offsets (rad).
using Params = cv::Vec<double, 5>;

// A circle of positive radius, every parameter finite (the refinement can diverge).
bool usable(const Params& p) { return p[2] > 0 && std::isfinite(p[0] + p[1] + p[2] + p[3] + p[4]); }

// Gauss-Newton on the support's samples (work.ground_samples) with the pose and the radius held
// near the given ones; the refined parameters.
Params refine(const GroundCamera& camera, double radius, const std::vector<CircleWorkspace::GroundSample>& samples,
              Params p) {
  constexpr double kStep = 1e-5;  // rad, for the pose's numeric derivatives
  for (int round = 0; round < kRounds; ++round) {
    cv::Matx<double, 5, 5> jtj = cv::Matx<double, 5, 5>::zeros();
    cv::Matx<double, 5, 1> jtr = cv::Matx<double, 5, 1>::zeros();
    const GroundProjection at(camera, p[3], p[4]), pitched(camera, p[3] + kStep, p[4]),
        rolled(camera, p[3], p[4] + kStep);
    const cv::Point2d c(p[0], p[1]);
    const auto residual = [&](const GroundProjection& projection, const CircleWorkspace::GroundSample& s) {
      const auto g = projection.to_ground(s.u, s.v);
      return g ? (cv::norm(*g - c) - p[2]) / (s.scale * kPixelSigma) : std::nan("");
    };
    for (const auto& s : samples) {
      const auto g = at.to_ground(s.u, s.v);
      if (!g) continue;
      const cv::Point2d d = *g - c;
      const double dist = cv::norm(d), w = 1 / (s.scale * kPixelSigma);
      if (!(dist > 0)) continue;
      const double r = (dist - p[2]) * w;
      const double rp = residual(pitched, s), rr = residual(rolled, s);
      if (!std::isfinite(rp) || !std::isfinite(rr)) continue;
      const cv::Matx<double, 5, 1> j(-d.x / dist * w, -d.y / dist * w, -w, (rp - r) / kStep, (rr - r) / kStep);
      jtj += j * j.t();
      jtr += j * r;
    }
    // The priors: the pose's angles near the given ones, the radius near the rules'.
    const std::array<std::pair<int, double>, 3> priors{{{3, kPoseSigma}, {4, kPoseSigma}, {2, kRadiusSigma * radius}}};
    for (const auto& [k, sigma] : priors) {
      const double target = k == 2 ? radius : 0;
      jtj(k, k) += 1 / (sigma * sigma);
      jtr(k) += (p[k] - target) / (sigma * sigma);
    }
    cv::Matx<double, 5, 1> step;
    if (!cv::solve(jtj, jtr, step, cv::DECOMP_CHOLESKY)) break;
    for (int k = 0; k < 5; ++k) p[k] -= step(k);
    if (std::abs(step(0)) + std::abs(step(1)) + std::abs(step(2)) < 1e-6 * radius) break;
  }
  return p;
}

// Image point (u, v) as a sample with its scale on the turf (metres per px); none above the horizon.
void add_sample(const GroundProjection& projection, double u, double v, std::vector<CircleWorkspace::GroundSample>& out) {
  const auto g = projection.to_ground(u, v), gu = projection.to_ground(u + 1, v), gv = projection.to_ground(u, v + 1);
  if (!g || !gu || !gv) return;
  const double scale = 0.5 * (cv::norm(*gu - *g) + cv::norm(*gv - *g));
  if (scale > 0 && std::isfinite(scale)) out.push_back({u, v, scale});
}

// The samples of the pieces in `support`.
void gather_samples(std::span<const Marking> pieces, const GroundProjection& projection,
                    const std::vector<std::uint8_t>& support, std::vector<CircleWorkspace::GroundSample>& out) {
  out.clear();
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (!support[i]) continue;
    const Marking& m = pieces[i];
    add_sample(projection, m.x0, m.y0, out);
    add_sample(projection, m.x1, m.y1, out);
  }
}

// The image ellipse of the circle `p` through `camera` turned by p's pose offsets: its points
// fitted as a conic (work.points); false when it passes behind the camera.
bool image_ellipse(const GroundCamera& camera, const Params& p, CircleWorkspace& work, Fit& fit) {
  const GroundProjection projection(camera, p[3], p[4]);
  work.points.clear();
  for (int k = 0; k < kOutline; ++k) {
    const double a = 2 * kPi * k / kOutline;
    const auto q = projection.to_image({p[0] + p[2] * std::cos(a), p[1] + p[2] * std::sin(a)});
    if (!q) return false;
    work.points.push_back({static_cast<float>(q->x), static_cast<float>(q->y), 1});
  }
  return fit_conic(work.points, fit);
}

}  // namespace

float fit_on_ground(std::span<const Marking> pieces, const GroundCamera& camera, double radius, CircleWorkspace& work,
                    Fit& fit) {
  const GroundProjection given(camera);
  to_ground(pieces, given, radius, work.ground);
  // The seed: of the two centres each chord allows, the one whose support covers most of the turn.
  Cover best;
  cv::Point2d seed;
  for (const GroundPiece& g : work.ground) {
    if (!g.valid) continue;
    const cv::Point2d mid = 0.5 * (g.at[0] + g.at[2]), chord = g.at[2] - g.at[0];
    const double half = 0.5 * cv::norm(chord);
    if (!(half < radius)) continue;
    const cv::Point2d normal = cv::Point2d(-chord.y, chord.x) * (1 / (2 * half));
    const double reach = std::sqrt(radius * radius - half * half);
    for (const double side : {-1.0, 1.0}) {
      const cv::Point2d c = mid + side * reach * normal;
      const Cover here = cover(work.ground, c, radius, kSeedTolerance * radius, work.ground_support);
      if (here.share > best.share || (here.share == best.share && here.pieces > best.pieces)) best = here, seed = c;
    }
  }
  if (best.pieces < kMinSupport) return 0;
  // Refined on the seed's support, then on the pieces along the refined circle.
  Params p(seed.x, seed.y, radius, 0, 0);
  for (const double tolerance : {kSeedTolerance, kTolerance}) {
    cover(work.ground, {p[0], p[1]}, p[2], tolerance * radius, work.ground_support);
    gather_samples(pieces, GroundProjection(camera, p[3], p[4]), work.ground_support, work.ground_samples);
    p = refine(camera, radius, work.ground_samples, p);
    if (!usable(p)) return 0;
    to_ground(pieces, GroundProjection(camera, p[3], p[4]), radius, work.ground);
  }
  const Cover found = cover(work.ground, {p[0], p[1]}, p[2], kTolerance * radius, work.ground_support);
  if (found.pieces < kMinSupport) return 0;
  for (int k = 0; k < 5; ++k) work.ground_fit[static_cast<std::size_t>(k)] = p[k];
  return image_ellipse(camera, p, work, fit) ? found.share : 0;
}

bool refit_on_ground(std::span<const CircleWorkspace::Point> paint, const GroundCamera& camera, double radius,
                     float tolerance, CircleWorkspace& work, Fit& fit) {
  const auto& g = work.ground_fit;
  Params p(g[0], g[1], g[2], g[3], g[4]);
  const GroundProjection at(camera, p[3], p[4]);
  work.ground_samples.clear();
  for (const CircleWorkspace::Point& q : paint) add_sample(at, q.x, q.y, work.ground_samples);
  p = refine(camera, radius, work.ground_samples, p);
  Fit candidate;
  if (!usable(p) || !image_ellipse(camera, p, work, candidate) || !most_within(candidate, paint, tolerance)) return false;
  for (int k = 0; k < 5; ++k) work.ground_fit[static_cast<std::size_t>(k)] = p[k];
  fit = candidate;
  return true;
}

}  // namespace fieldlines
