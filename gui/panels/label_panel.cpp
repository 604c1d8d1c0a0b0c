// Label tab: brush, overlay colouring and its legend, bulk actions, undo/redo, shortcut help.
#include <string>

#include <imgui.h>

#include "gui/panels/image_view.hpp"
#include "gui/model/shortcuts.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
// "Undo (Ctrl+Z)": the key from the shortcut table, so a caption never names a stale key.
std::string captioned(const char* text, studio::Action action) {
  const std::string key = studio::key_for(action);
  return key.empty() ? text : std::string(text) + " (" + key + ")";
}
}  // namespace

void draw_legend(studio::OverlayMode mode) {
  for (const studio::LegendEntry& entry : studio::legend(mode)) {
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = ImGui::GetTextLineHeight();
    draw_styled_line(ImGui::GetWindowDrawList(), {p.x, p.y + h / 2}, {p.x + 40, p.y + h / 2}, entry.style);
    ImGui::Dummy({46, h});
    ImGui::SameLine();
    ImGui::TextUnformatted(entry.text.data(), entry.text.data() + entry.text.size());
    if (!entry.detail.empty()) {  // the class's colour transition
      ImGui::SameLine();
      ImGui::TextDisabled("- %.*s", static_cast<int>(entry.detail.size()), entry.detail.data());
    }
  }
}

namespace {
// The four field feature layers (feature_layers.hpp), each captioned with its key.
void draw_feature_toggles(const studio::StudioController& controller, studio::FeatureLayers& layers) {
  ImGui::TextUnformatted("Field features on screen:");
  for (const studio::Shortcut& s : studio::shortcuts()) {
    if (s.action != studio::Action::ToggleFeatureLayer) continue;
    bool on = layers.on(s.layer);
    const std::string caption = std::string(studio::feature_layer_name(s.layer)) + " (" + studio::input_name(s) + ")";
    if (ImGui::Checkbox(caption.c_str(), &on)) layers.set(s.layer, on);
    if (s.layer == studio::FeatureLayer::Intersections || s.layer == studio::FeatureLayer::Stripes) continue;
    ImGui::SameLine();  // two per row
  }
  const FieldFeatures& f = controller.field_features();
  if (!layers.any()) return;
  ImGui::PushTextWrapPos(0);  // wrap at the panel's edge
  if (f.markings.empty() && f.intersections.empty() && f.ellipses.empty() && f.field_boundary.empty()) {
    ImGui::TextDisabled("none for this image: features come with a detection here (Thresholds tab, Re-detect all)");
  } else {
    ImGui::TextDisabled("this image: %zu stripes, %zu junctions, %zu circles, a boundary of %zu points",
                        f.markings.size(), f.intersections.size(), f.ellipses.size(), f.field_boundary.points.size());
  }
  ImGui::PopTextWrapPos();
}
}  // namespace

void draw_label_panel(studio::StudioController& controller, UiState& ui) {
  ImGui::TextUnformatted("Left click / rectangle labels as:");
  int brush = static_cast<int>(ui.image_view.brush);
  const auto brush_button = [&](const char* name, studio::Action action, Label label) {
    ImGui::RadioButton(captioned(name, action).c_str(), &brush, static_cast<int>(label));
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s: %s", name, palette::label_transition(label));
  };
  brush_button("marking", studio::Action::LabelMarking, Label::Marking);
  ImGui::SameLine();
  brush_button("boundary", studio::Action::LabelBoundary, Label::Boundary);
  ImGui::SameLine();
  brush_button("none", studio::Action::LabelNone, Label::None);
  ui.image_view.brush = static_cast<Label>(brush);

  ImGui::Separator();
  ImGui::TextUnformatted("Colour segments by:");
  int mode = static_cast<int>(ui.image_view.mode);
  ImGui::RadioButton("label", &mode, static_cast<int>(studio::OverlayMode::Labels));
  ImGui::SameLine();
  ImGui::RadioButton("prediction", &mode, static_cast<int>(studio::OverlayMode::Prediction));
  ImGui::SameLine();
  ImGui::RadioButton("agreement", &mode, static_cast<int>(studio::OverlayMode::Agreement));
  ui.image_view.mode = static_cast<studio::OverlayMode>(mode);
  ImGui::Checkbox("show segments", &ui.image_view.show_segments);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(120);
  float line_width = ui.image_view.settings.line_width;
  if (ImGui::SliderFloat("line width", &line_width, studio::ViewSettings::kMinLineWidth,
                         studio::ViewSettings::kMaxLineWidth, "%.1fx")) {
    ui.image_view.settings.set_line_width(line_width);
  }
  // On its own line: beside the two above it runs past the side panel's edge at 1280 px.
  ImGui::Checkbox("faint above the field", &ui.image_view.faint_above_field);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("segments above the field boundary (stands, walls, lights) drawn faint");
  draw_legend(ui.image_view.mode);
  ImGui::Checkbox("show paint with no segment", &ui.image_view.show_missed);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("tints cyan the bright, thin, colourless pixels on turf that no segment explains:\n"
                      "lines the detector missed (tight curves, worn paint), so there is nothing to label;\n"
                      "lower the detector's thresholds (Thresholds tab) and re-detect to find them");
  }
  if (ui.image_view.show_missed) {
    const MissedPaint& m = ui.image_view.missed.found();
    ImGui::SameLine();
    ImGui::TextDisabled("%zu px in %zu places", m.pixels, m.blobs);
  }

  draw_feature_toggles(controller, ui.image_view.settings.features);

  ImGui::Separator();
  if (ImGui::Button("Label the rest as none")) controller.label_rest_as_none();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("every unlabelled segment of this image becomes 'none'");
  ImGui::BeginDisabled(!controller.can_undo());
  if (ImGui::Button(captioned("Undo", studio::Action::Undo).c_str())) controller.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!controller.can_redo());
  if (ImGui::Button(captioned("Redo", studio::Action::Redo).c_str())) controller.redo();
  ImGui::EndDisabled();
  if (ImGui::Button(captioned("Fit to window", studio::Action::Fit).c_str())) ui.image_view.fit_requested = true;

  ImGui::Separator();
  if (ImGui::CollapsingHeader("Keys and mouse (hover a segment first)", ImGuiTreeNodeFlags_DefaultOpen)) {
    draw_shortcut_help();
  }
}

}  // namespace fieldlines::gui
