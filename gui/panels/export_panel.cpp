// Export tab: write the robot's thresholds file (path entry + folder browser), show it, import one.
#include <algorithm>
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "fieldlines/detect/atomic_file.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
namespace fs = std::filesystem;

// A minimal folder browser: click a folder to enter it, ".." to go up; the chosen folder
// replaces the folder part of the export path.
void folder_browser(std::string& path) {
  fs::path current = fs::path(path).parent_path();
  if (current.empty()) current = fs::current_path();
  ImGui::TextDisabled("%s", current.string().c_str());
  ImGui::BeginChild("folders", {0, 120}, true);
  const std::string file = fs::path(path).filename().string();
  if (ImGui::Selectable("..")) path = (current.parent_path() / file).string();
  std::vector<fs::path> folders;
  std::error_code ec;
  for (fs::directory_iterator it(current, ec), end; !ec && it != end; it.increment(ec)) {
    if (it->is_directory(ec) && it->path().filename().string().rfind('.', 0) != 0) folders.push_back(it->path());
  }
  std::sort(folders.begin(), folders.end());
  for (const fs::path& folder : folders) {
    if (ImGui::Selectable((folder.filename().string() + "/").c_str())) path = (folder / file).string();
  }
  ImGui::EndChild();
}
}  // namespace

void draw_export_panel(studio::StudioController& controller, UiState& ui) {
  const Thresholds& t = controller.thresholds();
  ImGui::TextUnformatted("Current thresholds");
  if (ImGui::BeginTable("thresholds", 4, ImGuiTableFlags_Borders | ImGuiTableFlags_SizingStretchProp)) {
    for (const char* header : {"class", "min projection", "max angle (deg)", "min length"}) ImGui::TableSetupColumn(header);
    ImGui::TableHeadersRow();
    for (const auto& [name, c] : {std::pair{"marking", t.marking.thresholds}, std::pair{"boundary", t.boundary.thresholds}}) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(name);
      for (const float value : {c.min_projection, c.max_angle_deg, c.min_length}) {
        ImGui::TableNextColumn();
        ImGui::Text("%.2f", value);
      }
    }
    ImGui::EndTable();
  }
  ImGui::Separator();
  if (ui.export_path.empty() || fs::path(ui.export_path).is_relative()) {
    ui.export_path = (controller.project_file().parent_path() / fs::path(ui.export_path).filename()).string();
  }
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##path", &ui.export_path);
  folder_browser(ui.export_path);
  // Every action reports in one line under the buttons; a failure shows its reason instead.
  const auto act = [&](const char* button, auto&& action) {
    if (!ImGui::Button(button)) return;
    try {
      ui.export_message = action();
    } catch (const std::exception& e) {
      ui.export_message = e.what();
    }
  };
  act("Export for the robot", [&] {
    controller.export_thresholds(ui.export_path);
    ui.export_preview = read_file(ui.export_path);
    return "wrote " + ui.export_path;
  });
  ImGui::SameLine();
  act("Import", [&] {
    controller.import_thresholds(ui.export_path);
    ui.export_preview = read_file(ui.export_path);
    return "imported " + ui.export_path;
  });
  ImGui::SameLine();
  act("Export labels (CSV)", [&] {
    const fs::path csv = fs::path(ui.export_path).parent_path() /
                         (controller.project_file().stem().string() + "-labels.csv");
    const std::size_t rows = controller.export_labels_csv(csv);
    return "wrote " + std::to_string(rows) + " labelled segments to " + csv.string() +
           " (the authors' reference CSV; `fieldlines train` reads it)";
  });
  ImGui::TextWrapped("%s", ui.export_message.c_str());
  if (!ui.export_preview.empty()) {
    ImGui::BeginChild("preview", {0, 0}, true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(ui.export_preview.c_str());
    ImGui::EndChild();
  }
}

}  // namespace fieldlines::gui
