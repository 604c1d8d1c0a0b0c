#include "gui/model/studio_files.hpp"

#include <vector>

#include <nlohmann/json.hpp>

#include "fieldlines/data/reference_csv.hpp"
#include "fieldlines/detect/thresholds_file.hpp"

namespace fieldlines::studio {

std::size_t export_labels_csv(const StudioController& controller, const std::filesystem::path& path) {
  const std::vector<ReferenceRow> rows = reference_rows_from_project(controller.project());
  write_reference_csv(path, rows);
  return rows.size();
}

void export_thresholds(const StudioController& controller, const std::filesystem::path& path) {
  const Project& project = controller.project();
  ThresholdsFile file;
  file.detector = project.detector;
  file.thresholds = project.thresholds;
  const auto metrics = [](const Counts& c) {
    const auto one = [](const ClassCounts& k) {
      return nlohmann::json{{"precision", k.precision()}, {"recall", k.recall()}, {"f1", k.f1()},
                            {"tp", k.tp}, {"fp", k.fp}, {"fn", k.fn}};
    };
    return nlohmann::json{{"marking", one(c.marking)}, {"boundary", one(c.boundary)}};
  };
  // An empty part has no figures (null, as `fieldlines train` writes an empty test part).
  const auto part = [&](const Counts& c, std::size_t segments) { return segments ? metrics(c) : nlohmann::json(nullptr); };
  // The split under the keys `fieldlines train` uses, so both provenances read alike.
  const std::size_t train_segments = controller.train_segment_count(), test_segments = controller.test_segment_count();
  file.provenance = {{"tool", "fieldlines-studio"},
                     {"project", controller.project_file().string()},
                     {"labelled_segments", controller.labelled_total()},
                     {"split", to_string(project.split.mode)},
                     {"train_fraction", project.split.train_fraction},
                     {"seed", project.split.seed},
                     {"counts", {{"train_segments", train_segments}, {"test_segments", test_segments}}},
                     {"train", part(controller.train_counts(), train_segments)},
                     {"test", part(controller.test_counts(), test_segments)}};
  // How the detector was chosen from the frames, under the key `fieldlines calibrate` uses.
  if (project.detector_choice.is_object()) file.provenance["detector"] = project.detector_choice;
  // Why a class is off, for whoever reads the file later: calibration's reason or the user's choice.
  for (const Label cls : kSwitchableClasses) {
    if (controller.class_on(cls)) continue;
    const std::string& why = controller.class_off_reason(cls);
    file.provenance["classes_off"][cls == Label::Marking ? "marking" : "boundary"] =
        why.empty() ? "switched off in the studio" : "calibration: " + why;
  }
  save_thresholds_file(path, file);
}

void import_thresholds(StudioController& controller, const std::filesystem::path& path) {
  const ThresholdsFile file = load_thresholds_file(path);
  controller.set_detector_params(file.detector);
  controller.set_thresholds(file.thresholds);
  // The file's classes are a person's choice, not calibration's verdict: P leaves them be.
  for (const Label cls : kSwitchableClasses) controller.set_class_on(cls, controller.class_on(cls));
  controller.flush();
}

}  // namespace fieldlines::studio
