#include "app/cli/eval_overlay.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include <opencv2/imgproc.hpp>

#include "fieldlines/data/overlay.hpp"
#include "fieldlines/data/palette.hpp"

namespace fieldlines::cli {
namespace {

using Seen = GtEdges::Seen;

cv::Scalar seen_colour(Seen seen) {
  switch (seen) {
    case Seen::Found: return bgr(palette::kTruthFound);
    case Seen::OnSegment: return bgr(palette::kTruthLost);
    default: return bgr(palette::kMissedPaint);
  }
}

// The hand-drawn boundary, a solid line through the columns it spans (each run of them its own).
void draw_hand_boundary(cv::Mat& canvas, std::span<const float> rows, int thickness) {
  for (std::size_t x = 1; x < rows.size(); ++x)
    if (rows[x - 1] >= 0 && rows[x] >= 0)
      cv::line(canvas, cv::Point2f(float(x - 1), rows[x - 1]), cv::Point2f(float(x), rows[x]),
               bgr(palette::kTruthFound), thickness, cv::LINE_8);
}

// Bottom-left: a swatch and the share of the truth edges' length per way of being seen.
void draw_legend(cv::Mat& canvas, const std::array<double, 3>& px) {
  const double total = px[0] + px[1] + px[2];
  if (!(total > 0)) return;
  const double scale = std::clamp(canvas.rows / 900.0, 0.35, 1.0);
  const int line = static_cast<int>(std::lround(22 * scale)), pad = line / 3;
  const char* names[3] = {"truth edge found", "on a segment, label lost", "missed: no segment"};
  for (int k = 0; k < 3; ++k) {
    char text[64];
    std::snprintf(text, sizeof text, "%s %.0f%%", names[k], 100 * px[static_cast<std::size_t>(k)] / total);
    const int y = canvas.rows - pad - (2 - k) * line;
    if (y - line < 0) return;  // too small a frame for the legend
    const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, 0.5 * scale, 1, nullptr);
    cv::rectangle(canvas, cv::Point(0, y - line + pad / 2), cv::Point(line + size.width + 2 * pad, y + pad / 2),
                  bgr(palette::kOutline), cv::FILLED);
    cv::rectangle(canvas, cv::Point(pad, y - line + pad), cv::Point(line - pad, y - pad / 2), seen_colour(Seen(k)),
                  cv::FILLED);
    cv::putText(canvas, text, cv::Point(line + pad, y - pad / 2), cv::FONT_HERSHEY_SIMPLEX, 0.5 * scale,
                cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
}

}  // namespace

cv::Mat draw_eval_overlay(const cv::Mat& image, std::span<const Segment> segments, const FieldBoundary& boundary,
                          const GtEdges& truth, std::span<const float> hand_boundary_rows) {
  OverlayParams look;
  look.field_boundary = &boundary;
  cv::Mat canvas = draw_overlay(image, segments, look);
  draw_field_boundary(canvas, boundary.points, look);
  const int thickness = std::max(1, canvas.rows / 480);
  draw_hand_boundary(canvas, hand_boundary_rows, thickness);
  // Found edges as fine dots, so the segment that found them shows under them; the rest bolder.
  std::array<double, 3> px{};
  truth.walk(segments, [&](const GtEdges::Edge&, float x, float y, float step, Seen seen) {
    px[static_cast<std::size_t>(seen)] += step;
    const cv::Point p(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
    cv::circle(canvas, p, seen == Seen::Found ? 0 : thickness, seen_colour(seen), cv::FILLED);
  });
  draw_legend(canvas, px);
  return canvas;
}

}  // namespace fieldlines::cli
