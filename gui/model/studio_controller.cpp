// Over ~400 lines: the controller is the studio's one owner of the project and its caches
// (features, predictions, split, counts); the review loop already lives apart (review.cpp).
#include "gui/model/studio_controller.hpp"

#include <algorithm>
#include <cmath>
#include <exception>

#include "fieldlines/detect/error.hpp"
#include "fieldlines/data/image_io.hpp"
#include "fieldlines/train/calibrate.hpp"
#include "fieldlines/train/splits.hpp"

namespace fieldlines::studio {

StudioController::StudioController(Project project, std::filesystem::path project_file, ControllerOptions options)
    : project_(std::move(project)), project_file_(std::move(project_file)), options_(options) {
  resplit();
  rebuild_all_features();
  load_current_pixels();
}

// ---------------------------------------------------------------- navigation

std::filesystem::path StudioController::image_path(std::size_t index) const {
  return Project::resolve(project_file_, project_.images.at(index).path);
}

bool StudioController::needs_detection(std::size_t index) const {
  return studio::needs_detection(project_.images.at(index));
}

void StudioController::select_image(std::size_t index) {
  if (index >= image_count() || index == current_) return;
  current_ = index;
  hovered_.reset();
  load_current_pixels();
}

void StudioController::next_image() {
  if (image_count() > 0) select_image((current_ + 1) % image_count());
}

void StudioController::previous_image() {
  if (image_count() > 0) select_image((current_ + image_count() - 1) % image_count());
}

bool StudioController::next_image_with_errors() {
  for (std::size_t step = 1; step <= image_count(); ++step) {
    const std::size_t i = (current_ + step) % image_count();
    if (progress(i).errors > 0) {
      select_image(i);
      return true;
    }
  }
  return false;
}

void StudioController::load_current_pixels() {
  pixels_.release();
  image_error_.clear();
  ++image_generation_;
  if (!options_.load_pixels || image_count() == 0) return;
  try {
    pixels_ = to_bgr8(load_image(image_path(current_))).clone();
  } catch (const std::exception& e) {
    image_error_ = e.what();
  }
}

// ---------------------------------------------------------------- segments

std::span<const Segment> StudioController::segments() const {
  if (image_count() == 0) return {};
  return project_.images[current_].segments;
}

std::span<const Label> StudioController::predictions() const {
  if (image_count() == 0) return {};
  return predictions_[current_];
}

const SegmentFeatures& StudioController::features(std::size_t segment) const {
  return features_.at(current_).at(segment);
}

void StudioController::set_hovered(std::optional<std::size_t> segment) {
  hovered_ = segment && *segment < segments().size() ? segment : std::nullopt;
}

void StudioController::rebuild_features(std::size_t image) {
  const auto& segs = project_.images[image].segments;
  auto& f = features_[image];
  auto& p = predictions_[image];
  f.resize(segs.size());
  p.resize(segs.size());
  for (std::size_t i = 0; i < segs.size(); ++i) {
    f[i] = compute_features(segs[i], project_.thresholds);
    p[i] = classify(f[i], project_.thresholds);
  }
}

void StudioController::rebuild_all_features() {
  features_.assign(image_count(), {});
  predictions_.assign(image_count(), {});
  for (std::size_t i = 0; i < image_count(); ++i) rebuild_features(i);
  recount();
}

// ---------------------------------------------------------------- labelling

void StudioController::after_label_change() {
  live_.labels_changed();
  resplit();
  recount();
  autosave();
}

bool StudioController::label(std::span<const std::size_t> segments, Label label) {
  if (image_count() == 0) return false;
  std::vector<SegmentRef> refs;
  for (const std::size_t i : segments) {
    if (i < project_.images[current_].segments.size()) refs.push_back({current_, i});
  }
  if (!history_.apply(project_, refs, label, std::string("label ") + std::string(to_string(label)))) return false;
  after_label_change();
  return true;
}

bool StudioController::label_hovered(Label label) {
  if (!hovered_) return false;
  const std::size_t one[] = {*hovered_};
  return this->label(one, label);
}

bool StudioController::label_rest_as_none() {
  std::vector<std::size_t> rest;
  const auto segs = segments();
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (segs[i].label == Label::Unlabelled) rest.push_back(i);
  }
  return label(rest, Label::None);
}

bool StudioController::undo() {
  const LabelCommand* next = history_.next_undo();
  if (!next || next->edits.empty()) return false;
  select_image(next->edits.front().ref.image);  // show the user what changes
  if (!history_.undo(project_)) return false;
  after_label_change();
  return true;
}

bool StudioController::redo() {
  const LabelCommand* next = history_.next_redo();
  if (!next || next->edits.empty()) return false;
  select_image(next->edits.front().ref.image);
  if (!history_.redo(project_)) return false;
  after_label_change();
  return true;
}

// ---------------------------------------------------------------- thresholds and metrics

void StudioController::set_thresholds(const Thresholds& thresholds) {
  if (thresholds == project_.thresholds) return;
  settings_dirty_ = true;
  settings_changed_at_ = -1;
  const bool same_features = thresholds.boundary.from == project_.thresholds.boundary.from &&
                             thresholds.boundary.to == project_.thresholds.boundary.to &&
                             thresholds.marking.from == project_.thresholds.marking.from &&
                             thresholds.marking.to == project_.thresholds.marking.to &&
                             thresholds.boundary.two_sided == project_.thresholds.boundary.two_sided &&
                             thresholds.marking.two_sided == project_.thresholds.marking.two_sided &&
                             thresholds.mode == project_.thresholds.mode && thresholds.reference_pi == project_.thresholds.reference_pi;
  project_.thresholds = thresholds;
  if (!same_features) {
    rebuild_all_features();
    return;
  }
  reclassify();
}

void StudioController::reclassify() {
  for (std::size_t img = 0; img < image_count(); ++img) {
    for (std::size_t i = 0; i < features_[img].size(); ++i) predictions_[img][i] = classify(features_[img][i], project_.thresholds);
  }
  recount();
}

void StudioController::set_split_spec(const SplitSpec& spec) {
  if (spec == project_.split) return;
  project_.split = spec;
  settings_dirty_ = true;
  settings_changed_at_ = -1;
  resplit();
  recount();
}

bool StudioController::is_test_image(std::size_t index) const {
  if (index >= in_test_.size()) return false;
  return std::find(in_test_[index].begin(), in_test_[index].end(), 1) != in_test_[index].end();
}

bool StudioController::is_test_segment(std::size_t image, std::size_t segment) const {
  return image < in_test_.size() && segment < in_test_[image].size() && in_test_[image][segment];
}

void StudioController::resplit() {
  in_test_.assign(image_count(), {});
  train_segments_ = test_segments_ = test_images_ = 0;
  split_error_.clear();
  for (std::size_t img = 0; img < image_count(); ++img) in_test_[img].assign(project_.images[img].segments.size(), 0);
  // The very set `fieldlines train project.json` splits: labelled segments, image by image.
  const LabelledSet labelled = project_.labelled();
  if (labelled.size() == 0) return;
  Split split;
  try {
    split = split_train_test(labelled, project_.split);
  } catch (const std::exception& e) {
    split_error_ = e.what();  // a bad spec: everything counts as train, the summary says why
    train_segments_ = labelled.size();
    return;
  }
  std::vector<char> test_row(labelled.size(), 0);
  for (const std::size_t row : split.test) test_row[row] = 1;
  // labelled() lists labelled segments in image order, then segment order: row k is the k-th here.
  std::size_t row = 0;
  for (std::size_t img = 0; img < image_count(); ++img) {
    const auto& segs = project_.images[img].segments;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (segs[i].label != Label::Unlabelled) in_test_[img][i] = test_row[row++];
    }
    test_images_ += is_test_image(img);
  }
  train_segments_ = split.train.size();
  test_segments_ = split.test.size();
}

std::string StudioController::split_summary() const {
  const SplitSpec& spec = project_.split;
  const bool by_image = spec.mode == SplitMode::ByImage;
  const std::string how = std::string("split by ") + std::string(to_string(spec.mode)) + ", " +
                          std::to_string(static_cast<int>(std::lround(spec.train_fraction * 100))) + " % train, seed " +
                          std::to_string(spec.seed);
  if (!split_error_.empty()) return "no test split: " + split_error_;
  const std::size_t labelled = train_segments_ + test_segments_;
  if (labelled == 0) return "no labelled segments yet, so no test split (" + how + ")";
  if (test_segments_ == 0) {
    return "test split empty: all " + std::to_string(labelled) + " labelled segments fall in train (" + how +
           "); " + (by_image ? "label another image" : "label more segments") + " or lower the train fraction";
  }
  return "test split: " + std::to_string(test_segments_) + " of " + std::to_string(labelled) +
         " labelled segments in " + std::to_string(test_images_) + " image" + (test_images_ == 1 ? "" : "s") + " (" +
         how + ")";
}

void StudioController::recount() {
  train_counts_ = {};
  test_counts_ = {};
  for (std::size_t img = 0; img < image_count(); ++img) {
    const auto& segs = project_.images[img].segments;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (segs[i].label != Label::Unlabelled) {
        tally(is_test_segment(img, i) ? test_counts_ : train_counts_, segs[i].label, predictions_[img][i]);
      }
    }
  }
}

ImageProgress StudioController::progress(std::size_t image) const {
  ImageProgress p;
  const auto& segs = project_.images.at(image).segments;
  p.total = segs.size();
  for (std::size_t i = 0; i < segs.size(); ++i) {
    if (segs[i].label == Label::Unlabelled) continue;
    ++p.labelled;
    if (segs[i].label != predictions_[image][i]) ++p.errors;
  }
  return p;
}

std::size_t StudioController::labelled_total() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < image_count(); ++i) n += progress(i).labelled;
  return n;
}

// ---------------------------------------------------------------- saving

void StudioController::save() {
  project_.save(project_file_);
  ++save_count_;
  settings_dirty_ = false;
}

void StudioController::flush() {
  if (settings_dirty_) autosave();
}

void StudioController::set_detector_params(const DetectorParams& params) {
  if (params == project_.detector) return;
  project_.detector = params;
  project_.detector_choice = nullptr;  // set by hand: no longer what the frames chose
  settings_dirty_ = true;
  settings_changed_at_ = -1;
}

void StudioController::autosave() {
  if (!options_.autosave) return;
  if (options_.background_save) {
    saver_.save(project_, project_file_);  // a copy: the UI thread goes on editing its own
    settings_dirty_ = false;               // a failed write sets it again (take_saves)
    return;
  }
  try {
    save();
    save_error_.clear();
  } catch (const std::exception& e) {
    save_error_ = e.what();  // shown in the status bar; the edit stays in memory
  }
}

void StudioController::take_saves(const ProjectSaver::Done& done) {
  save_count_ += done.saved;
  if (!done.error.empty()) {
    save_error_ = done.error;  // shown in the status bar; retried after the settings delay
    settings_dirty_ = true;
    settings_changed_at_ = -1;
  } else if (done.saved > 0) {
    save_error_.clear();
  }
}

std::string StudioController::finish_saves() {
  take_saves(saver_.finish());
  return save_error_;
}

// ---------------------------------------------------------------- background jobs

void StudioController::set_camera(const std::optional<GroundCamera>& camera) {
  if (camera) validate(*camera);
  options_.camera = camera;
}

void StudioController::detect_all(bool only_undetected) {
  detection_.start(project_, project_file_, only_undetected, options_.camera);
}

void StudioController::choose_detector_from_frames() {
  detection_.start(project_, project_file_, false, options_.camera, true);
}

std::vector<Segment> StudioController::all_segments() const {
  std::vector<Segment> all;
  for (const ImageEntry& e : project_.images) all.insert(all.end(), e.segments.begin(), e.segments.end());
  return all;
}

ProposalGate StudioController::all_gates() const {
  ProposalGate all;
  for (std::size_t img = 0; img < image_count(); ++img) {
    const std::size_t n = project_.images[img].segments.size();
    if (const ProposalGate& g = detection_.gate(img); g.covers(n)) {
      all.may_mark.insert(all.may_mark.end(), g.may_mark.begin(), g.may_mark.end());
      all.may_bound.insert(all.may_bound.end(), g.may_bound.begin(), g.may_bound.end());
    } else {
      all.may_mark.insert(all.may_mark.end(), n, 1);
      all.may_bound.insert(all.may_bound.end(), n, 1);
    }
  }
  return all;
}

ProposalGate StudioController::labelled_gates(std::optional<bool> test) const {
  ProposalGate out;
  for (std::size_t img = 0; img < image_count(); ++img) {
    const auto& segs = project_.images[img].segments;
    const ProposalGate& g = detection_.gate(img);
    const bool known = g.covers(segs.size());
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (segs[i].label == Label::Unlabelled || (test && is_test_segment(img, i) != *test)) continue;
      out.may_mark.push_back(known ? g.may_mark[i] : 1);
      out.may_bound.push_back(known ? g.may_bound[i] : 1);
    }
  }
  return out;
}

std::pair<std::vector<Segment>, std::vector<Segment>> StudioController::labelled_by_split() const {
  std::pair<std::vector<Segment>, std::vector<Segment>> split;
  for (std::size_t img = 0; img < image_count(); ++img) {
    const auto& segs = project_.images[img].segments;
    for (std::size_t i = 0; i < segs.size(); ++i) {
      if (segs[i].label != Label::Unlabelled) (is_test_segment(img, i) ? split.second : split.first).push_back(segs[i]);
    }
  }
  return split;
}

void StudioController::start_training(const TrainParams& params) {
  auto [train_set, test_set] = labelled_by_split();
  training_.start(std::move(train_set), std::move(test_set), project_.thresholds, params, labelled_gates(false),
                  labelled_gates(true));
}

double StudioController::current_detect_ms() const {
  return image_count() ? project_.images[current_].detect_ms : 0;
}

double StudioController::mean_detect_ms() const {
  double total = 0;
  std::size_t n = 0;
  for (const ImageEntry& e : project_.images) {
    if (e.detect_ms > 0) {
      total += e.detect_ms;
      ++n;
    }
  }
  return n ? total / static_cast<double>(n) : 0;
}

bool StudioController::apply_training_result() {
  const auto& outcome = training_.outcome();
  if (!outcome || !outcome->ok()) return false;
  Thresholds t = outcome->value().run.thresholds;
  // PSO over both classes fits a switched-off one too: the switch stands.
  for (const Label cls : kSwitchableClasses)
    if (!class_on(cls)) class_thresholds(t, cls) = class_thresholds(project_.thresholds, cls);
  set_thresholds(t);
  flush();  // a deliberate act, not a drag: on disk at once
  return true;
}

void StudioController::poll(double now_s) {
  training_.poll();
  camera_fit_.poll();
  take_saves(saver_.poll());
  if (const auto retrained = live_.poll()) adopt_auto_train(*retrained);
  if (settings_dirty_) {
    if (settings_changed_at_ < 0) settings_changed_at_ = now_s;
    if (now_s - settings_changed_at_ >= settings_save_delay_s) {
      autosave();
      if (settings_dirty_) settings_changed_at_ = now_s;  // failed: retry after another delay
    }
  }
  const std::vector<std::size_t>& detected = detection_.poll(project_);
  for (const std::size_t image : detected) rebuild_features(image);
  const bool changed = !detected.empty();
  if (changed) {
    history_.clear();  // edits may refer to segments that no longer exist
    if (hovered_ && *hovered_ >= segments().size()) hovered_.reset();
    live_.labels_changed();
    resplit();
    recount();
    autosave();
  }
  // Started after the settings save above, so the save never waits on it; one run at a time,
  // and a change made while one runs starts the next when it is adopted.
  if (live_.due()) start_auto_train();
}

}  // namespace fieldlines::studio
