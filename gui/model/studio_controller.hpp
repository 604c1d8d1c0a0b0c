#pragma once
// Everything the studio knows and does, without a window: the project, the current image, the
// hovered segment, label edits with undo/redo, autosave, thresholds with live re-classification
// from cached features, live metrics, and the background training and detection jobs.
// The ImGui code reads this state and calls these methods; it holds no logic of its own.
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "gui/model/auto_train.hpp"
#include "gui/model/camera_fit_job.hpp"
#include "gui/model/class_switch.hpp"
#include "gui/model/project_detection.hpp"
#include "gui/model/project_saver.hpp"
#include "fieldlines/detect/classifier.hpp"
#include "fieldlines/detect/detector.hpp"
#include "fieldlines/train/metrics.hpp"
#include "fieldlines/data/project.hpp"
#include "fieldlines/data/label_commands.hpp"
#include "gui/model/training_job.hpp"

namespace fieldlines::studio {

struct ControllerOptions {
  bool autosave = true;  // save the project atomically after every label edit
  bool load_pixels = true;  // read the current image from disk (tests can skip it)
  // Retrain both classes in the background after every label change (the studio turns this
  // on by default; off here so tests choose when thresholds may change).
  bool auto_train = false;
  // Autosave writes on a background thread (gui/model/project_saver.hpp); the studio turns it
  // on, tests that read the file right after an edit leave it off.
  bool background_save = false;
  // The robot's camera, when known: detections fit the centre circle on the turf too.
  std::optional<GroundCamera> camera;
};

struct ImageProgress {
  std::size_t labelled = 0, total = 0;
  long errors = 0;  // labelled segments the current thresholds get wrong
};

class StudioController {
 public:
  // Starts from the project's thresholds and detector parameters; autosaves to `project_file`.
  StudioController(Project project, std::filesystem::path project_file, ControllerOptions options = {});

  // --- project and navigation
  const Project& project() const { return project_; }
  const std::filesystem::path& project_file() const { return project_file_; }
  std::filesystem::path image_path(std::size_t index) const;
  // An image whose segments were never detected (no segments and no detection time).
  bool needs_detection(std::size_t index) const;
  std::size_t image_count() const { return project_.images.size(); }
  std::size_t current() const { return current_; }
  void select_image(std::size_t index);  // out of range is ignored
  void next_image();
  void previous_image();
  // Moves to the next image (wrapping) with a labelled segment the thresholds get wrong.
  bool next_image_with_errors();
  const cv::Mat& image() const { return pixels_; }  // 8-bit BGR; empty when it could not be read
  const std::string& image_error() const { return image_error_; }
  // Bumped whenever image() changes, so the GUI knows to re-upload its texture.
  std::size_t image_generation() const { return image_generation_; }

  // --- the current image's segments
  std::span<const Segment> segments() const;               // .label = human label
  std::span<const Label> predictions() const;              // by the current thresholds
  const SegmentFeatures& features(std::size_t segment) const;
  std::optional<std::size_t> hovered() const { return hovered_; }
  void set_hovered(std::optional<std::size_t> segment);

  // --- labelling (one call = one undo step; autosaved)
  // Returns false (and records nothing) when no label actually changes.
  bool label(std::span<const std::size_t> segments, Label label);
  bool label_hovered(Label label);
  bool label_rest_as_none();  // every unlabelled segment of the current image
  bool undo();
  bool redo();
  bool can_undo() const { return history_.can_undo(); }
  bool can_redo() const { return history_.can_redo(); }

  // --- thresholds and metrics (features are cached: no re-detection)
  const Thresholds& thresholds() const { return project_.thresholds; }
  // Re-classifies every image from cached features. Saved in the project after a short pause
  // (see poll), so dragging a slider does not write the file every frame.
  void set_thresholds(const Thresholds& thresholds);
  const Counts& train_counts() const { return train_counts_; }
  const Counts& test_counts() const { return test_counts_; }
  // Images holding a labelled segment of the test split: how much the test figures mean.
  std::size_t test_image_count() const { return test_images_; }
  // With fewer than kMinTestImages test images, the last retraining's leave-one-image-out
  // figures of the review loop's rule (leave_one_out.hpp); images = 0 when there are none.
  const LeaveOneOut& leave_one_out() const { return leave_one_out_; }

  // --- per-class on/off (class_switch.hpp; class_switches.cpp). `cls` is Marking or Boundary.
  bool class_on(Label cls) const;
  // The user's choice: off keeps the class's thresholds to give back when it is turned on again.
  // Predictions, metrics, proposals and the exported file follow at once.
  void set_class_on(Label cls, bool on);
  // Calibration's reason when calibration turned the class off (proposals found no such class
  // and too few of its labels); empty when it is on or the user turned it off.
  const std::string& class_off_reason(Label cls) const;
  // What calibration refused that the labels do not cover yet, and what to do (empty: nothing);
  // from the last proposals or retraining.
  const std::string& guidance() const { return guidance_; }

  // --- the test split: split_train_test (fieldlines/train/splits.hpp) of the LABELLED segments
  // with the project's SplitSpec, so the studio tests on what `fieldlines train` would with the
  // same parameters. It is re-drawn whenever labels change; unlabelled segments are in neither part.
  const SplitSpec& split_spec() const { return project_.split; }
  // Saved in the project like thresholds (after a pause, or flush()).
  void set_split_spec(const SplitSpec& spec);
  bool is_test_image(std::size_t index) const;  // holds a labelled segment of the test split
  bool is_test_segment(std::size_t image, std::size_t segment) const;
  std::size_t train_segment_count() const { return train_segments_; }
  std::size_t test_segment_count() const { return test_segments_; }
  // One line for the panels: the split's sizes and parameters, or why its test part is empty.
  std::string split_summary() const;
  ImageProgress progress(std::size_t image) const;
  std::size_t labelled_total() const;

  // --- saving
  void save();  // throws fieldlines::Error
  std::size_t save_count() const { return save_count_; }
  const std::string& save_error() const { return save_error_; }  // last autosave failure
  bool has_unsaved_settings() const { return settings_dirty_; }
  // Saves pending threshold/detector changes now (on exit, and in tests); with background_save
  // it queues them.
  void flush();
  // Blocks until every queued background save is written; returns the last failure, if any
  // (on exit, so a failed final save is reported). Without background_save there is none.
  std::string finish_saves();

  // --- detection (background)
  const DetectorParams& detector_params() const { return project_.detector; }
  void set_detector_params(const DetectorParams& params);
  void detect_all(bool only_undetected = true);
  // Every image measured, the detector chosen from them as `fieldlines calibrate` chooses it
  // (from the current one), then every image detected again with it; labels follow by geometry.
  void choose_detector_from_frames();
  DetectionJob& detection() { return detection_.job(); }
  const DetectionJob& detection() const { return detection_.job(); }
  const DetectionReport& detection_report() const { return detection_.report(); }
  // The reason the image's last detection failed, or empty.
  const std::string& detection_error(std::size_t index) const { return detection_.error(index); }
  // The current image's field features from its last detection here (detection_job.hpp); empty
  // for an image not detected since the project was opened.
  const FieldFeatures& field_features() const { return detection_.features(current_); }
  void set_field_features(std::size_t image, FieldFeatures features) {
    detection_.set_features(image, std::move(features));
  }
  // What the detector lets each of the image's segments be (proposal_gate.hpp); empty before a
  // detection here.
  const ProposalGate& proposal_gate(std::size_t image) const { return detection_.gate(image); }
  // Detector time of the current image (from the project), 0 when not detected here.
  double current_detect_ms() const;
  // Mean detector time over the project's detected images.
  double mean_detect_ms() const;

  // --- the robot's camera (the Camera tab): detections started from now on fit the centre
  // circle on the turf with it; features already detected keep the camera they had.
  const std::optional<GroundCamera>& camera() const { return options_.camera; }
  void set_camera(const std::optional<GroundCamera>& camera);  // throws fieldlines::Error when invalid
  CameraFitJob& camera_fit() { return camera_fit_; }  // camera_fit_job.hpp: fit from the lines
  const CameraFitJob& camera_fit() const { return camera_fit_; }

  // --- review loop (gui/model/review.cpp): proposals, one-key accept, uncertain first
  // Proposes a label for every segment of the project (fieldlines/train/review.hpp: label-free
  // until a class has enough labels, then trained on them), kept as the project's proposals
  // (never counted as labels) and autosaved. Returns the one-line summary (also summary()).
  std::string propose();
  const std::string& proposal_summary() const { return proposal_summary_; }
  // The proposal shown for a segment of the current image: Unlabelled when it has a label or none.
  Label proposal(std::size_t segment) const;
  // The current image's proposals for its unlabelled segments become labels (one undo step),
  // then moves to the next image with proposals or unlabelled segments left. Returns how many.
  std::size_t accept_proposals();
  // Unlabelled segments in the whole project: what is left to review.
  std::size_t to_review() const;
  // How close the image's least certain unlabelled segment is to flipping (decision margin,
  // fieldlines/train/review.hpp); infinity when it has none. Smaller = review first.
  double image_uncertainty(std::size_t image) const;
  // Every image, least certain first (the review order); images with nothing left to review
  // last; ties in file order.
  std::vector<std::size_t> images_by_uncertainty() const;
  // Selects the image of the project's least certain unlabelled segment, hovers it and asks the
  // view to centre on it (take_focus_request); empty when nothing is left to review.
  std::optional<SegmentRef> focus_most_uncertain();
  std::optional<std::size_t> take_focus_request();

  // --- live retraining (gui/model/live_training.cpp): with auto-train on, every label change
  // retrains both classes on the train split in the background (poll() starts and adopts it);
  // the result becomes the thresholds, refreshes predictions, proposals and metrics, and adds a
  // point to the learning curve. Editing thresholds by hand turns it off (the caller does).
  bool auto_train() const { return live_.on(); }
  void set_auto_train(bool on) { live_.set_on(on); }  // on: retrains the current labels at the next poll
  bool auto_train_busy() const { return live_.busy(); }
  const std::vector<CurvePoint>& learning_curve() const { return live_.curve(); }
  // One line: what the last retraining used and how long it took, or why it failed.
  const std::string& auto_train_summary() const { return live_.summary(); }
  // Polls until no retraining is pending or running (tests; shutdown needs nothing: the job joins).
  void wait_for_auto_train(double now_s = 0);

  // --- training (background)
  void start_training(const TrainParams& params);
  void cancel_training() { training_.cancel(); }
  TrainingJob& training() { return training_; }
  const TrainingJob& training() const { return training_; }
  // Adopts the finished training's thresholds; false when there is none.
  bool apply_training_result();

  // Once per frame on the UI thread, with the time in seconds (glfwGetTime): takes finished
  // background work and saves settings changed more than `settings_save_delay_s` ago.
  void poll(double now_s = 0);
  static constexpr double settings_save_delay_s = 0.5;

 private:
  void load_current_pixels();
  void rebuild_features(std::size_t image);
  void rebuild_all_features();
  void reclassify();
  void resplit();  // after any change of labels, segments or the split spec; before recount()
  void recount();
  void after_label_change();
  void autosave();
  // The image's least certain unlabelled segment and its |decision margin| (review.cpp).
  struct Uncertain {
    std::size_t segment;
    double margin;
  };
  std::optional<Uncertain> least_certain(std::size_t image) const;
  // The review loop's training rule, shared by propose() and auto-train (review.cpp).
  static ProposalParams proposal_params();
  // Re-proposes every unlabelled segment that has a proposal slot with `t` (review.cpp).
  std::size_t refresh_proposals(const Thresholds& t);
  void start_auto_train();
  // Every segment of the project, in image order (labels kept); the labelled ones by split.
  std::vector<Segment> all_segments() const;
  // Every segment's gate (proposal_gate.hpp) in the same order; 1s where nothing is known.
  ProposalGate all_gates() const;
  // The gates of the labelled segments, in the order of labelled_by_split() (`test` false: the
  // train split, true: the test split) or, without `test`, of Project::labelled().
  ProposalGate labelled_gates(std::optional<bool> test = std::nullopt) const;
  std::pair<std::vector<Segment>, std::vector<Segment>> labelled_by_split() const;  // train, test
  void adopt_auto_train(const AutoTrainResult& result);
  ClassSwitch& class_switch(Label cls);
  const ClassSwitch& class_switch(Label cls) const;
  // Switches without clearing calibration's reason; on gives the class `when_on`.
  void switch_class(Label cls, bool on, const ClassThresholds& when_on);
  // What proposals start from: the project's thresholds, a class calibration turned off tried again.
  Thresholds proposal_start() const;
  // After proposals or a retraining: calibration's verdict on each class, and the guidance.
  void follow_proposals(const ProposalThresholds& made);

  Project project_;
  std::filesystem::path project_file_;
  ControllerOptions options_;
  bool settings_dirty_ = false;
  double settings_changed_at_ = -1;  // poll time of the first poll after the change
  std::size_t current_ = 0;
  cv::Mat pixels_;
  std::string image_error_;
  std::size_t image_generation_ = 0;
  std::optional<std::size_t> hovered_;
  LabelHistory history_;
  std::vector<std::vector<SegmentFeatures>> features_;  // per image, per segment
  std::vector<std::vector<Label>> predictions_;         // per image, per segment
  Counts train_counts_, test_counts_;
  std::vector<std::vector<char>> in_test_;  // per image, per segment: labelled and in the test split
  std::size_t train_segments_ = 0, test_segments_ = 0, test_images_ = 0;
  std::string split_error_;
  void take_saves(const ProjectSaver::Done& done);
  std::size_t save_count_ = 0;
  std::string save_error_;
  ProjectSaver saver_;  // before the jobs: they are stopped first, then the last save finishes
  ProjectDetection detection_;
  TrainingJob training_;
  CameraFitJob camera_fit_;
  std::optional<Thresholds> proposal_thresholds_;  // what the proposals were made with
  std::string proposal_summary_;
  std::optional<std::size_t> focus_request_;
  LiveRetraining live_{options_.auto_train};
  ClassSwitch switches_[2] = {{Thresholds{}.marking.thresholds, {}}, {Thresholds{}.boundary.thresholds, {}}};
  std::string guidance_;
  LeaveOneOut leave_one_out_;
};

}  // namespace fieldlines::studio
