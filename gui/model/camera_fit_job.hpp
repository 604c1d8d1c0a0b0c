#pragma once
// The Camera tab's "Fit from lines" as a background Job (gui/model/job.hpp): each of the
// project's images detected with the stripes stage on (frame_lines.hpp, as `fieldlines
// calibrate-camera` does), then fit_camera (camera_fit.hpp) on all of them from the studio's
// camera. The result waits for the person: Apply adopts the fitted camera, Discard drops it; a
// failure keeps fit_camera's message (the frames do not determine the pose, ...).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "fieldlines/detect/detector.hpp"
#include "fieldlines/train/camera_fit.hpp"
#include "gui/model/job.hpp"

namespace fieldlines::studio {

class StudioController;

struct CameraFitProgress {
  std::size_t done = 0, total = 0;  // frames detected
};

struct CameraFitResult {
  CameraFit fit;
  GroundCamera start;
  std::size_t frames = 0;      // detected frames
  std::size_t unreadable = 0;  // images that could not be read (left out)
};

// The result for the tab, before -> after: "pitch 33.00 -> 30.02 deg", "roll ...", "fx 640.0
// -> 643.2, fy ..." when the fit scaled the focal lengths, "height
// 0.600 -> 0.612 m" or "height 0.600 m kept (no line width)", "residual 2.41 -> 0.18 deg RMS,
// 96 % of the lines' weight fits", "31 lines in 6 of 6 frames (1 unreadable)".
std::vector<std::string> fit_summary(const CameraFitResult& result);

class CameraFitJob {
 public:
  // Detects `images` with `params` (stripes on) and `thresholds` and fits from `start` on a
  // worker; a running fit is cancelled and joined first, and any result waiting is dropped.
  void start(std::vector<std::filesystem::path> images, const DetectorParams& params, const Thresholds& thresholds,
             const GroundCamera& start, const CameraFitParams& fit_params);
  void cancel() { job_.cancel(); }
  bool running() const { return job_.running(); }
  // UI thread, once per frame: takes the progress and the outcome.
  void poll();
  void wait() {  // tests
    job_.wait();
    poll();
  }
  const CameraFitProgress& progress() const { return progress_; }
  // The finished fit or its error until taken or discarded; none while running.
  const std::optional<Outcome<CameraFitResult>>& outcome() const { return outcome_; }
  // The fitted camera (and the result is gone); none without a successful fit.
  std::optional<GroundCamera> take_fitted();
  void discard() { outcome_.reset(); }
  // One line: "detecting frames 3/8", "fitting ...", the error, or empty.
  std::string status() const;

 private:
  Job<CameraFitProgress, CameraFitResult> job_;
  CameraFitProgress progress_;
  std::optional<Outcome<CameraFitResult>> outcome_;
};

// Starts `controller`'s fit on every image of its project with its detector parameters and
// thresholds, from its camera. False (nothing started) without a camera.
bool start_camera_fit(StudioController& controller, const CameraFitParams& params = {});
// Adopts the fitted camera as the studio's (StudioController::set_camera). False without one.
bool apply_camera_fit(StudioController& controller);

}  // namespace fieldlines::studio
