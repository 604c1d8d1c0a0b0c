#include "fieldlines/data/overlay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "fieldlines/data/image_io.hpp"

namespace fieldlines {
namespace {

cv::Point2f start(const Segment& s) { return {s.x0, s.y0}; }
cv::Point2f end(const Segment& s) { return {s.x1, s.y1}; }

// Sub-pixel endpoints via OpenCV's fixed-point shift, so short segments are not rounded away.
constexpr int kShift = 4;
cv::Point fixed(cv::Point2f p) {
  // Clamped so a wild endpoint cannot overflow the fixed-point int; cv::line clips the rest.
  auto to_fixed = [](float v) {
    return static_cast<int>(std::lround(std::clamp(v, -1e6f, 1e6f) * (1 << kShift)));
  };
  return {to_fixed(p.x), to_fixed(p.y)};
}

// The line and, when dot_radius > 0, a dot at each endpoint (shows where segments split).
void draw_segment(cv::Mat& canvas, const Segment& s, const cv::Scalar& colour, int thickness, int dot_radius) {
  cv::line(canvas, fixed(start(s)), fixed(end(s)), colour, thickness, cv::LINE_AA, kShift);
  if (dot_radius <= 0) return;
  cv::circle(canvas, fixed(start(s)), dot_radius << kShift, colour, cv::FILLED, cv::LINE_AA, kShift);
  cv::circle(canvas, fixed(end(s)), dot_radius << kShift, colour, cv::FILLED, cv::LINE_AA, kShift);
}

struct LegendEntry {
  cv::Scalar colour;
  std::string text;
  bool dashed = false;  // drawn as the field boundary is: two dashes with a gap
};

// A darkened box of colour swatches and their text in the top-left or top-right corner, so it
// reads on any background; nothing when it would not fit (segments matter more).
void draw_legend(cv::Mat& canvas, std::span<const LegendEntry> entries, bool right, const OverlayParams& p) {
  if (entries.empty()) return;
  const double scale = std::clamp(std::min(canvas.cols, canvas.rows) / 960.0, 0.35, 1.5);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  const int text_thickness = std::max(1, static_cast<int>(std::lround(scale * 1.5)));
  int baseline = 0;
  cv::Size glyph = cv::getTextSize("boundary 0000", font, scale, text_thickness, &baseline);
  for (const LegendEntry& e : entries)
    glyph.width = std::max(glyph.width, cv::getTextSize(e.text, font, scale, text_thickness, &baseline).width);
  const int pad = std::max(3, glyph.height / 2);
  const int swatch = glyph.height * 2;
  const int row = glyph.height + baseline + pad;
  const int width = swatch + glyph.width + 3 * pad;
  const cv::Rect box(right ? canvas.cols - pad - width : pad, pad, width, static_cast<int>(entries.size()) * row + pad);
  if (box.x < 0 || box.br().x > canvas.cols || box.br().y > canvas.rows) return;

  cv::Mat roi = canvas(box);
  roi.convertTo(roi, -1, 0.35, 0);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int y = box.y + pad + static_cast<int>(i) * row + glyph.height;
    const int mid = y - glyph.height / 2;
    const int swatch_width = std::max(2, text_thickness + 1);
    // Solid, or two dashes of two fifths with a fifth between them.
    const int x0 = box.x + pad, x1 = x0 + swatch, dash = 2 * swatch / 5;
    for (const auto& [from, to] : entries[i].dashed ? std::array{std::pair{x0, x0 + dash}, std::pair{x1 - dash, x1}}
                                                    : std::array{std::pair{x0, x1}, std::pair{x1, x1}}) {
      if (to <= from) continue;
      if (p.outline_px > 0)
        cv::line(canvas, {from, mid}, {to, mid}, p.outline_colour, swatch_width + 2 * p.outline_px, cv::LINE_AA);
      cv::line(canvas, {from, mid}, {to, mid}, entries[i].colour, swatch_width, cv::LINE_AA);
    }
    cv::putText(canvas, entries[i].text, {box.x + 2 * pad + swatch, y}, font, scale, {255, 255, 255}, text_thickness,
                cv::LINE_AA);
  }
}

// The labels and their counts, top left.
void draw_label_legend(cv::Mat& canvas, std::span<const Segment> segments, const OverlayParams& p) {
  std::array<LegendEntry, 3> entries;
  std::size_t n = 0;
  for (const auto& entry : {std::pair{Label::Marking, "marking"}, std::pair{Label::Boundary, "boundary"},
                            std::pair{Label::None, "none"}}) {
    const Label label = entry.first;  // a named copy: clang before 16 cannot capture a binding
    const auto count = std::count_if(segments.begin(), segments.end(), [&](const Segment& s) { return s.label == label; });
    entries[n++] = {label_colour(label, p), std::string(entry.second) + " " + std::to_string(count)};
  }
  draw_legend(canvas, entries, false, p);
}

// What the field features' colours mean and how many there are, top right (the labels' legend
// holds the top left).
void draw_feature_legend(cv::Mat& canvas, const FieldFeatures& f, const OverlayParams& p) {
  std::array<LegendEntry, 4> entries;
  std::size_t n = 0;
  const cv::Scalar feature = bgr(palette::kFeature);
  if (!f.markings.empty()) entries[n++] = {feature, "stripes " + std::to_string(f.markings.size())};
  if (!f.intersections.empty()) entries[n++] = {feature, "junctions " + std::to_string(f.intersections.size())};
  if (!f.ellipses.empty()) entries[n++] = {feature, "centre circle"};
  if (!f.field_boundary.points.empty()) entries[n++] = {bgr(palette::kFieldBoundary), "field boundary", true};
  draw_legend(canvas, std::span(entries.data(), n), true, p);
}

}  // namespace

cv::Scalar label_colour(Label label, const OverlayParams& params) {
  switch (label) {
    case Label::Marking: return params.marking_colour;
    case Label::Boundary: return params.boundary_colour;
    case Label::None: return params.none_colour;
    case Label::Unlabelled: break;
  }
  return params.unlabelled_colour;
}

void draw_field_boundary(cv::Mat& canvas, std::span<const FieldBoundary::Point> boundary, const OverlayParams& params) {
  const int thickness =
      params.thickness > 0 ? params.thickness : std::max(1, std::min(canvas.cols, canvas.rows) / 240);
  constexpr double kDashPx = 10;
  for (std::size_t i = 1; i < boundary.size(); ++i) {
    const cv::Point2d a(boundary[i - 1].x, boundary[i - 1].y), b(boundary[i].x, boundary[i].y);
    const double length = cv::norm(b - a);
    for (double t = 0; t < length; t += 2 * kDashPx) {
      const cv::Point2d p = a + (b - a) * (t / length), q = a + (b - a) * (std::min(t + kDashPx, length) / length);
      if (params.outline_px > 0)
        cv::line(canvas, p, q, params.outline_colour, thickness + 2 * params.outline_px, cv::LINE_AA);
      cv::line(canvas, p, q, bgr(palette::kFieldBoundary), thickness, cv::LINE_AA);
    }
  }
}

void draw_field_features(cv::Mat& canvas, const FieldFeatures& features, const OverlayParams& params) {
  draw_field_boundary(canvas, features.field_boundary.points, params);
  const int thickness =
      params.thickness > 0 ? params.thickness : std::max(1, std::min(canvas.cols, canvas.rows) / 240);
  const cv::Scalar colour = bgr(palette::kFeature);
  const int outline = thickness + 2 * params.outline_px;
  // Outline first, colour on top, as every other overlay element.
  const auto stroke = [&](auto&& draw) {
    if (params.outline_px > 0) draw(params.outline_colour, outline);
    draw(colour, thickness);
  };
  for (const Marking& m : features.markings) {
    if (!std::isfinite(m.x0) || !std::isfinite(m.y0) || !std::isfinite(m.x1) || !std::isfinite(m.y1)) continue;
    stroke([&](const cv::Scalar& c, int t) {
      cv::line(canvas, cv::Point2d(m.x0, m.y0), cv::Point2d(m.x1, m.y1), c, t, cv::LINE_AA);
    });
  }
  for (const MarkingEllipse& e : features.ellipses) {
    if (!std::isfinite(e.cx) || !std::isfinite(e.cy) || !(e.width > 0) || !(e.height > 0)) continue;
    const cv::RotatedRect box(cv::Point2f(e.cx, e.cy), cv::Size2f(e.width, e.height), e.angle_deg);
    stroke([&](const cv::Scalar& c, int t) { cv::ellipse(canvas, box, c, t, cv::LINE_AA); });
  }
  const double ray_px = palette::junction_tick_length(thickness), ring_px = palette::junction_ring_radius(thickness);
  for (const Intersection& j : features.intersections) {
    if (!std::isfinite(j.x) || !std::isfinite(j.y)) continue;
    const cv::Point2d centre(j.x, j.y);
    stroke([&](const cv::Scalar& c, int t) {
      cv::circle(canvas, centre, static_cast<int>(ring_px), c, t, cv::LINE_AA);
      for (int k = 0; k < std::clamp(j.num_rays, 0, 4); ++k) {
        const double h = j.heading_rays[static_cast<std::size_t>(k)];
        cv::line(canvas, centre + ring_px * cv::Point2d(std::cos(h), std::sin(h)),
                 centre + ray_px * cv::Point2d(std::cos(h), std::sin(h)), c, t, cv::LINE_AA);
      }
      cv::putText(canvas, to_string(j.type), centre + cv::Point2d(ring_px + 2, -ring_px - 2), cv::FONT_HERSHEY_SIMPLEX,
                  0.4 + 0.1 * thickness, c, t, cv::LINE_AA);
    });
  }
  if (params.legend) draw_feature_legend(canvas, features, params);  // last: over the features
}

namespace {
// The segments `pick` takes, by label: unlabelled and "none" first, so field features are drawn
// on top where they overlap.
template <class Pick>
void draw_segments(cv::Mat& canvas, std::span<const Segment> segments, const OverlayParams& params, int thickness,
                   int dot_radius, Pick pick) {
  for (const Label pass : {Label::Unlabelled, Label::None, Label::Boundary, Label::Marking}) {
    for (const Segment& s : segments) {
      if (s.label != pass || !pick(s)) continue;
      if (!std::isfinite(s.x0) || !std::isfinite(s.y0) || !std::isfinite(s.x1) || !std::isfinite(s.y1))
        continue;
      // Outline then colour, per segment as in the studio: a feature drawn later keeps its
      // outline where it crosses an earlier segment.
      if (params.outline_px > 0) {
        draw_segment(canvas, s, params.outline_colour, thickness + 2 * params.outline_px,
                     dot_radius > 0 ? dot_radius + params.outline_px : 0);
      }
      draw_segment(canvas, s, label_colour(s.label, params), thickness, dot_radius);
    }
  }
}
}  // namespace

cv::Mat draw_overlay(const cv::Mat& image, std::span<const Segment> segments, const OverlayParams& params) {
  cv::Mat canvas = to_bgr8(image).clone();
  const int thickness =
      params.thickness > 0 ? params.thickness : std::max(1, std::min(canvas.cols, canvas.rows) / 240);
  const int dot_radius = params.endpoints ? thickness + 1 : 0;
  const FieldBoundary* field = params.field_boundary && !params.field_boundary->empty() ? params.field_boundary : nullptr;
  const auto above = [&](const Segment& s) { return field && place_of(s, *field) == BoundaryPlace::Above; };
  // The segments above the field first, on a copy blended back at their opacity: faint under
  // everything on the field.
  if (field && params.above_opacity > 0) {
    cv::Mat layer = canvas.clone();
    draw_segments(layer, segments, params, thickness, dot_radius, above);
    const double a = std::clamp(params.above_opacity, 0.0, 1.0);
    cv::addWeighted(layer, a, canvas, 1 - a, 0, canvas);
  }
  draw_segments(canvas, segments, params, thickness, dot_radius, [&](const Segment& s) { return !above(s); });
  if (params.legend) draw_label_legend(canvas, segments, params);
  return canvas;
}

}  // namespace fieldlines
