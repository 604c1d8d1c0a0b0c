#include "fieldlines/detect/classifier.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fieldlines {
namespace {

// The reference converts degrees with pi = 3.1415 (see Thresholds::reference_pi).
constexpr float kReferencePi = 3.1415f;

float dot(const Rgb& a, const Rgb& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

ClassFeatures measure(const Rgb& g, const ColourClass& cls, bool reference_pi) {
  const Rgb v{cls.to[0] - cls.from[0], cls.to[1] - cls.from[1], cls.to[2] - cls.from[2]};
  const float norm_v = std::sqrt(dot(v, v));
  const float norm_g = std::sqrt(dot(g, g));
  ClassFeatures f;
  if (norm_v <= 0.f || !(norm_g > 0.f)) return f;  // no direction to compare: never a member
  const float projection = dot(g, v) / norm_v;
  // Clamp: rounding can push |cos| a hair past 1, which would make acos NaN.
  float angle = std::acos(std::clamp(projection / norm_g, -1.f, 1.f));
  const float pi = std::numbers::pi_v<float>;
  if (cls.two_sided && angle > pi / 2) angle = pi - angle;
  f.projection = cls.two_sided ? std::abs(projection) : projection;
  f.angle_deg = angle * 180.f / (reference_pi ? kReferencePi : pi);
  return f;
}

}  // namespace

SegmentFeatures compute_features(const Segment& s, const Thresholds& t) {
  SegmentFeatures f;
  f.length = s.saliency;
  const float dx = s.x1 - s.x0, dy = s.y1 - s.y0;
  const float len = std::hypot(dx, dy);
  if (t.mode == GradientMode::Normal && len > 0.f) {
    // Unit normal chosen to point down (right when the segment is vertical), so a
    // one-sided class keeps the meaning it has on grad_y for a horizontal segment.
    float nx = -dy / len, ny = dx / len;
    if (ny < 0.f || (ny == 0.f && nx < 0.f)) nx = -nx, ny = -ny;
    Rgb g;
    for (int c = 0; c < 3; ++c) g[c] = s.grad_x[c] * nx + s.grad_y[c] * ny;
    f.boundary = measure(g, t.boundary, t.reference_pi);
    f.marking[0] = measure(g, t.marking, t.reference_pi);
    f.marking_count = 1;
    return f;
  }
  f.boundary = measure(s.grad_y, t.boundary, t.reference_pi);
  f.marking[0] = measure(s.grad_y, t.marking, t.reference_pi);
  f.marking[1] = measure(s.grad_x, t.marking, t.reference_pi);
  f.marking_count = 2;
  return f;
}

bool passes(const ClassFeatures& f, float length, const ClassThresholds& t) {
  return f.projection >= t.min_projection && f.angle_deg <= t.max_angle_deg && length >= t.min_length;
}

double achromatic_angle_deg(const ColourClass& c) {
  const double v[3] = {double(c.to[0]) - c.from[0], double(c.to[1]) - c.from[1], double(c.to[2]) - c.from[2]};
  const double nv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (nv == 0) return 0;  // no transition: no direction to compare
  double cosine = (v[0] + v[1] + v[2]) / (nv * std::sqrt(3.0));
  if (c.two_sided) cosine = std::abs(cosine);
  return std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / std::numbers::pi;
}

Label classify(const SegmentFeatures& f, const Thresholds& t) {
  if (passes(f.boundary, f.length, t.boundary.thresholds)) return Label::Boundary;
  for (int i = 0; i < f.marking_count; ++i)
    if (passes(f.marking[i], f.length, t.marking.thresholds)) return Label::Marking;
  return Label::None;
}

Label classify(const Segment& s, const Thresholds& t) { return classify(compute_features(s, t), t); }

void classify_all(std::span<Segment> segments, const Thresholds& t) {
  for (Segment& s : segments) s.label = classify(s, t);
}

}  // namespace fieldlines
