// Label tab: brush, overlay colouring and its legend, bulk actions, undo/redo, shortcut help.
#include <string>

#include <imgui.h>

#include "gui/image_view.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

void draw_legend(studio::OverlayMode mode) {
  for (const studio::LegendEntry& entry : studio::legend(mode)) {
    const ImVec2 p = ImGui::GetCursorScreenPos();
    const float h = ImGui::GetTextLineHeight();
    draw_styled_line(ImGui::GetWindowDrawList(), {p.x, p.y + h / 2}, {p.x + 40, p.y + h / 2}, entry.style);
    ImGui::Dummy({46, h});
    ImGui::SameLine();
    ImGui::TextUnformatted(entry.text.data(), entry.text.data() + entry.text.size());
  }
}

void draw_label_panel(studio::StudioController& controller, UiState& ui) {
  ImGui::TextUnformatted("Left click / rectangle labels as:");
  int brush = static_cast<int>(ui.image_view.brush);
  ImGui::RadioButton("marking (M)", &brush, static_cast<int>(Label::Marking));
  ImGui::SameLine();
  ImGui::RadioButton("boundary (B)", &brush, static_cast<int>(Label::Boundary));
  ImGui::SameLine();
  ImGui::RadioButton("none (N)", &brush, static_cast<int>(Label::None));
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
  draw_legend(ui.image_view.mode);

  ImGui::Separator();
  if (ImGui::Button("Label the rest as none")) controller.label_rest_as_none();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("every unlabelled segment of this image becomes 'none'");
  ImGui::BeginDisabled(!controller.can_undo());
  if (ImGui::Button("Undo (Ctrl+Z)")) controller.undo();
  ImGui::EndDisabled();
  ImGui::SameLine();
  ImGui::BeginDisabled(!controller.can_redo());
  if (ImGui::Button("Redo (Ctrl+Shift+Z)")) controller.redo();
  ImGui::EndDisabled();
  if (ImGui::Button("Fit to window (F)")) ui.image_view.fit_requested = true;

  ImGui::Separator();
  ImGui::TextDisabled("Hover a segment, then: M marking, B boundary,");
  ImGui::TextDisabled("N none, C clear. Right click: none.");
  ImGui::TextDisabled("Left drag: label a rectangle. Right/middle drag: pan.");
  ImGui::TextDisabled("Wheel: zoom at cursor. Left/Right: prev/next image.");
  ImGui::TextDisabled("E: next image with errors. F1..F6: panels.");
  ImGui::TextDisabled("Ctrl+Z undo, Ctrl+Shift+Z redo, Ctrl+T train.");
}

}  // namespace fieldlines::gui
