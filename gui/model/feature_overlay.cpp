#include "gui/model/feature_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <span>

namespace fieldlines::studio {

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kBaseThickness = 2;  // a labelled segment's (overlay_style.cpp)

constexpr Rgba opaque(palette::Rgb c, std::uint8_t alpha = 255) { return {c.r, c.g, c.b, alpha}; }

bool finite(float a, float b) { return std::isfinite(a) && std::isfinite(b); }

// Image pixel (x, y) to screen, at the pixel's centre as segments are (hit_test.cpp's to_screen).
Vec2 screen(const ViewTransform& view, float x, float y) { return view.image_to_screen({x + 0.5f, y + 0.5f}); }

// Dashed along the whole polyline, the pattern running on across its corners (a hull has many
// short pieces near a curve: dashing each piece anew would draw them solid). Each dash is a
// solid line over its outline, as the CLI draws it.
void add_boundary(const FieldBoundary& boundary, const ViewTransform& view, float thickness, FeatureDrawing& out) {
  const SegmentStyle style{opaque(palette::kFieldBoundary), Stroke::Solid, thickness};
  const DashPattern dash = dash_pattern(Stroke::Dashed, thickness);
  const auto& p = boundary.points;
  float phase = 0;  // distance into the current period where this piece starts
  for (std::size_t i = 1; i < p.size(); ++i) {
    if (!finite(p[i - 1].x, p[i - 1].y) || !finite(p[i].x, p[i].y)) continue;
    const Vec2 a = screen(view, p[i - 1].x, p[i - 1].y), b = screen(view, p[i].x, p[i].y);
    const Vec2 d = b - a;
    const float length = std::hypot(d.x, d.y);
    if (!(length > 0)) continue;
    const auto at = [&](float t) { return a + d * (t / length); };
    for (float t = -phase; t < length; t += dash.period) {
      const float from = std::max(t, 0.0f), to = std::min(t + dash.on, length);
      if (to > from) out.lines.push_back({at(from), at(to), style});
    }
    phase = std::fmod(phase + length, dash.period);
  }
}

void add_intersections(std::span<const Intersection> junctions, const ViewTransform& view, float thickness,
                       FeatureDrawing& out) {
  const SegmentStyle style{opaque(palette::kFeature), Stroke::Solid, thickness};
  const auto ring = static_cast<float>(palette::junction_ring_radius(thickness));
  const auto tick = static_cast<float>(palette::junction_tick_length(thickness));
  for (const Intersection& j : junctions) {
    if (!finite(j.x, j.y)) continue;
    const Vec2 c = screen(view, j.x, j.y);
    out.rings.push_back({c, ring, style});
    for (int k = 0; k < std::clamp(j.num_rays, 0, 4); ++k) {
      const float h = j.heading_rays[static_cast<std::size_t>(k)];
      if (!std::isfinite(h)) continue;
      const Vec2 u{std::cos(h), std::sin(h)};  // image y down is screen y down: same heading
      out.lines.push_back({c + u * ring, c + u * tick, style});
    }
    out.letters.push_back({{c.x + ring + 2, c.y - ring - 2}, to_string(j.type)[0], style.colour});
  }
}

void add_ellipses(std::span<const MarkingEllipse> ellipses, const ViewTransform& view, float thickness,
                  FeatureDrawing& out) {
  const SegmentStyle style{opaque(palette::kFeature), Stroke::Solid, thickness};
  for (const MarkingEllipse& e : ellipses) {
    if (!finite(e.cx, e.cy) || !std::isfinite(e.angle_deg) || !(e.width > 0) || !(e.height > 0)) continue;
    const float a = 0.5f * e.width, b = 0.5f * e.height, phi = e.angle_deg * kPi / 180;
    const float cp = std::cos(phi), sp = std::sin(phi);
    const auto at = [&](int step) {
      const float t = 2 * kPi * static_cast<float>(step) / kEllipseSteps;
      const float u = a * std::cos(t), v = b * std::sin(t);
      return screen(view, e.cx + u * cp - v * sp, e.cy + u * sp + v * cp);
    };
    Vec2 previous = at(0);
    for (int step = 1; step <= kEllipseSteps; ++step) {
      const Vec2 next = at(step);
      out.lines.push_back({previous, next, style});
      previous = next;
    }
  }
}

void add_stripes(std::span<const Marking> markings, const ViewTransform& view, float thickness, FeatureDrawing& out) {
  const SegmentStyle style{opaque(palette::kFeature), Stroke::Solid, thickness};
  for (const Marking& m : markings) {
    if (!finite(m.x0, m.y0) || !finite(m.x1, m.y1)) continue;
    const Vec2 a = screen(view, m.x0, m.y0), b = screen(view, m.x1, m.y1);
    out.lines.push_back({a, b, style});
    // The width: a bar across each end as long as the paint is wide, and at least twice the
    // line's width, so a thin stripe's bar still shows beyond the line.
    const Vec2 d = b - a;
    const float length = std::hypot(d.x, d.y);
    if (!(length > 0) || !std::isfinite(m.width) || !(m.width > 0)) continue;
    const float half = 0.5f * std::max(m.width * view.scale(), 2 * thickness);
    const Vec2 across{-d.y / length * half, d.x / length * half};
    out.lines.push_back({a + across, a - across, style});
    out.lines.push_back({b + across, b - across, style});
  }
}

}  // namespace

float feature_thickness(const ViewSettings& settings, float view_scale) {
  return settings.drawn_width(kBaseThickness, view_scale);
}

void build_feature_drawing(const FieldFeatures& features, const FeatureLayers& layers, const ViewTransform& view,
                           const ViewSettings& settings, FeatureDrawing& out) {
  out.clear();
  const float thickness = feature_thickness(settings, view.scale());
  // Lines in this order: the stripes, the circle, the junctions' ticks, the boundary last
  // (dashed: what is under it shows between its dashes). Rings and letters go over every line.
  if (layers.on(FeatureLayer::Stripes)) add_stripes(features.markings, view, thickness, out);
  if (layers.on(FeatureLayer::CentreCircle)) add_ellipses(features.ellipses, view, thickness, out);
  if (layers.on(FeatureLayer::Intersections)) add_intersections(features.intersections, view, thickness, out);
  if (layers.on(FeatureLayer::FieldBoundary)) add_boundary(features.field_boundary, view, thickness, out);
}

}  // namespace fieldlines::studio
