#include "fieldlines/detect/detector.hpp"

#include <string>

#include <opencv2/imgproc.hpp>

#include "elsed/elsed.hpp"
#include "fieldlines/detect/error.hpp"

namespace fieldlines {

void validate(const DetectorParams& p) {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw Error("detector parameter " + what);
  };
  require(p.gaussian_kernel < 3 || (p.gaussian_kernel % 2 == 1 && p.gaussian_kernel <= 31),
          "gaussian_kernel must be odd and at most 31 (or < 3 to disable smoothing)");
  require(p.gaussian_sigma > 0 && p.gaussian_sigma <= 20, "gaussian_sigma must be in (0, 20]");
  require(p.gradient_threshold >= 0 && p.gradient_threshold <= 2040, "gradient_threshold must be in [0, 2040]");
  require(p.anchor_threshold >= 0 && p.anchor_threshold <= 255, "anchor_threshold must be in [0, 255]");
  require(p.scan_interval >= 1 && p.scan_interval <= 1000, "scan_interval must be in [1, 1000]");
  require(p.min_line_length >= 3 && p.min_line_length <= 10000, "min_line_length must be in [3, 10000]");
  require(p.line_fit_error > 0 && p.line_fit_error <= 100, "line_fit_error must be in (0, 100]");
  require(p.px_to_segment_dist > 0 && p.px_to_segment_dist <= 100, "px_to_segment_dist must be in (0, 100]");
  require(p.validation_threshold > 0 && p.validation_threshold <= 1.5708,
          "validation_threshold must be in (0, pi/2] radians");
  require(p.threads >= 1 && p.threads <= 64, "threads must be in [1, 64]");
  for (const int s : p.junction_sizes)
    require(s >= 1 && s <= 100, "junction_sizes must each be in [1, 100]");
}

// Hidden like the engine it holds (see elsed/line_model.hpp).
struct [[gnu::visibility("hidden")]] LineDetector::Impl {
  ElsedEngine engine;
  cv::Mat eight, bgr8;  // the input normalised to 8-bit BGR, reused between calls
};

LineDetector::LineDetector(DetectorParams params, Thresholds thresholds)
    : params_(std::move(params)), thresholds_(thresholds), impl_(std::make_unique<Impl>()) {
  validate(params_);
}
LineDetector::~LineDetector() = default;
LineDetector::LineDetector(LineDetector&&) noexcept = default;
LineDetector& LineDetector::operator=(LineDetector&&) noexcept = default;

std::vector<Segment> LineDetector::detect(const cv::Mat& image) {
  std::vector<Segment> out;
  detect(image, out);
  return out;
}

const cv::Mat* LineDetector::normalise(const cv::Mat& image) {
  if (image.empty()) throw Error("empty image");
  const int depth = image.depth();
  if (depth != CV_8U && depth != CV_16U)
    throw Error("unsupported pixel depth (expected 8- or 16-bit unsigned, got OpenCV depth " +
                std::to_string(depth) + ")");
  const int channels = image.channels();
  if (channels != 1 && channels != 3 && channels != 4)
    throw Error("unsupported channel count " + std::to_string(channels) + " (expected 1, 3 or 4)");
  if (image.rows < 3 || image.cols < 3) return nullptr;  // too small for any 3x3 window

  // Normalise to 8-bit BGR into reused Mats. 16-bit is scaled (>> 8); grey is replicated so
  // every channel carries the same gradient; alpha is dropped.
  if (depth == CV_8U && channels == 3) return &image;
  const cv::Mat* eight = &image;
  if (depth == CV_16U) {
    image.convertTo(impl_->eight, CV_8U, 1.0 / 256.0);
    if (channels == 3) return &impl_->eight;
    eight = &impl_->eight;
  }
  cv::cvtColor(*eight, impl_->bgr8, channels == 1 ? cv::COLOR_GRAY2BGR : cv::COLOR_BGRA2BGR);
  return &impl_->bgr8;
}

void LineDetector::detect(const cv::Mat& image, std::vector<Segment>& out) {
  out.clear();
  const cv::Mat* bgr = normalise(image);
  if (!bgr) return;
  impl_->engine.run(*bgr, params_, out);
  classify_all(out, thresholds_);
}

LineDetector::GradientViews LineDetector::compute_gradients(const cv::Mat& image) {
  const cv::Mat* bgr = normalise(image);
  if (!bgr) return {};
  impl_->engine.compute_gradients(*bgr, params_);
  const elsed::GradientMaps& g = impl_->engine.gradients();
  // Views over the engine's buffers: the const_cast only satisfies cv::Mat's constructor.
  const auto view = [&](const std::vector<std::int16_t>& v) {
    return cv::Mat(g.height, g.width, CV_16SC1, const_cast<std::int16_t*>(v.data()));
  };
  return {view(g.dx), view(g.dy), view(g.mag)};
}

}  // namespace fieldlines
