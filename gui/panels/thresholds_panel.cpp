// Thresholds tab: hand-tune each class's thresholds (re-classifies at once from cached features)
// and the detector's main parameters (used by the next background detection).
#include <imgui.h>

#include "gui/model/figures.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
// While a slider is dragged the controller saves after a short pause; releasing it saves at once.
bool class_sliders(const char* name, ClassThresholds& t, bool& released) {
  bool changed = false;
  ImGui::PushID(name);
  ImGui::TextUnformatted(name);
  changed |= ImGui::SliderFloat("min projection", &t.min_projection, 0, 255, "%.1f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  changed |= ImGui::SliderFloat("max angle (deg)", &t.max_angle_deg, 0, 90, "%.1f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  changed |= ImGui::SliderFloat("min length", &t.min_length, 0, 400, "%.0f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::PopID();
  return changed;
}

void counts_line(const char* name, const ClassCounts& c) {
  if (c.empty()) {
    ImGui::Text("%-9s n/a (no labelled or predicted segment)", name);
    return;
  }
  ImGui::Text("%-9s P %.3f  R %.3f  F1 %.3f  (TP %ld FP %ld FN %ld)", name, c.precision(), c.recall(), c.f1(), c.tp,
              c.fp, c.fn);
}
}  // namespace

void draw_thresholds_panel(studio::StudioController& controller, UiState& /*ui*/) {
  Thresholds t = controller.thresholds();
  if (controller.auto_train()) ImGui::TextDisabled("auto-train is on: moving a slider turns it off");
  bool released = false;
  bool changed = class_sliders("marking (white <-> green)", t.marking.thresholds, released);
  ImGui::Separator();
  changed |= class_sliders("boundary (black -> green)", t.boundary.thresholds, released);
  if (ImGui::Button("Reset to defaults")) {
    t = Thresholds{};
    changed = released = true;
  }
  if (changed) {
    controller.set_auto_train(false);  // otherwise the next label change overwrites the hand tuning
    controller.set_thresholds(t);
  }
  if (released) controller.flush();
  ImGui::Separator();
  ImGui::TextUnformatted("Labelled data with these thresholds, train split:");
  counts_line("marking", controller.train_counts().marking);
  counts_line("boundary", controller.train_counts().boundary);
  ImGui::TextDisabled("test split:");
  counts_line("marking", controller.test_counts().marking);
  counts_line("boundary", controller.test_counts().boundary);
  ImGui::TextWrapped("%s", controller.split_summary().c_str());

  ImGui::Separator();
  ImGui::TextUnformatted("Detector (applies to the next detection)");
  DetectorParams p = controller.detector_params();
  released = false;
  ImGui::SliderInt("gradient threshold", &p.gradient_threshold, 1, 255);
  released |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SliderInt("anchor threshold", &p.anchor_threshold, 0, 64);
  released |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SliderInt("min line length", &p.min_line_length, 5, 200);
  released |= ImGui::IsItemDeactivatedAfterEdit();
  float sigma = static_cast<float>(p.gaussian_sigma);
  if (ImGui::SliderFloat("gaussian sigma", &sigma, 0.1f, 5)) p.gaussian_sigma = sigma;
  released |= ImGui::IsItemDeactivatedAfterEdit();
  float validation = static_cast<float>(p.validation_threshold);
  if (ImGui::SliderFloat("validation (rad)", &validation, 0.01f, 1)) p.validation_threshold = validation;
  released |= ImGui::IsItemDeactivatedAfterEdit();
  controller.set_detector_params(p);
  if (released) controller.flush();
  studio::DetectionJob& job = controller.detection();
  if (job.running()) {
    ImGui::ProgressBar(job.progress(), {-1, 0});
    if (ImGui::Button("Stop detection")) job.cancel();
  } else {
    if (ImGui::Button("Detect new images")) controller.detect_all(true);
    ImGui::SameLine();
    // Labels follow the new segments by geometry; the status bar says how many could not.
    if (ImGui::Button("Re-detect all")) controller.detect_all(false);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Detect every image again with these parameters; labels move to the new segments\n"
                        "that overlap the old ones (same direction, within a few pixels)");
    }
  }
}

}  // namespace fieldlines::gui
