#include "elsed.hpp"

#include <algorithm>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

#include "colour_gradients.hpp"

namespace fieldlines {

using elsed::EdgeDir;
using elsed::Mark;
using elsed::Pixel;

void ElsedEngine::compute_gradients(const DetectorParams& params) {
  const cv::Mat* src = &gray_;
  if (params.gaussian_kernel >= 3) {
    cv::GaussianBlur(gray_, blurred_, cv::Size(params.gaussian_kernel, params.gaussian_kernel), params.gaussian_sigma);
    src = &blurred_;
  }
  const int w = src->cols, h = src->rows;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  maps_.width = w;
  maps_.height = h;
  maps_.dx.resize(n);
  maps_.dy.resize(n);
  maps_.mag.resize(n);
  maps_.dir.resize(n);
  // Sobel straight into our buffers (no copies): wrap them as Mats.
  dx_mat_ = cv::Mat(h, w, CV_16SC1, maps_.dx.data());
  dy_mat_ = cv::Mat(h, w, CV_16SC1, maps_.dy.data());
  cv::Sobel(*src, dx_mat_, CV_16S, 1, 0, 3, 1, 0, cv::BORDER_REPLICATE);
  cv::Sobel(*src, dy_mat_, CV_16S, 0, 1, 3, 1, 0, cv::BORDER_REPLICATE);
  const int threshold = params.gradient_threshold;
  const std::int16_t* dx = maps_.dx.data();
  const std::int16_t* dy = maps_.dy.data();
  std::int16_t* mag = maps_.mag.data();
  EdgeDir* dir = maps_.dir.data();
  for (std::size_t i = 0; i < n; ++i) {
    const int ax = std::abs(dx[i]), ay = std::abs(dy[i]);
    const int sum = ax + ay;  // at most 2040 for 8-bit input: fits int16
    mag[i] = static_cast<std::int16_t>(sum < threshold ? 0 : sum);
    dir[i] = ax >= ay ? EdgeDir::Vertical : EdgeDir::Horizontal;
  }
}

void ElsedEngine::find_anchors(int scan_interval, int threshold) {
  const int w = maps_.width, h = maps_.height;
  const std::int16_t* g = maps_.mag.data();
  anchors_.clear();
  // Column by column, as the method scans: the order decides which anchor draws an edge first.
  for (int x = 1; x < w - 1; x += scan_interval) {
    for (int y = 1; y < h - 1; y += scan_interval) {
      const int i = y * w + x;
      if (g[i] == 0) continue;
      // A local maximum across the edge by at least `threshold`.
      const int step = maps_.dir[i] == EdgeDir::Horizontal ? w : 1;
      if (g[i] >= g[i - step] + threshold && g[i] >= g[i + step] + threshold) anchors_.push_back({x, y});
    }
  }
}

void ElsedEngine::run(const cv::Mat& bgr, const DetectorParams& params, std::vector<Segment>& out) {
  cv::cvtColor(bgr, gray_, cv::COLOR_BGR2GRAY);
  compute_gradients(params);

  // With no anchor at all, retry with a halved threshold (down to zero) like the method.
  int anchor_threshold = params.anchor_threshold;
  for (;;) {
    find_anchors(params.scan_interval, anchor_threshold);
    if (!anchors_.empty() || anchor_threshold == 0) break;
    anchor_threshold /= 2;
  }

  marks_.assign(maps_.mag.size(), Mark::Free);
  elsed::DrawerParams dp;
  dp.line_fit_error = params.line_fit_error;
  dp.px_to_segment_dist = params.px_to_segment_dist;
  dp.min_line_length = params.min_line_length;
  dp.treat_junctions = params.treat_junctions;
  dp.junction_sizes = params.junction_sizes;
  drawer_.reset(maps_, marks_, dp);
  const int w = maps_.width;
  for (const Pixel& a : anchors_) {
    if (marks_[a.y * w + a.x] != Mark::Free) continue;  // already part of an edge
    drawer_.draw_from_anchor(a);
  }

  const elsed::ValidationParams vp{params.validation_threshold, params.validate};
  Segment s;
  for (const elsed::LineModel& seg : drawer_.segments()) {
    if (elsed::validate_segment(seg, drawer_.chain(), marks_, maps_, bgr, vp, s)) out.push_back(s);
  }
}

}  // namespace fieldlines
