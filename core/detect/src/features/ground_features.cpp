#include "fieldlines/detect/ground_features.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

#include <opencv2/core/matx.hpp>
#include <opencv2/core/types.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180;
constexpr int kCirclePoints = 36;       // on the image ellipse, projected one by one
constexpr int kMinCirclePoints = 24;    // of them on the ground for a circle
constexpr int kCutIterations = 30;      // bisection to where a marking leaves the ground
constexpr double kRayStepPx = 1;        // a ray's direction: its point this far from the centre

// The camera's projection and the same camera turned by one sigma each way in pitch and in
// roll: the spread of a measure across them is its covariance.
class Projections {
 public:
  Projections(const GroundCamera& camera, const GroundFeatureParams& params)
      : centre_(camera),
        turned_{GroundProjection(camera, params.angle_sigma_deg * kRadiansPerDegree, 0),
                GroundProjection(camera, -params.angle_sigma_deg * kRadiansPerDegree, 0),
                GroundProjection(camera, 0, params.angle_sigma_deg * kRadiansPerDegree),
                GroundProjection(camera, 0, -params.angle_sigma_deg * kRadiansPerDegree)},
        max_distance_(params.max_distance_m) {}

  // Pixel (u, v) on the ground through `projection`, or none above the horizon or too far.
  std::optional<cv::Point2d> ground(const GroundProjection& projection, double u, double v) const {
    const auto g = projection.to_ground(u, v);
    if (!g || !(std::hypot(g->x, g->y) <= max_distance_)) return std::nullopt;
    return g;
  }
  std::optional<cv::Point2d> ground(double u, double v) const { return ground(centre_, u, v); }
  const GroundProjection& centre() const { return centre_; }

  // `measure(projection)` (a ground point, or none) with its covariance; none where the
  // camera's own projection gives none. One sigma's displacement per angle is the central
  // difference, one-sided where a turned camera loses the point; lost both ways, the point is
  // as uncertain as the range.
  template <class Measure>
  std::optional<GroundPoint> point(const Measure& measure) const {
    const auto at = measure(centre_);
    if (!at) return std::nullopt;
    GroundPoint out{at->x, at->y, {}};
    for (int axis = 0; axis < 2; ++axis) {
      const auto up = measure(turned_[2 * axis]), down = measure(turned_[2 * axis + 1]);
      cv::Point2d d;
      if (up && down) d = 0.5 * (*up - *down);
      else if (up) d = *up - *at;
      else if (down) d = *at - *down;
      else d = {max_distance_, max_distance_};
      out.covariance[0] += d.x * d.x;
      out.covariance[1] += d.x * d.y;
      out.covariance[2] += d.y * d.y;
    }
    return out;
  }
  std::optional<GroundPoint> point(double u, double v) const {
    if (!ground(u, v)) return std::nullopt;
    return point([&](const GroundProjection& p) { return p.to_ground(u, v); });
  }

 private:
  GroundProjection centre_;
  std::array<GroundProjection, 4> turned_;  // pitch +, pitch -, roll +, roll -
  double max_distance_;
};

// The last point from `inside` towards `outside` (image px) that is still on the ground.
cv::Point2d cut(const Projections& p, cv::Point2d inside, cv::Point2d outside) {
  for (int i = 0; i < kCutIterations; ++i) {
    const cv::Point2d mid = 0.5 * (inside + outside);
    (p.ground(mid.x, mid.y) ? inside : outside) = mid;
  }
  return inside;
}

void project_marking(const Marking& m, const Projections& p, std::vector<GroundMarkingSegment>& out) {
  cv::Point2d a(m.x0, m.y0), b(m.x1, m.y1);
  auto start = p.point(a.x, a.y), end = p.point(b.x, b.y);
  if (!start && !end) return;
  if (!start) {
    a = cut(p, b, a);
    start = p.point(a.x, a.y);
  }
  if (!end) {
    b = cut(p, a, b);
    end = p.point(b.x, b.y);
  }
  if (!start || !end) return;
  // The width at the middle: the points half a width either side in the image lie on the two
  // edges; on the ground, the edges' distance is their gap across the line (the image's normal
  // is not the ground's).
  const cv::Point2d along = b - a, mid = 0.5 * (a + b);
  const double length = std::hypot(along.x, along.y);
  const cv::Point2d ground_along(end->x - start->x, end->y - start->y);
  const double ground_length = std::hypot(ground_along.x, ground_along.y);
  double width = 0;
  if (length > 0 && ground_length > 0) {
    const cv::Point2d across = cv::Point2d(-along.y, along.x) * (0.5 * m.width / length);
    const auto l = p.ground(mid.x + across.x, mid.y + across.y), r = p.ground(mid.x - across.x, mid.y - across.y);
    if (l && r) width = std::abs(ground_along.cross(*l - *r)) / ground_length;
  }
  out.push_back({*start, *end, width});
}

// The unit ground direction of ray k of `j`, whose centre lies on the ground at `origin`: from
// the point a pixel along it (a ray running up to the horizon: from the point a pixel back,
// reversed). Zero when neither is on the ground.
std::array<double, 2> ground_ray(const Intersection& j, int k, const GroundProjection& at, cv::Point2d origin) {
  const double h = j.heading_rays[static_cast<std::size_t>(k)];
  const cv::Point2d step(kRayStepPx * std::cos(h), kRayStepPx * std::sin(h));
  cv::Point2d d;
  if (const auto ahead = at.to_ground(j.x + step.x, j.y + step.y)) d = *ahead - origin;
  else if (const auto behind = at.to_ground(j.x - step.x, j.y - step.y)) d = origin - *behind;
  const double n = std::hypot(d.x, d.y);
  return n > 0 ? std::array<double, 2>{d.x / n, d.y / n} : std::array<double, 2>{};
}

void project_intersection(const Intersection& j, const Projections& p, std::vector<GroundIntersection>& out) {
  const auto centre = p.point(j.x, j.y);
  if (!centre) return;
  GroundIntersection g{*centre, j.type, std::clamp(j.num_rays, 0, 4), {}, j.confidence};
  const cv::Point2d origin(centre->x, centre->y);
  for (int k = 0; k < g.num_rays; ++k) g.rays[static_cast<std::size_t>(k)] = ground_ray(j, k, p.centre(), origin);
  out.push_back(g);
}

// a x = b by Cramer's rule; none when a is (nearly) singular.
std::optional<cv::Vec3d> solve(const cv::Matx33d& a, const cv::Vec3d& b) {
  const auto det = [](const cv::Matx33d& m) {
    return m(0, 0) * (m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1)) - m(0, 1) * (m(1, 0) * m(2, 2) - m(1, 2) * m(2, 0)) +
           m(0, 2) * (m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0));
  };
  const double d = det(a);
  double scale = 0;
  for (int i = 0; i < 9; ++i) scale = std::max(scale, std::abs(a.val[i]));
  if (!(std::abs(d) > 1e-12 * scale * scale * scale)) return std::nullopt;
  cv::Vec3d x;
  for (int c = 0; c < 3; ++c) {
    cv::Matx33d m = a;
    for (int r = 0; r < 3; ++r) m(r, c) = b[r];
    x[c] = det(m) / d;
  }
  return x;
}

struct GroundCircle {
  cv::Point2d centre;
  double radius = 0;
};

// The circle through the image ellipse's points on the ground (least squares on
// x^2 + y^2 + D x + E y + F = 0, linear in D, E, F); none when too few of them are on it.
std::optional<GroundCircle> circle_through(const MarkingEllipse& e, const Projections& p,
                                           const GroundProjection& projection) {
  const double a = 0.5 * e.width, b = 0.5 * e.height, t = e.angle_deg * kRadiansPerDegree;
  const double ct = std::cos(t), st = std::sin(t);
  cv::Matx33d normal = cv::Matx33d::zeros();
  cv::Vec3d rhs(0, 0, 0);
  int on = 0;
  for (int i = 0; i < kCirclePoints; ++i) {
    const double phi = 2 * std::numbers::pi * i / kCirclePoints;
    const double u = e.cx + a * std::cos(phi) * ct - b * std::sin(phi) * st;
    const double v = e.cy + a * std::cos(phi) * st + b * std::sin(phi) * ct;
    const auto g = p.ground(projection, u, v);
    if (!g) continue;
    ++on;
    const cv::Vec3d row(g->x, g->y, 1);
    normal += row * row.t();
    rhs -= row * (g->x * g->x + g->y * g->y);
  }
  if (on < kMinCirclePoints) return std::nullopt;
  const auto def = solve(normal, rhs);
  if (!def) return std::nullopt;
  const cv::Point2d centre(-0.5 * (*def)[0], -0.5 * (*def)[1]);
  const double r2 = centre.dot(centre) - (*def)[2];
  if (!(r2 > 0)) return std::nullopt;
  return GroundCircle{centre, std::sqrt(r2)};
}

void project_ellipse(const MarkingEllipse& e, const Projections& p, std::vector<GroundEllipse>& out) {
  const auto circle = circle_through(e, p, p.centre());
  if (!circle) return;
  const auto centre = p.point([&](const GroundProjection& projection) -> std::optional<cv::Point2d> {
    const auto c = circle_through(e, p, projection);
    return c ? std::optional(c->centre) : std::nullopt;
  });
  if (!centre) return;
  out.push_back({*centre, 2 * circle->radius, e.confidence});
}

}  // namespace

bool square_on_ground(const Intersection& j, const GroundProjection& projection, double tolerance_deg) {
  const auto origin = projection.to_ground(j.x, j.y);
  if (!origin) return false;
  const int n = std::clamp(j.num_rays, 0, 4);
  std::array<std::array<double, 2>, 4> rays{};
  for (int k = 0; k < n; ++k) rays[static_cast<std::size_t>(k)] = ground_ray(j, k, projection, *origin);
  // |sin 2a| is 0 at every multiple of 90 degrees and sin(2 tolerance) at the tolerance.
  const double limit = std::sin(2 * std::min(tolerance_deg, 45.0) * kRadiansPerDegree);
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) {
      const auto &u = rays[static_cast<std::size_t>(a)], &v = rays[static_cast<std::size_t>(b)];
      const double cos_ab = u[0] * v[0] + u[1] * v[1], sin_ab = u[0] * v[1] - u[1] * v[0];
      if (std::abs(2 * sin_ab * cos_ab) > limit) return false;
    }
  return true;
}

void validate(const GroundFeatureParams& params) {
  if (!(params.angle_sigma_deg >= 0 && params.angle_sigma_deg <= 10))
    throw Error("ground features: angle_sigma_deg must lie in [0, 10] degrees");
  if (!(params.max_distance_m > 0 && std::isfinite(params.max_distance_m)))
    throw Error("ground features: max_distance_m must be a positive number of metres");
}

void project_features(const FieldFeatures& image, const GroundCamera& camera, const GroundFeatureParams& params,
                      GroundFeatures& out) {
  out.clear();
  const Projections p(camera, params);
  for (const Marking& m : image.markings) project_marking(m, p, out.segments);
  for (const Intersection& j : image.intersections) project_intersection(j, p, out.intersections);
  for (const MarkingEllipse& e : image.ellipses) project_ellipse(e, p, out.ellipses);
  for (const FieldBoundary::Point& b : image.field_boundary.points)
    if (const auto g = p.point(b.x, b.y)) out.field_boundary.push_back(*g);
}

}  // namespace fieldlines
