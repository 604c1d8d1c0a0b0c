// Thresholds tab: hand-tune each class's thresholds (re-classifies at once from cached features)
// and the detector's main parameters (used by the next background detection).
#include <algorithm>
#include <string>
#include <variant>

#include <imgui.h>

#include "fieldlines/detect/detector_params.hpp"
#include "gui/model/figures.hpp"
#include "gui/model/leave_one_out.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
// A slider's bar takes what its label leaves of the panel's width, so the label is never cut.
void fit_next_slider(const char* label) {
  const float avail = ImGui::GetContentRegionAvail().x;
  const float text = ImGui::CalcTextSize(label, nullptr, true).x + ImGui::GetStyle().ItemInnerSpacing.x;
  ImGui::SetNextItemWidth(std::max(avail - text, avail * 0.35f));
}

// While a slider is dragged the controller saves after a short pause; releasing it saves at once.
bool class_sliders(const char* name, ClassThresholds& t, bool& released) {
  bool changed = false;
  ImGui::PushID(name);
  ImGui::TextUnformatted(name);
  fit_next_slider("min projection");
  changed |= ImGui::SliderFloat("min projection", &t.min_projection, 0, 255, "%.1f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  fit_next_slider("max angle (deg)");
  changed |= ImGui::SliderFloat("max angle (deg)", &t.max_angle_deg, 0, 90, "%.1f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  fit_next_slider("min length");
  changed |= ImGui::SliderFloat("min length", &t.min_length, 0, 400, "%.0f");
  released |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::PopID();
  return changed;
}

// One detector parameter on a slider over its spec's span, its meaning and range as the tooltip.
// Returns whether the slider was released after an edit.
bool detector_slider(const ParamSpec& spec, DetectorParams& p) {
  std::string label(spec.name);
  std::replace(label.begin(), label.end(), '_', ' ');
  if (!spec.unit.empty()) label += " (" + std::string(spec.unit) + ")";
  const auto lo = static_cast<float>(spec.slider.lo), hi = static_cast<float>(spec.slider.hi);
  fit_next_slider(label.c_str());
  if (const auto* member = std::get_if<int DetectorParams::*>(&spec.member)) {
    ImGui::SliderInt(label.c_str(), &(p.*(*member)), static_cast<int>(lo), static_cast<int>(hi));
  } else if (const auto* real = std::get_if<double DetectorParams::*>(&spec.member)) {
    float v = static_cast<float>(p.*(*real));
    if (ImGui::SliderFloat(label.c_str(), &v, lo, hi)) p.*(*real) = v;
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("%.*s\nvalid range %s", static_cast<int>(spec.help.size()), spec.help.data(),
                      spec.range.to_string().c_str());
  return ImGui::IsItemDeactivatedAfterEdit();
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
  if (controller.auto_train()) ImGui::TextDisabled("auto-train is on: moving a slider turns it off");
  bool released = false;
  const auto hand_tuned = [&](const Thresholds& t) {
    controller.set_auto_train(false);  // otherwise the next label change overwrites the hand tuning
    controller.set_thresholds(t);
  };
  for (const Label cls : studio::kSwitchableClasses) {
    if (cls == Label::Boundary) ImGui::Separator();
    const bool on = class_switch(controller, cls);
    Thresholds t = controller.thresholds();  // after the switch, which may change them
    ImGui::BeginDisabled(!on);
    if (class_sliders(cls == Label::Marking ? "marking (white <-> green)" : "boundary (black -> green)",
                      studio::class_thresholds(t, cls), released))
      hand_tuned(t);
    ImGui::EndDisabled();
  }
  if (ImGui::Button("Reset to defaults")) {
    hand_tuned(Thresholds{});
    released = true;
  }
  if (released) controller.flush();
  ImGui::Separator();
  ImGui::TextUnformatted("Labelled data with these thresholds, train split:");
  counts_line("marking", controller.train_counts().marking);
  counts_line("boundary", controller.train_counts().boundary);
  ImGui::TextDisabled("test split:");
  if (const std::string few = studio::not_enough_to_judge(controller.test_image_count());
      controller.test_segment_count() && !few.empty()) {
    wrapped_hint(few + " (Metrics tab: leave-one-image-out figures)");
  } else {
    counts_line("marking", controller.test_counts().marking);
    counts_line("boundary", controller.test_counts().boundary);
  }
  ImGui::TextWrapped("%s", controller.split_summary().c_str());

  ImGui::Separator();
  ImGui::TextUnformatted("Detector (applies to the next detection)");
  DetectorParams p = controller.detector_params();
  released = false;
  for (const ParamSpec& spec : kDetectorParamSpecs)
    if (!spec.slider.empty()) released |= detector_slider(spec, p);
  controller.set_detector_params(p);
  if (released) controller.flush();
  studio::DetectionJob& job = controller.detection();
  if (job.running()) {
    ImGui::ProgressBar(job.bar_progress(), {-1, 0}, job.bar_text().c_str());
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
    // Its own line: three buttons overrun the side panel.
    if (ImGui::Button("Choose the detector from the frames")) controller.choose_detector_from_frames();
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("Measure every image and choose the detector as `fieldlines calibrate` does (a\n"
                        "folder's first detection does this), then detect every image again; labels\n"
                        "move to the new segments as with Re-detect all");
    }
  }
}

}  // namespace fieldlines::gui
