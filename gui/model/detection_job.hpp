#pragma once
// Detects segments in many images as a background Job (gui/model/job.hpp), one LineDetector
// reused: each image's result is a progress message as it finishes; the job fails as a whole
// only when it cannot start (bad detector parameters).
//
// Every feature stage runs (with_every_feature), so each result also holds the frame's field
// features for the image view. The stages relabel the detector's segments (the stripes check
// makes non-stripe markings none) but never move, add or drop one, and the studio takes only
// their geometry and colour gradients: ProjectDetection clears their labels, and predictions
// are the thresholds' classify() of the cached features. So the studio's segments, labels and
// predictions are the same with the stages on as off (tests/studio/project_detection_test.cpp).
#include <atomic>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/detect/detector.hpp"
#include "gui/model/job.hpp"
#include "gui/model/proposal_gate.hpp"

namespace fieldlines::studio {

// The detector a job chose from its frames, and the record of that choice (what
// detector_provenance() writes: the contrasts measured, the parameters chosen).
struct DetectorChoice {
  DetectorParams params;
  nlohmann::json provenance;
};

struct DetectionResult {
  std::size_t image = 0;          // the caller's index
  std::vector<Segment> segments;  // labels as the detector's thresholds and stripes check set them
  FieldFeatures features;         // the frame's field features, every stage on
  // Per segment, stripe-checked as though its colours passed (stripes.hpp): the review proposes
  // through the check (proposal_gate.hpp) with other thresholds than the detector's.
  std::vector<StripeVerdict> stripes;
  double detect_ms = 0;           // detector time only (not file loading), feature stages included
  std::string error;              // non-empty when this image could not be loaded or detected
  // The detector it was detected with, when the job chose it from the frames (one per job,
  // shared by its results).
  std::shared_ptr<const DetectorChoice> chosen_detector;
};

class DetectionJob {
 public:
  struct Item {
    std::size_t image;
    std::filesystem::path path;
  };
  // Starts on a worker thread; a running job is cancelled and joined first. The detector runs
  // with_every_feature(params) and finds the field boundary too; with `camera`, it also fits
  // the centre circle on the turf (LineDetector::set_camera). With `choose_detector`, every
  // image is first measured and the detector chosen from them as `fieldlines calibrate` chooses
  // it (calibrated_detector(params, ...), detector_calibration.hpp); each result says which.
  void start(std::vector<Item> items, const DetectorParams& params, const Thresholds& thresholds,
             const std::optional<GroundCamera>& camera = std::nullopt, bool choose_detector = false);
  void cancel() { job_.cancel(); }
  bool running() const { return job_.running(); }
  // Results finished since the last poll (UI thread, once per frame).
  std::vector<DetectionResult> poll();
  void wait() { job_.wait(); }  // blocks until done (tests, shutdown); results stay queued for poll()
  // The images processed (fewer than total() when cancelled), or why detection could not start.
  const std::optional<Outcome<std::size_t>>& outcome() const { return job_.outcome(); }

  std::size_t total() const { return total_; }
  std::size_t done() const { return done_; }  // results polled so far
  // While the job chooses the detector: the images measured so far (then total()); else total().
  std::size_t measured() const { return measured_ ? measured_->load() : total_; }
  bool measuring() const { return running() && measured() < total_; }
  float progress() const { return total_ ? static_cast<float>(done_) / static_cast<float>(total_) : 1.0f; }
  // What a progress bar shows: the share measured while the job chooses the detector, then the
  // share detected, and "measuring k/N" or "detecting k/N".
  float bar_progress() const;
  std::string bar_text() const;

 private:
  std::size_t total_ = 0, done_ = 0;
  std::shared_ptr<std::atomic<std::size_t>> measured_;  // shared with the worker
  Job<DetectionResult, std::size_t> job_;
};

}  // namespace fieldlines::studio
