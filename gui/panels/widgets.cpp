// Small text widgets the side-bar tabs share (declared in panels.hpp).
#include <string>

#include <imgui.h>

#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

void help_marker(const char* text) {
  ImGui::TextDisabled("(?)");
  if (!ImGui::IsItemHovered()) return;
  // Above the marker and left of its right edge (it sits at the right of the side panel): what
  // follows below, e.g. the progress line, stays visible.
  ImGui::SetNextWindowPos({ImGui::GetItemRectMax().x, ImGui::GetItemRectMin().y - 4}, ImGuiCond_Always, {1, 1});
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(text);
  ImGui::EndTooltip();
}

bool class_switch(studio::StudioController& controller, Label cls) {
  const char* name = cls == Label::Marking ? "marking on" : "boundary on";
  bool on = controller.class_on(cls);
  if (ImGui::Checkbox(name, &on)) controller.set_class_on(cls, on);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("off: no segment is %s, in predictions, proposals and the exported file\n"
                      "(its thresholds never pass, as `fieldlines calibrate` writes a class it refuses)",
                      cls == Label::Marking ? "a marking" : "a boundary");
  }
  if (const std::string& why = controller.class_off_reason(cls); !why.empty()) {
    wrapped_hint("off by calibration: " + why);
  }
  return on;
}

void wrapped_text(const ImVec4& colour, const std::string& text) {
  ImGui::PushStyleColor(ImGuiCol_Text, colour);
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
}

void wrapped_hint(const std::string& text) { wrapped_text(ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled), text); }

}  // namespace fieldlines::gui
