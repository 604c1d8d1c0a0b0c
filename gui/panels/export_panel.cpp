// Export tab: write the robot's thresholds file (path entry + folder browser), show it, import one.
// The typed path is read by gui/model/export_path.hpp (~, the relative base, a missing folder).
#include <exception>
#include <filesystem>
#include <string>
#include <system_error>

#include <imgui.h>
#include <imgui_stdlib.h>

#include "fieldlines/detect/atomic_file.hpp"
#include "gui/model/export_path.hpp"
#include "gui/model/folder_listing.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
namespace fs = std::filesystem;

// A minimal folder browser: click a folder to enter it, ".." to go up; the chosen folder
// replaces the folder part of the export path. Starts in the nearest existing folder of `folder`.
void folder_browser(studio::FolderListing& listing, std::string& path, fs::path folder, const std::string& file) {
  std::error_code ec;
  while (folder.has_relative_path() && !fs::is_directory(folder, ec)) folder = folder.parent_path();
  ImGui::TextDisabled("%s", folder.string().c_str());
  ImGui::BeginChild("folders", {0, 120}, true);
  if (ImGui::Selectable("..")) path = (folder.parent_path() / file).string();
  for (const fs::path& f : listing.subfolders(folder, ImGui::GetTime())) {
    if (ImGui::Selectable((f.filename().string() + "/").c_str())) path = (f / file).string();
  }
  ImGui::EndChild();
}

const ImVec4 kErrorColour{1, 0.4f, 0.4f, 1};

// The path as written, with symbolic links and ".." resolved, for the "wrote ..." line.
std::string written_path(const fs::path& path) {
  std::error_code ec;
  const fs::path real = fs::weakly_canonical(path, ec);
  return (ec ? path : real).string();
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
  // A newly opened project starts from its own default, never inside its image folder.
  const fs::path& project = controller.project_file();
  if (ui.export_path_project != project.string()) {
    ui.export_path_project = project.string();
    ui.export_path = studio::default_export_path(project, controller.project().images).string();
    ui.export_message.clear();
    ui.export_preview.clear();
  }
  // Relative paths start in the project's folder: the same on every launch, from any shell.
  const fs::path base = fs::absolute(project).lexically_normal().parent_path();
  ImGui::TextUnformatted("Thresholds file for the robot");
  ImGui::SameLine();
  help_marker(("~ is your home folder ($HOME); a relative path starts in the project's folder,\n" + base.string() +
               "\nEnter exports (when the folder exists).")
                  .c_str());
  ImGui::SetNextItemWidth(-1);
  const bool enter = ImGui::InputText("##path", &ui.export_path, ImGuiInputTextFlags_EnterReturnsTrue);
  // Resolved every frame, so the line below always says where Export will write.
  const studio::ExportTarget target = studio::resolve_export_path(ui.export_path, base, studio::home_folder());
  if (!target.ok()) {
    wrapped_text(kErrorColour, target.error);
  } else {
    wrapped_hint("-> " + target.path.string() + (target.from_base ? "  (from the project folder)" : ""));
    if (!target.folder_exists) {
      wrapped_text({1, 0.7f, 0.3f, 1}, "folder " + target.path.parent_path().string() + " does not exist yet");
    }
  }
  // Every action reports in one line under the buttons; a failure shows its reason instead.
  const auto act = [&](bool pressed, auto&& action) {
    if (!pressed) return;
    try {
      ui.export_message = action();
      ui.export_failed = false;
    } catch (const std::exception& e) {
      ui.export_message = e.what();
      ui.export_failed = true;
    }
  };
  const auto export_to = [&] {
    controller.export_thresholds(target.path);
    ui.export_preview = read_file(target.path);
    return "wrote " + written_path(target.path);
  };
  ImGui::BeginDisabled(!target.ok());
  if (target.ok() && !target.folder_exists) {
    // Creating folders is never a side effect of a typo: it takes this button, not Enter.
    act(ImGui::Button("Create folder and export"), [&] {
      studio::create_parent_folders(target.path);
      return export_to();
    });
    if (enter) {
      ui.export_message = "the folder does not exist: press \"Create folder and export\" to create it";
      ui.export_failed = true;
    }
  } else {
    act(ImGui::Button("Export for the robot") || (enter && target.ok()), export_to);
  }
  ImGui::SameLine();
  act(ImGui::Button("Import"), [&] {
    controller.import_thresholds(target.path);
    ui.export_preview = read_file(target.path);
    return "imported " + written_path(target.path);
  });
  ImGui::SameLine();
  act(ImGui::Button("Export labels (CSV)"), [&] {
    const fs::path csv = target.path.parent_path() / (project.stem().string() + "-labels.csv");
    const std::size_t rows = controller.export_labels_csv(csv);
    return "wrote " + std::to_string(rows) + " labelled segments to " + written_path(csv) +
           " (the authors' reference CSV; `fieldlines train` reads it)";
  });
  ImGui::EndDisabled();
  wrapped_text(ui.export_failed ? kErrorColour : ImGui::GetStyleColorVec4(ImGuiCol_Text), ui.export_message);
  folder_browser(ui.export_folders, ui.export_path, target.ok() ? target.path.parent_path() : base,
                 target.ok() ? target.path.filename().string() : "robot-thresholds.json");
  if (!ui.export_preview.empty()) {
    ImGui::BeginChild("preview", {0, 0}, true, ImGuiWindowFlags_HorizontalScrollbar);
    ImGui::TextUnformatted(ui.export_preview.c_str());
    ImGui::EndChild();
  }
}

}  // namespace fieldlines::gui
