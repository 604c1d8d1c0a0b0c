// Export tab: write the robot's thresholds file (path entry + folder browser), show it, import one.
// The form, its files and paths are gui/model/export_form.hpp's; this draws it.
#include <string>
#include <string_view>
#include <utility>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "gui/model/ellipsize.hpp"
#include "gui/model/export_form.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
// A minimal folder browser: click a folder to enter it, ".." to go up; the chosen folder
// replaces the folder part of the export path.
void folder_browser(studio::ExportForm& form) {
  const std::filesystem::path& folder = form.browsed_folder();
  wrapped_hint(folder.string());
  ImGui::BeginChild("folders", {0, 120}, true);
  std::filesystem::path chosen;
  if (ImGui::Selectable("..")) chosen = folder.parent_path();
  const auto measure = [](std::string_view t) { return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x; };
  for (const std::filesystem::path& f : form.subfolders(ImGui::GetTime())) {
    // A long name is cut to the list's width; the whole name shows on hover.
    const std::string name = f.filename().string() + "/";
    const std::string shown = studio::ellipsize(name, ImGui::GetContentRegionAvail().x, measure);
    if (ImGui::Selectable((shown + "##" + name).c_str())) chosen = f;
    if (shown != name && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", name.c_str());
  }
  ImGui::EndChild();
  if (!chosen.empty()) form.choose_folder(chosen);
}

const ImVec4 kErrorColour{1, 0.4f, 0.4f, 1};
}  // namespace

void draw_export_panel(studio::StudioController& controller, UiState& ui) {
  const Thresholds& t = controller.thresholds();
  ImGui::TextUnformatted("Current thresholds");
  if (ImGui::BeginTable("thresholds", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
    for (const char* header : {"class", "min projection", "max angle (deg)", "min length"}) ImGui::TableSetupColumn(header);
    ImGui::TableHeadersRow();
    for (const Label cls : studio::kSwitchableClasses) {
      const ClassThresholds& c = studio::class_thresholds(t, cls);
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(cls == Label::Marking ? "marking" : "boundary");
      for (const float value : {c.min_projection, c.max_angle_deg, c.min_length}) {
        ImGui::TableNextColumn();
        if (controller.class_on(cls)) ImGui::Text("%.2f", value);
        else ImGui::TextDisabled("off");
      }
    }
    ImGui::EndTable();
  }
  // Written into the file: an off class gets thresholds no segment passes.
  for (const Label cls : studio::kSwitchableClasses) class_switch(controller, cls);
  ImGui::Separator();
  studio::ExportForm& form = ui.export_form;
  form.update(controller);
  ImGui::TextUnformatted("Thresholds file for the robot");
  ImGui::SameLine();
  help_marker(("~ is your home folder ($HOME); a relative path starts in the project's folder,\n" + form.base().string() +
               "\nEnter exports (when the folder exists).")
                  .c_str());
  ImGui::SetNextItemWidth(-1);
  const bool enter = ImGui::InputText("##path", &form.path(), ImGuiInputTextFlags_EnterReturnsTrue);
  if (ImGui::IsItemEdited()) form.resolve();  // the line below says where this frame's text points
  const studio::ExportTarget& target = form.target();
  if (!target.ok()) {
    wrapped_text(kErrorColour, target.error);
  } else {
    wrapped_hint("-> " + target.path.string() + (target.from_base ? "  (from the project folder)" : ""));
    if (!target.folder_exists) {
      wrapped_text({1, 0.7f, 0.3f, 1}, "folder " + target.path.parent_path().string() + " does not exist yet");
    }
  }
  // Every action reports in one line under the buttons; a failure shows its reason instead.
  ImGui::BeginDisabled(!target.ok());
  bool export_now = enter && target.ok();  // without the folder: refused, saying why
  if (target.ok() && !target.folder_exists) {
    if (ImGui::Button("Create folder and export")) form.create_folder_and_export(controller);
  } else {
    export_now |= ImGui::Button("Export for the robot");
  }
  if (export_now) form.export_thresholds(controller);
  ImGui::SameLine();
  if (ImGui::Button("Import")) form.import_thresholds(controller);
  ImGui::SameLine();
  if (ImGui::Button("Export labels (CSV)")) form.export_labels_csv(controller);
  ImGui::EndDisabled();
  wrapped_text(form.failed() ? kErrorColour : ImGui::GetStyleColorVec4(ImGuiCol_Text), form.message());
  folder_browser(form);
  if (!form.preview().empty()) {
    ImGui::BeginChild("preview", {0, 0}, true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(form.preview().c_str());
    ImGui::EndChild();
  }
}

}  // namespace fieldlines::gui
