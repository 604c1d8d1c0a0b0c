#include "fieldlines/train/detector_calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/detect/field_green.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/percentile.hpp"

namespace fieldlines {
namespace {

// |dx| + |dy| of a 3x3 Sobel on 8-bit grey is at most 2040: a histogram holds it exactly.
constexpr int kMaxGradient = 2040;
// Fewer green pixels than this is no field in view (a frame of the stands, say).
constexpr std::size_t kMinFieldPixels = 1000;

double histogram_percentile(const std::array<std::uint32_t, kMaxGradient + 1>& h, std::size_t n, double p) {
  const double rank = p / 100.0 * static_cast<double>(n - 1);
  std::size_t seen = 0;
  for (int v = 0; v <= kMaxGradient; ++v) {
    seen += h[v];
    if (static_cast<double>(seen) > rank) return v;
  }
  return kMaxGradient;
}

// Every segment offered as a marking, the boundary class off, the field-boundary gate on: what
// the stripes stage keeps of a frame is its stripes on the field.
Thresholds every_segment_a_marking() {
  Thresholds t;
  t.marking.thresholds = {0.f, 90.f, 0.f};
  t.boundary.thresholds = disabled_class();
  t.field_boundary_gate = true;
  return t;
}

double stripe_px(LineDetector& detector, const cv::Mat& bgr, std::vector<Segment>& segments) {
  detector.detect(bgr, segments);
  double px = 0;
  for (const Segment& s : segments)
    if (s.label == Label::Marking) px += std::hypot(s.x1 - s.x0, s.y1 - s.y0);
  return px;
}

}  // namespace

FieldContrast::FieldContrast(const DetectorCalibrationParams& params, double gaussian_sigma)
    : params_(params), sigma_(gaussian_sigma) {}

FieldContrast::FieldContrast(const DetectorCalibrationParams& params, const DetectorParams& given)
    : params_(params), sigma_(given.gaussian_sigma) {
  DetectorParams fine = field_detector(given, params);
  fine.intersections = fine.centre_circle = false;
  fine.coarse_scale = 1;
  fine.thin_reach = 0;  // far thin lines are not what the coarse pass is weighed on
  DetectorParams coarse = fine;
  coarse.coarse_scale = params.coarse_scale;
  coarse.coarse_from = params.coarse_from;
  fine_ = std::make_unique<LineDetector>(fine, every_segment_a_marking());
  coarse_ = std::make_unique<LineDetector>(coarse, every_segment_a_marking());
}

FieldContrast::~FieldContrast() = default;
FieldContrast::FieldContrast(FieldContrast&&) noexcept = default;
FieldContrast& FieldContrast::operator=(FieldContrast&&) noexcept = default;

// A frame set with no stripe at the full scale but some with the coarse pass gains all of them.
double FieldContrast::coarse_gain() const { return coarse_px_ > 0 ? coarse_px_ / std::max(fine_px_, 1.0) - 1 : 0.0; }

void FieldContrast::add_image(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3) return;
  cv::cvtColor(bgr, grey_, cv::COLOR_BGR2GRAY);
  const int k = params_.gaussian_kernel;
  if (k >= 3) cv::GaussianBlur(grey_, smooth_, {k, k}, sigma_);
  else grey_.copyTo(smooth_);
  cv::Sobel(smooth_, dx_, CV_16S, 1, 0, 3, 1, 0, cv::BORDER_REPLICATE);
  cv::Sobel(smooth_, dy_, CV_16S, 0, 1, 3, 1, 0, cv::BORDER_REPLICATE);
  std::array<std::uint32_t, kMaxGradient + 1> histogram{};
  std::size_t n = 0;
  const FieldGreen green;
  for (int y = 0; y < bgr.rows; ++y) {
    const std::uint8_t* p = bgr.ptr<std::uint8_t>(y);
    const std::int16_t* gx = dx_.ptr<std::int16_t>(y);
    const std::int16_t* gy = dy_.ptr<std::int16_t>(y);
    for (int x = 0; x < bgr.cols; ++x, p += 3) {
      if (!green(p[0], p[1], p[2])) continue;
      ++histogram[std::min(kMaxGradient, std::abs(gx[x]) + std::abs(gy[x]))];
      ++n;
    }
  }
  if (n < kMinFieldPixels) return;
  texture_.push_back(histogram_percentile(histogram, n, params_.texture_percentile));
  paint_.push_back(histogram_percentile(histogram, n, params_.paint_percentile));
  if (fine_) {
    fine_px_ += stripe_px(*fine_, bgr, segments_);
    coarse_px_ += stripe_px(*coarse_, bgr, segments_);
  }
}

double FieldContrast::texture() const { return median(texture_); }
double FieldContrast::paint() const { return median(paint_); }

DetectorParams field_detector(const DetectorParams& given, const DetectorCalibrationParams& params) {
  DetectorParams d = given;
  d.gaussian_kernel = params.gaussian_kernel;
  d.scan_interval = params.scan_interval;
  d.min_line_length = params.min_line_length;
  d.stripes = true;
  d.stripe_turf_colours = params.stripe_turf_colours;
  d.thin_reach = params.thin_reach;
  d.thin_to = params.thin_to;
  return d;
}

DetectorParams calibrated_detector(const DetectorParams& given, const FieldContrast& contrast,
                                   const DetectorCalibrationParams& params) {
  if (contrast.frames() == 0) return given;
  DetectorParams d = field_detector(given, params);
  if (contrast.coarse_gain() >= params.min_coarse_gain) {
    d.coarse_scale = params.coarse_scale;
    d.coarse_from = params.coarse_from;
    d.coarse_twins_from = params.coarse_twins_from;
    d.thin_reach = 0;  // turf this coarse fills the ridge maps with its blades (see the header)
  }
  if (!params.follow_contrast) return d;
  const double wanted = std::max(params.paint_share * contrast.paint(), params.texture_margin * contrast.texture());
  d.gradient_threshold = std::clamp(static_cast<int>(std::lround(wanted)), params.min_gradient_threshold,
                                    std::max(params.min_gradient_threshold, given.gradient_threshold));
  return d;
}

DetectorParams for_fitting(DetectorParams chosen) {
  chosen.stripes = chosen.intersections = chosen.centre_circle = false;
  return chosen;
}

nlohmann::json detector_provenance(const FieldContrast& contrast, const DetectorParams& chosen) {
  return {{"calibrated", contrast.frames() > 0},
          {"frames_with_field", contrast.frames()},
          {"field_texture", contrast.texture()},
          {"field_paint_contrast", contrast.paint()},
          {"gradient_threshold", chosen.gradient_threshold},
          {"scan_interval", chosen.scan_interval},
          {"min_line_length", chosen.min_line_length},
          {"coarse_gain", contrast.coarse_gain()},
          {"coarse_scale", chosen.coarse_scale},
          {"coarse_twins_from", chosen.coarse_twins_from},
          {"thin_reach", chosen.thin_reach},
          {"stripes", chosen.stripes}};
}

}  // namespace fieldlines
