// Images tab: every image with its labelling progress, filters, and navigation.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <imgui.h>

#include "gui/model/shortcuts.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

void draw_images_panel(studio::StudioController& controller, UiState& ui) {
  if (ImGui::Button("< Prev")) controller.previous_image();
  ImGui::SameLine();
  if (ImGui::Button("Next >")) controller.next_image();
  ImGui::SameLine();
  const std::string next_with_errors = "Next with errors (" + studio::key_for(studio::Action::NextImageWithErrors) + ")";
  if (ImGui::Button(next_with_errors.c_str())) controller.next_image_with_errors();
  ImGui::Combo("filter", &ui.image_filter, "all\0not fully labelled\0with errors\0test split\0");
  ImGui::Combo("order", &ui.image_order, "file order\0least certain first\0");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("least certain first: images whose unlabelled segments lie closest to a\n"
                      "threshold boundary come first (%s jumps to the single least certain one)",
                      studio::key_for(studio::Action::FocusUncertain).c_str());
  }
  ImGui::Text("%zu labelled segments in %zu images", controller.labelled_total(), controller.image_count());
  if (!ui.recent_projects.empty() && ImGui::CollapsingHeader("Recent projects")) {
    for (const std::string& recent : ui.recent_projects) {
      if (ImGui::Selectable(recent.c_str(), recent == std::filesystem::absolute(controller.project_file()).string())) {
        ui.open_request = recent;
      }
    }
  }
  ImGui::Separator();
  ImGui::BeginChild("image list");
  std::vector<std::size_t> order(controller.image_count());
  if (ui.image_order == 1) {
    order = controller.images_by_uncertainty();
  } else {
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  }
  for (const std::size_t i : order) {
    const studio::ImageProgress p = controller.progress(i);
    const bool keep = ui.image_filter == 0 || (ui.image_filter == 1 && p.labelled < p.total) ||
                      (ui.image_filter == 2 && p.errors > 0) || (ui.image_filter == 3 && controller.is_test_image(i));
    if (!keep) continue;
    ImGui::PushID(static_cast<int>(i));
    const std::string& file = controller.project().images[i].path;
    if (ImGui::Selectable(file.c_str(), i == controller.current(), 0, {200, 0})) controller.select_image(i);
    ImGui::SameLine();
    const float fraction = p.total ? static_cast<float>(p.labelled) / static_cast<float>(p.total) : 0.0f;
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "%zu/%zu%s", p.labelled, p.total, controller.is_test_image(i) ? " test" : "");
    ImGui::ProgressBar(fraction, {110, 0}, overlay);
    if (p.errors > 0) {
      ImGui::SameLine();
      ImGui::TextColored({1, 0.5f, 0.3f, 1}, "%ld err", p.errors);
    }
    if (const std::string& failure = controller.detection_error(i); !failure.empty()) {
      ImGui::SameLine();
      ImGui::TextColored({1, 0.3f, 0.3f, 1}, "unreadable");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", failure.c_str());
    }
    ImGui::PopID();
  }
  ImGui::EndChild();
}

}  // namespace fieldlines::gui
