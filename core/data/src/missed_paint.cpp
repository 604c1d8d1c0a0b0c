#include "fieldlines/data/missed_paint.hpp"

#include <cmath>

#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/error.hpp"

namespace fieldlines {

MissedPaint find_missed_paint(const cv::Mat& bgr, std::span<const Segment> segments, const MissedPaintParams& p) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw Error("missed paint: expected an 8-bit BGR image");
  if (p.window < 3 || p.window % 2 == 0 || p.max_line_width < 3 || p.segment_radius < 0 || p.min_blob < 1)
    throw Error("missed paint: window must be odd and >= 3, line width >= 3, radius >= 0, min blob >= 1");
  // Paint is bright in all three channels, so its darkest channel stands out from the turf's;
  // a white top-hat keeps only bright structures narrower than a line can be, so a white wall
  // or board beside the turf (wider than that) is not paint.
  cv::Mat channels[3], darkest, thin, local;
  cv::split(bgr, channels);
  cv::min(channels[0], channels[1], darkest);
  cv::min(darkest, channels[2], darkest);
  const cv::Mat disk = cv::getStructuringElement(cv::MORPH_ELLIPSE, {p.max_line_width, p.max_line_width});
  cv::morphologyEx(darkest, thin, cv::MORPH_TOPHAT, disk, {-1, -1}, 1, cv::BORDER_REPLICATE);
  cv::blur(bgr, local, {p.window, p.window}, {-1, -1}, cv::BORDER_REPLICATE);
  cv::Mat paint(bgr.size(), CV_8U);
  for (int y = 0; y < bgr.rows; ++y) {
    const auto* t = thin.ptr<std::uint8_t>(y);
    const auto* l = local.ptr<cv::Vec3b>(y);
    auto* out = paint.ptr<std::uint8_t>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const bool turf = l[x][1] > std::max(l[x][0], l[x][2]) + p.green_margin;
      out[x] = turf && t[x] > p.min_contrast ? 255 : 0;
    }
  }
  // Everything near a segment is explained by it (both edges of a painted line are segments).
  cv::Mat explained = cv::Mat::zeros(bgr.size(), CV_8U);
  const int thickness = std::max(1, static_cast<int>(std::lround(2 * p.segment_radius + 1)));
  for (const Segment& s : segments) {
    cv::line(explained, {static_cast<int>(std::lround(s.x0)), static_cast<int>(std::lround(s.y0))},
             {static_cast<int>(std::lround(s.x1)), static_cast<int>(std::lround(s.y1))}, 255, thickness);
  }
  paint.setTo(0, explained);
  MissedPaint out;
  out.mask = cv::Mat::zeros(bgr.size(), CV_8U);
  cv::Mat labels, stats, centroids;
  const int n = cv::connectedComponentsWithStats(paint, labels, stats, centroids, 8, CV_32S);
  for (int y = 0; y < labels.rows; ++y) {
    const auto* lab = labels.ptr<int>(y);
    auto* m = out.mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < labels.cols; ++x)
      if (lab[x] > 0 && stats.at<int>(lab[x], cv::CC_STAT_AREA) >= p.min_blob) m[x] = 255;
  }
  for (int i = 1; i < n; ++i) {
    const int area = stats.at<int>(i, cv::CC_STAT_AREA);
    if (area >= p.min_blob) out.pixels += static_cast<std::size_t>(area), ++out.blobs;
  }
  return out;
}

}  // namespace fieldlines
