#include "gui/model/project_detection.hpp"

#include <algorithm>
#include <span>

#include "gui/model/open_project.hpp"

namespace fieldlines::studio {

std::string DetectionReport::summary() const {
  if (!error.empty()) return "detection could not start: " + error;
  if (detected == 0 && failed.empty()) return {};
  std::string out = "detected " + std::to_string(detected) + " image" + (detected == 1 ? "" : "s");
  if (detector_chosen) out += " with the detector chosen from them";
  if (labels_kept + labels_lost > 0) {
    out += "; " + std::to_string(labels_kept) + " labels kept";
    if (labels_lost > 0) out += ", " + std::to_string(labels_lost) + " could not be re-attached";
  }
  if (!failed.empty()) out += "; " + std::to_string(failed.size()) + " failed: " + failed.front().second;
  if (failed.size() > 1) out += " (and " + std::to_string(failed.size() - 1) + " more, see the Images tab)";
  return out;
}

bool needs_detection(const ImageEntry& image) { return image.segments.empty() && image.detect_ms == 0; }

bool chooses_detector(const Project& project) {
  return !project.images.empty() && project.detector == folder_detector() &&
         std::all_of(project.images.begin(), project.images.end(), [](const ImageEntry& e) { return needs_detection(e); });
}

void ProjectDetection::start(const Project& project, const std::filesystem::path& project_file, bool only_undetected,
                             const std::optional<GroundCamera>& camera, std::optional<bool> choose) {
  report_ = {};
  std::vector<DetectionJob::Item> items;
  for (std::size_t i = 0; i < project.images.size(); ++i) {
    if (!only_undetected || needs_detection(project.images[i])) {
      items.push_back({i, Project::resolve(project_file, project.images[i].path)});
    }
  }
  job_.start(std::move(items), project.detector, project.thresholds, camera, choose.value_or(chooses_detector(project)));
}

const std::vector<std::size_t>& ProjectDetection::poll(Project& project) {
  changed_.clear();
  for (DetectionResult& r : job_.poll()) {
    errors_.resize(project.images.size());
    errors_[r.image] = r.error;
    features_.resize(project.images.size());
    features_[r.image] = std::move(r.features);  // empty when it failed
    if (!r.error.empty()) {
      report_.failed.emplace_back(r.image, r.error);
      continue;
    }
    if (r.chosen_detector && r.chosen_detector != adopted_) {  // once per job: its results share it
      adopted_ = r.chosen_detector;
      if (!(adopted_->params == project.detector)) report_.detector_chosen = true;
      project.detector = adopted_->params;             // what the exported file will run
      project.detector_choice = adopted_->provenance;  // and why (its provenance)
    }
    // Human labels move to the new segments that match the old ones (the rest are Unlabelled).
    for (Segment& s : r.segments) s.label = Label::Unlabelled;
    gates_.resize(project.images.size());
    // The stripes check gates proposals only where the project's detector runs it.
    const std::span<const StripeVerdict> stripes =
        project.detector.stripes ? std::span<const StripeVerdict>(r.stripes) : std::span<const StripeVerdict>{};
    gates_[r.image] = ProposalGate::of(r.segments, features_[r.image].field_boundary, stripes);
    const ReattachStats stats = project.replace_segments(r.image, std::move(r.segments));
    ++report_.detected;
    report_.labels_kept += stats.kept;
    report_.labels_lost += stats.lost;
    project.images[r.image].detect_ms = r.detect_ms;
    changed_.push_back(r.image);
  }
  if (const auto& outcome = job_.outcome(); outcome && !outcome->ok()) report_.error = outcome->error();
  return changed_;
}

const std::string& ProjectDetection::error(std::size_t image) const {
  static const std::string none;
  return image < errors_.size() ? errors_[image] : none;
}

const FieldFeatures& ProjectDetection::features(std::size_t image) const {
  static const FieldFeatures none;
  return image < features_.size() ? features_[image] : none;
}

const ProposalGate& ProjectDetection::gate(std::size_t image) const {
  static const ProposalGate none;
  return image < gates_.size() ? gates_[image] : none;
}

void ProjectDetection::set_features(std::size_t image, FieldFeatures features) {
  if (image >= features_.size()) features_.resize(image + 1);
  features_[image] = std::move(features);
}

}  // namespace fieldlines::studio
