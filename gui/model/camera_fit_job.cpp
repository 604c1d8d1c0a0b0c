#include "gui/model/camera_fit_job.hpp"

#include <cstdio>
#include <numbers>
#include <utility>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/train/frame_lines.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::studio {

namespace {
constexpr double kDeg = std::numbers::pi / 180;
}

std::vector<std::string> fit_summary(const CameraFitResult& r) {
  const GroundCamera &from = r.start, &to = r.fit.camera;
  char line[200];
  std::vector<std::string> out;
  std::snprintf(line, sizeof line, "pitch %.2f -> %.2f deg (sd %.2f)", from.pitch_rad / kDeg, to.pitch_rad / kDeg,
                r.fit.pitch_sd_deg);
  out.emplace_back(line);
  std::snprintf(line, sizeof line, "roll %.2f -> %.2f deg (sd %.2f)", from.roll_rad / kDeg, to.roll_rad / kDeg,
                r.fit.roll_sd_deg);
  out.emplace_back(line);
  if (to.fx != from.fx || to.fy != from.fy) {  // a fit that scales the focal lengths too
    std::snprintf(line, sizeof line, "fx %.1f -> %.1f, fy %.1f -> %.1f px", from.fx, to.fx, from.fy, to.fy);
    out.emplace_back(line);
  }
  if (r.fit.height_fitted)
    std::snprintf(line, sizeof line, "height %.3f -> %.3f m (from %d stripes' widths)", from.height_m, to.height_m,
                  r.fit.widths_used);
  else
    std::snprintf(line, sizeof line, "height %.3f m kept (no line width given)", from.height_m);
  out.emplace_back(line);
  std::snprintf(line, sizeof line, "residual %.2f -> %.2f deg RMS; %.0f %% of the lines' weight fits",
                r.fit.rms_before_deg, r.fit.rms_after_deg, 100 * r.fit.fitting_share);
  out.emplace_back(line);
  std::snprintf(line, sizeof line, "%d lines in %d of %zu frames", r.fit.lines_used, r.fit.frames_used, r.frames);
  out.emplace_back(std::string(line) + (r.unreadable ? " (" + std::to_string(r.unreadable) + " unreadable)" : ""));
  return out;
}

void CameraFitJob::start(std::vector<std::filesystem::path> images, const DetectorParams& params,
                         const Thresholds& thresholds, const GroundCamera& start, const CameraFitParams& fit_params) {
  outcome_.reset();
  progress_ = {0, images.size()};
  job_.start([images = std::move(images), params, thresholds, start, fit_params](std::stop_token stop,
                                                                                 const auto& report) {
    validate(fit_params);  // before the long part
    FrameLinesDetector detector(params, thresholds);
    CameraFitResult r;
    r.start = start;
    std::vector<FrameLines> frames;
    for (const std::filesystem::path& image : images) {
      if (stop.stop_requested()) throw Error("cancelled");
      try {
        frames.push_back(detector.detect(image));
      } catch (const Error&) {
        ++r.unreadable;  // this image only: the others still fit
      }
      report(CameraFitProgress{frames.size() + r.unreadable, images.size()});
    }
    if (frames.empty()) throw Error("no readable image in the project");
    r.frames = frames.size();
    r.fit = fit_camera(frames, start, fit_params);
    return r;
  });
}

void CameraFitJob::poll() {
  const bool was_running = job_.running();
  for (const CameraFitProgress& p : job_.poll()) progress_ = p;
  if (was_running && !job_.running()) outcome_ = job_.outcome();
}

std::optional<GroundCamera> CameraFitJob::take_fitted() {
  if (!outcome_ || !outcome_->ok()) return std::nullopt;
  const GroundCamera fitted = outcome_->value().fit.camera;
  outcome_.reset();
  return fitted;
}

std::string CameraFitJob::status() const {
  if (running()) {
    if (progress_.done < progress_.total)
      return "detecting frames " + std::to_string(progress_.done) + "/" + std::to_string(progress_.total);
    return "fitting pitch and roll to " + std::to_string(progress_.total) + " frames";
  }
  if (outcome_ && !outcome_->ok()) return "fit failed: " + outcome_->error();
  return {};
}

bool start_camera_fit(StudioController& controller, const CameraFitParams& params) {
  if (!controller.camera()) return false;
  std::vector<std::filesystem::path> images;
  for (std::size_t i = 0; i < controller.image_count(); ++i) images.push_back(controller.image_path(i));
  controller.camera_fit().start(std::move(images), controller.detector_params(), controller.thresholds(),
                                *controller.camera(), params);
  return true;
}

bool apply_camera_fit(StudioController& controller) {
  const auto fitted = controller.camera_fit().take_fitted();
  if (fitted) controller.set_camera(*fitted);
  return fitted.has_value();
}

}  // namespace fieldlines::studio
