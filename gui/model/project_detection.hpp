#pragma once
// Background detection of a project's images as the studio tracks it: the job, what the runs
// since the last start did (DetectionReport), the reason each image's last detection failed,
// and taking finished images into the project with their labels re-attached by geometry. Each
// detected image's field features are kept here (the project file has no place for them).
#include <cstddef>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fieldlines/data/project.hpp"
#include "gui/model/detection_job.hpp"
#include "gui/model/proposal_gate.hpp"

namespace fieldlines::studio {

// What the background detections since the last start did: how many images, the labels
// re-attached to the new segments by geometry and those that could not be, the images that
// failed (unreadable or corrupt), each with its reason, and why the whole job could not run.
struct DetectionReport {
  std::size_t detected = 0;
  bool detector_chosen = false;  // the project's detector was chosen from its frames
  std::size_t labels_kept = 0, labels_lost = 0;
  std::vector<std::pair<std::size_t, std::string>> failed;  // image index, reason
  std::string error;  // the job could not start (e.g. bad detector parameters)
  std::string summary() const;  // one line for the status bar; empty before any detection
};

// An image whose segments were never detected (no segments and no detection time).
bool needs_detection(const ImageEntry& image);

// Whether the project is a folder's new one: nothing detected, nothing labelled, the folder's
// detector (open_project.hpp). Its detector is chosen from its frames as `fieldlines calibrate`
// chooses it: the built-in one draws a half to three quarters of a real field's lines.
bool chooses_detector(const Project& project);

class ProjectDetection {
 public:
  // Detects the project's images (only those never detected, or all) with its detector
  // parameters and thresholds; a running detection is replaced. A folder's new project
  // (chooses_detector) first has its detector chosen from its frames, which poll() adopts.
  // `camera`: the robot's, when known (the centre circle is also fitted on the turf).
  // `choose`: whether the detector is chosen from the frames first; by default when
  // chooses_detector(project).
  void start(const Project& project, const std::filesystem::path& project_file, bool only_undetected,
             const std::optional<GroundCamera>& camera = std::nullopt, std::optional<bool> choose = std::nullopt);
  // Once per frame: takes the finished images into `project` (segments replaced, human labels
  // moved to the matching new segments, detection time) and returns their indices.
  const std::vector<std::size_t>& poll(Project& project);

  DetectionJob& job() { return job_; }
  const DetectionJob& job() const { return job_; }
  const DetectionReport& report() const { return report_; }
  // The reason the image's last detection failed, or empty.
  const std::string& error(std::size_t image) const;
  // The field features of the image's last detection; empty before one (or when it failed).
  const FieldFeatures& features(std::size_t image) const;
  // What the detector lets each of the image's segments be (proposal_gate.hpp); empty before
  // a detection here.
  const ProposalGate& gate(std::size_t image) const;
  // Replaces them (a synthetic scene has features but no detection: bench_scene.hpp).
  void set_features(std::size_t image, FieldFeatures features);

 private:
  DetectionJob job_;
  DetectionReport report_;
  std::vector<std::string> errors_;  // per image
  std::vector<FieldFeatures> features_;  // per image
  std::vector<ProposalGate> gates_;      // per image
  std::vector<std::size_t> changed_;  // poll's result, reused
  std::shared_ptr<const DetectorChoice> adopted_;  // the last job's choice, once adopted
};

}  // namespace fieldlines::studio
