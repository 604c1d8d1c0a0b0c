#include "fieldlines/synth/feature_truth.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "fieldlines/synth/camera.hpp"
#include "fieldlines/synth/field.hpp"

namespace fieldlines::synth {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kArmPx = 12;          // an arm is visible when it reaches this far in the frame
constexpr double kSameArmCos = 0.9998;  // cos(~1 degree): the same arm of two lines
constexpr double kStraightCos = -0.866;  // cos(150 degrees)
constexpr int kCircleSamples = 720;

struct WorldJunction {
  Vector2d at;
  std::vector<Vector2d> arms;  // unit directions on the ground
};

void add_arm(WorldJunction& j, const Vector2d& dir) {
  for (const Vector2d& a : j.arms)
    if (a.dot(dir) > kSameArmCos) return;
  j.arms.push_back(dir);
}

std::vector<WorldJunction> world_junctions(const FieldModel& field) {
  std::vector<WorldJunction> out;
  const double eps = field.line_width;
  for (std::size_t i = 0; i < field.lines.size(); ++i) {
    const PaintedLine& a = field.lines[i];
    if (a.arc) continue;
    for (std::size_t k = i + 1; k < field.lines.size(); ++k) {
      const PaintedLine& b = field.lines[k];
      if (b.arc) continue;
      const Vector2d da = (a.b - a.a).normalized(), db = (b.b - b.a).normalized();
      const double cross = da.x() * db.y() - da.y() * db.x();
      if (std::abs(cross) < 1e-6) continue;
      const Vector2d w = b.a - a.a;
      const double t = (w.x() * db.y() - w.y() * db.x()) / cross, s = (w.x() * da.y() - w.y() * da.x()) / cross;
      const double la = a.length(), lb = b.length();
      if (t < -eps || t > la + eps || s < -eps || s > lb + eps) continue;
      const Vector2d at = a.a + t * da;
      auto j = std::find_if(out.begin(), out.end(), [&](const WorldJunction& o) { return (o.at - at).norm() < eps; });
      if (j == out.end()) j = out.insert(out.end(), WorldJunction{at, {}});
      if (t > eps) add_arm(*j, -da);
      if (la - t > eps) add_arm(*j, da);
      if (s > eps) add_arm(*j, -db);
      if (lb - s > eps) add_arm(*j, db);
    }
  }
  return out;
}

bool inside(const Vector2d& p, const Intrinsics& k) {
  return p.x() >= -0.5 && p.y() >= -0.5 && p.x() < k.width - 0.5 && p.y() < k.height - 0.5;
}

double segment_distance(float px, float py, const TruthPoint& a, const TruthPoint& b) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  const double t = len2 > 0 ? std::clamp(((px - a.x) * dx + (py - a.y) * dy) / len2, 0.0, 1.0) : 0.0;
  return std::hypot(px - (a.x + t * dx), py - (a.y + t * dy));
}

// The distance from (x, y) to the nearest visible polyline of `truth` (named `name`, or any
// marking when empty), and that polyline's width there.
double nearest_paint(const GroundTruth& truth, float x, float y, std::string_view name, float& width) {
  double best = 1e9;
  for (const TruthFeature& f : truth.features) {
    if (f.label != Label::Marking || (!name.empty() && f.name != name)) continue;
    for (std::size_t i = 1; i < f.points.size(); ++i) {
      const double d = segment_distance(x, y, f.points[i - 1], f.points[i]);
      if (d < best) best = d, width = 0.5f * (f.points[i - 1].width + f.points[i].width);
    }
  }
  return best;
}

float heading(const Vector2d& v) {
  double h = std::atan2(v.y(), v.x());
  if (h < 0) h += 2 * std::numbers::pi;
  return static_cast<float>(h >= 2 * std::numbers::pi ? 0 : h);
}

}  // namespace

FeatureTruth feature_truth(const GroundTruth& truth, const cv::Mat& mask, float min_width_px) {
  FeatureTruth out;
  out.carpet_top = carpet_top_rows(truth, mask);
  const FieldModel field = make_field({.scene = truth.scene, .line_width = truth.line_width});
  const Camera camera(truth.intrinsics, truth.pose);
  const Intrinsics& k = truth.intrinsics;
  // Whether a visible painted line lies at (x, y): within 3 px (or its width), at least
  // min_width_px wide there (thinner paint is too thin to see).
  const auto paint_visible_at = [&](float x, float y) {
    float width = 0;
    return nearest_paint(truth, x, y, "", width) <= std::max(3.f, width) && width >= min_width_px;
  };
  for (const WorldJunction& j : world_junctions(field)) {
    const auto centre = camera.project(Vector3d(j.at.x(), j.at.y(), 0));
    if (!centre || !inside(*centre, k)) continue;
    Intersection i{.x = float(centre->x()), .y = float(centre->y()), .confidence = 1};
    if (!paint_visible_at(i.x, i.y)) {  // hidden, or too thin to see
      out.ignored.push_back(i);
      continue;
    }
    for (const Vector2d& arm : j.arms) {
      // Walk along the arm on the ground until it is kArmPx from the centre in the frame.
      for (double s = 0.01; s < 3; s += 0.01) {
        const auto p = camera.project(Vector3d(j.at.x() + s * arm.x(), j.at.y() + s * arm.y(), 0));
        if (!p || !inside(*p, k)) break;
        if ((*p - *centre).norm() >= kArmPx) {
          // An arm shows where its own paint is visible there: at an X of a near line and a
          // crossing line seen edge-on, the centre's paint is the near line's.
          if (paint_visible_at(float(p->x()), float(p->y())) && i.num_rays < 4)
            i.heading_rays[static_cast<std::size_t>(i.num_rays++)] = heading(*p - *centre);
          break;
        }
      }
    }
    const auto dir = [&](int r) {
      const float h = i.heading_rays[static_cast<std::size_t>(r)];
      return Vector2d(std::cos(h), std::sin(h));
    };
    if (i.num_rays < 2 || (i.num_rays == 2 && dir(0).dot(dir(1)) < kStraightCos)) {
      out.ignored.push_back(i);  // cut by the frame's border: a line or less of it shows
      continue;
    }
    // Insertion sort of at most four: std::sort over a prefix of the array trips GCC 12's
    // -Warray-bounds.
    auto& h = i.heading_rays;
    for (std::size_t a = 1; a < static_cast<std::size_t>(i.num_rays); ++a)
      for (std::size_t b = a; b > 0 && h[b - 1] > h[b]; --b) std::swap(h[b - 1], h[b]);
    i.type = i.num_rays == 2 ? JunctionType::L : (i.num_rays == 3 ? JunctionType::T : JunctionType::X);
    out.intersections.push_back(i);
  }
  // Where the centre circle crosses a straight line (the halfway line): not scored either way.
  for (const PaintedLine& c : field.lines) {
    if (!c.arc) continue;
    for (const PaintedLine& l : field.lines) {
      if (l.arc) continue;
      const Vector2d d = (l.b - l.a).normalized(), w = l.a - c.centre;
      const double b = w.dot(d), disc = b * b - (w.squaredNorm() - c.radius * c.radius);
      if (disc < 0) continue;
      for (const double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
        if (t < 0 || t > l.length()) continue;
        const Vector2d g = l.a + t * d;
        const auto p = camera.project(Vector3d(g.x(), g.y(), 0));
        if (p && inside(*p, k)) out.ignored.push_back({.x = float(p->x()), .y = float(p->y())});
      }
    }
  }

  for (const PaintedLine& line : field.lines) {
    if (!line.full_circle()) continue;
    std::vector<cv::Point2f> points;
    int visible = 0;
    for (int n = 0; n < kCircleSamples; ++n) {
      const double s = line.length() * n / kCircleSamples;
      const Vector2d g = line.point(s);
      const auto p = camera.project(Vector3d(g.x(), g.y(), 0));
      if (!p) return out;  // partly behind the camera: no ellipse in the image
      points.emplace_back(float(p->x()), float(p->y()));
      float width = 0;
      if (inside(*p, k) && nearest_paint(truth, float(p->x()), float(p->y()), line.name, width) <= 2 &&
          width >= min_width_px)
        ++visible;
    }
    const cv::RotatedRect r = cv::fitEllipse(points);
    out.circle = TruthCircle{{r.center.x, r.center.y, r.size.width, r.size.height, r.angle, 1},
                             float(visible) / kCircleSamples};
  }
  return out;
}

FeatureScore& FeatureScore::operator+=(const FeatureScore& o) {
  detected += o.detected, truth += o.truth, matched += o.matched, type_correct += o.type_correct;
  circles += o.circles, circles_found += o.circles_found, ellipses += o.ellipses, ellipses_wrong += o.ellipses_wrong;
  boundary_columns += o.boundary_columns, boundary_right += o.boundary_right;
  marking_px += o.marking_px, marking_on_line_px += o.marking_on_line_px;
  return *this;
}

FeatureScore score_features(const GroundTruth& frame, const FeatureTruth& truth, const FieldFeatures& detected,
                            const FeatureScoreParams& params) {
  FeatureScore s = score_features(truth, detected, params);
  // One point per pixel of length along each marking, both ends included.
  for (const Marking& m : detected.markings) {
    const int n = std::max(1, static_cast<int>(std::ceil(std::hypot(m.x1 - m.x0, m.y1 - m.y0))));
    for (int k = 0; k <= n; ++k) {
      const float a = float(k) / float(n), x = m.x0 + a * (m.x1 - m.x0), y = m.y0 + a * (m.y1 - m.y0);
      float width = 0;
      ++s.marking_px;
      s.marking_on_line_px += nearest_paint(frame, x, y, "", width) <= 0.5 * width + params.marking_margin_px;
    }
  }
  return s;
}

std::vector<std::pair<std::size_t, std::size_t>> matched_junctions(const FeatureTruth& truth, const FieldFeatures& detected,
                                                                   const FeatureScoreParams& params) {
  struct Pair {
    double d;
    std::size_t det, tru;
  };
  std::vector<Pair> pairs;
  for (std::size_t a = 0; a < detected.intersections.size(); ++a)
    for (std::size_t b = 0; b < truth.intersections.size(); ++b) {
      const double d = std::hypot(detected.intersections[a].x - truth.intersections[b].x,
                                  detected.intersections[a].y - truth.intersections[b].y);
      if (d <= params.max_distance_px) pairs.push_back({d, a, b});
    }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& x, const Pair& y) { return x.d < y.d; });
  std::vector<char> det_used(detected.intersections.size()), tru_used(truth.intersections.size());
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const Pair& p : pairs) {
    if (det_used[p.det] || tru_used[p.tru]) continue;
    det_used[p.det] = tru_used[p.tru] = 1;
    out.emplace_back(p.det, p.tru);
  }
  return out;
}

FeatureScore score_features(const FeatureTruth& truth, const FieldFeatures& detected, const FeatureScoreParams& params) {
  FeatureScore s;
  const FieldBoundary& boundary = detected.field_boundary;
  for (std::size_t u = 0; u < truth.carpet_top.size(); ++u) {
    if (truth.carpet_top[u] < 0) continue;
    ++s.boundary_columns;
    s.boundary_right += !boundary.empty() &&
                        std::abs(boundary.y_at(float(u)) - truth.carpet_top[u]) <= params.max_boundary_px;
  }
  s.detected = static_cast<long>(detected.intersections.size());
  s.truth = static_cast<long>(truth.intersections.size());
  std::vector<char> det_used(detected.intersections.size());
  for (const auto& [det, tru] : matched_junctions(truth, detected, params)) {
    det_used[det] = 1;
    ++s.matched;
    s.type_correct += detected.intersections[det].type == truth.intersections[tru].type;
  }
  for (std::size_t a = 0; a < detected.intersections.size(); ++a) {
    if (det_used[a]) continue;
    const Intersection& d = detected.intersections[a];
    for (const Intersection& i : truth.ignored)
      if (std::hypot(d.x - i.x, d.y - i.y) <= params.max_distance_px) {
        --s.detected;  // neither right nor wrong
        break;
      }
  }

  s.ellipses = static_cast<long>(detected.ellipses.size());
  const auto found = [&](const MarkingEllipse& e) {
    if (!truth.circle || truth.circle->visible_share <= 0) return false;
    const MarkingEllipse& t = truth.circle->ellipse;
    const double radius = 0.5 * std::sqrt(double(t.width) * t.height);
    return std::hypot(e.cx - t.cx, e.cy - t.cy) <= params.max_centre_error * radius;
  };
  for (const MarkingEllipse& e : detected.ellipses) s.ellipses_wrong += !found(e);
  if (truth.circle && truth.circle->visible_share >= params.min_circle_share) {
    s.circles = 1;
    s.circles_found = std::any_of(detected.ellipses.begin(), detected.ellipses.end(), found) ? 1 : 0;
  }
  return s;
}

}  // namespace fieldlines::synth
