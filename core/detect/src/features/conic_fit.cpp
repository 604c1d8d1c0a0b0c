#include "conic_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <opencv2/core.hpp>  // Matx::solve is defined in operations.hpp

namespace fieldlines {
namespace {
constexpr float kMinSemiAxisPx = 4;
constexpr float kMaxAxisRatio = 12;  // a circle seen at 5 degrees above the turf
}  // namespace

ConicPoint conic_point(const Fit& fit, float x, float y) {
  const double u = (x - fit.mx) / fit.s, v = (y - fit.my) / fit.s;
  return {u, v, 2 * fit.a * u + fit.b * v + fit.d, fit.b * u + 2 * fit.c * v + fit.e};
}

float distance(const Fit& fit, float x, float y) {
  const auto [u, v, gu, gv] = conic_point(fit, x, y);
  const double q = fit.a * u * u + fit.b * u * v + fit.c * v * v + fit.d * u + fit.e * v + fit.f;
  const double g2 = gu * gu + gv * gv;  // normalised coordinates: no overflow for hypot() to guard
  return g2 > 0 ? static_cast<float>(std::abs(q) / std::sqrt(g2) * fit.s) : 1e9f;
}

bool most_within(const Fit& fit, std::span<const ConicSample> points, float tolerance) {
  const auto close = std::count_if(points.begin(), points.end(),
                                   [&](const ConicSample& p) { return distance(fit, p.x, p.y) <= tolerance; });
  return 2 * close >= static_cast<std::ptrdiff_t>(points.size());
}

bool to_ellipse(Fit& fit) {
  if (fit.b * fit.b - 4 * fit.a * fit.c >= 0) return false;  // a parabola or hyperbola
  const double det = 4 * fit.a * fit.c - fit.b * fit.b;
  const double u0 = (fit.b * fit.e - 2 * fit.c * fit.d) / det, v0 = (fit.b * fit.d - 2 * fit.a * fit.e) / det;
  const double f0 = fit.a * u0 * u0 + fit.b * u0 * v0 + fit.c * v0 * v0 + fit.d * u0 + fit.e * v0 + fit.f;
  const double theta = 0.5 * std::atan2(fit.b, fit.a - fit.c);
  const double co = std::cos(theta), si = std::sin(theta);
  const double la = fit.a * co * co + fit.b * co * si + fit.c * si * si;
  const double lb = fit.a * si * si - fit.b * co * si + fit.c * co * co;
  if (!(-f0 / la > 0) || !(-f0 / lb > 0)) return false;  // imaginary
  const double s = fit.s;
  fit.theta = static_cast<float>(theta);
  fit.semi_a = static_cast<float>(std::sqrt(-f0 / la) * s);
  fit.semi_b = static_cast<float>(std::sqrt(-f0 / lb) * s);
  fit.ellipse = {.cx = static_cast<float>(fit.mx + u0 * s), .cy = static_cast<float>(fit.my + v0 * s),
                 .width = 2 * fit.semi_a, .height = 2 * fit.semi_b,
                 .angle_deg = static_cast<float>(theta * 180 / std::numbers::pi)};
  const float lo = std::min(fit.semi_a, fit.semi_b), hi = std::max(fit.semi_a, fit.semi_b);
  return std::isfinite(hi) && lo >= kMinSemiAxisPx && hi <= kMaxAxisRatio * lo;
}

bool fit_conic(const std::vector<ConicSample>& points, Fit& fit, bool aligned, float roll) {
  return solve_conic(points, fit, aligned, roll) && to_ellipse(fit);
}

bool solve_conic(const std::vector<ConicSample>& points, Fit& fit, bool aligned, float roll) {
  fit = Fit{};
  double mx = 0, my = 0;
  int n = 0;
  for (const ConicSample& p : points)
    if (p.inlier) mx += p.x, my += p.y, ++n;
  if (n < (aligned ? 4 : 6)) return false;
  mx /= n, my /= n;
  double spread = 0;
  for (const ConicSample& p : points)
    if (p.inlier) spread += (p.x - mx) * (p.x - mx) + (p.y - my) * (p.y - my);
  const double s = std::sqrt(spread / n / 2);
  if (!(s > 1e-3)) return false;
  fit.mx = mx, fit.my = my, fit.s = s;
  if (aligned) {
    const double co = std::cos(roll), si = std::sin(roll);
    cv::Matx<double, 4, 4> m = cv::Matx<double, 4, 4>::zeros();
    cv::Matx<double, 4, 1> rhs = cv::Matx<double, 4, 1>::zeros();
    for (const ConicSample& p : points) {
      if (!p.inlier) continue;
      const double u0 = (p.x - mx) / s, v0 = (p.y - my) / s;
      const double u = u0 * co + v0 * si, v = -u0 * si + v0 * co;  // the axes turned by `roll`
      const cv::Matx<double, 4, 1> r(u * u - v * v, u, v, 1);
      m += r * r.t();
      rhs += r * (-v * v);
    }
    if (std::abs(cv::determinant(m)) < 1e-12) return false;
    const cv::Matx<double, 4, 1> x = m.solve(rhs, cv::DECOMP_LU);
    // A u'^2 + C v'^2 + D u' + E v' + F in the image's axes (A + C = 1 stays a + c = 1).
    const double ca = x(0), cc = 1 - x(0);
    fit.a = ca * co * co + cc * si * si, fit.b = 2 * co * si * (ca - cc), fit.c = ca * si * si + cc * co * co;
    fit.d = x(1) * co - x(2) * si, fit.e = x(1) * si + x(2) * co, fit.f = x(3);
    return true;
  }
  cv::Matx<double, 5, 5> m = cv::Matx<double, 5, 5>::zeros();
  cv::Matx<double, 5, 1> rhs = cv::Matx<double, 5, 1>::zeros();
  for (const ConicSample& p : points) {
    if (!p.inlier) continue;
    const double u = (p.x - mx) / s, v = (p.y - my) / s;
    const cv::Matx<double, 5, 1> r(u * u - v * v, u * v, u, v, 1);
    m += r * r.t();
    rhs += r * (-v * v);
  }
  if (std::abs(cv::determinant(m)) < 1e-12) return false;
  const cv::Matx<double, 5, 1> x = m.solve(rhs, cv::DECOMP_LU);
  fit.a = x(0), fit.b = x(1), fit.c = 1 - x(0), fit.d = x(2), fit.e = x(3), fit.f = x(4);
  return true;
}

}  // namespace fieldlines
