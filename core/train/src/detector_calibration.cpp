#include "fieldlines/train/detector_calibration.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include <opencv2/imgproc.hpp>

#include "fieldlines/detect/field_green.hpp"
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

}  // namespace

FieldContrast::FieldContrast(const DetectorCalibrationParams& params, double gaussian_sigma)
    : params_(params), sigma_(gaussian_sigma) {}

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
}

double FieldContrast::texture() const { return median(texture_); }
double FieldContrast::paint() const { return median(paint_); }

DetectorParams field_detector(const DetectorParams& given, const DetectorCalibrationParams& params) {
  DetectorParams d = given;
  d.gaussian_kernel = params.gaussian_kernel;
  d.scan_interval = params.scan_interval;
  d.min_line_length = params.min_line_length;
  d.stripes = true;
  return d;
}

DetectorParams calibrated_detector(const DetectorParams& given, const FieldContrast& contrast,
                                   const DetectorCalibrationParams& params) {
  if (contrast.frames() == 0) return given;
  DetectorParams d = field_detector(given, params);
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

nlohmann::json detector_provenance(const FieldContrast& contrast, const DetectorParams& chosen, bool calibrated) {
  return {{"calibrated", calibrated},
          {"frames_with_field", contrast.frames()},
          {"field_texture", contrast.texture()},
          {"field_paint_contrast", contrast.paint()},
          {"gradient_threshold", chosen.gradient_threshold},
          {"scan_interval", chosen.scan_interval},
          {"min_line_length", chosen.min_line_length},
          {"stripes", chosen.stripes}};
}

}  // namespace fieldlines
