#include "gui/panels/studio_window.hpp"

#include <cstdio>
#include <string>

#include <imgui.h>

#include "gui/model/shortcuts.hpp"
#include "gui/panels/image_view.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

void draw_shortcut_help() {
  if (!ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_SizingFixedFit)) return;
  for (const studio::Shortcut& s : studio::shortcuts()) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(studio::input_name(s).c_str());
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%.*s", static_cast<int>(s.description.size()), s.description.data());
  }
  ImGui::EndTable();
}

namespace {

void draw_status_bar(const studio::StudioController& controller, const UiState& ui) {
  const auto segments = controller.segments();
  std::size_t labelled = 0;
  for (const Segment& s : segments) labelled += s.label != Label::Unlabelled;
  ImGui::Text("image %zu/%zu  %s  |  %zu/%zu labelled  |  %zu to review  |  zoom %.0f%%  |  frame %.1f ms",
              controller.image_count() ? controller.current() + 1 : 0, controller.image_count(),
              controller.image_count() ? controller.project().images[controller.current()].path.c_str() : "-",
              labelled, segments.size(), controller.to_review(), ui.image_view.view.scale() * 100,
              ui.frame_stats ? ui.frame_stats->median_ms() : 0.0);
  if (!ui.status_message.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("  %s", ui.status_message.c_str());
  }
  if (const studio::DetectionJob& job = controller.detection(); job.running()) {
    // Visible from every tab: detection of a whole folder takes a while on a laptop.
    ImGui::SameLine();
    char overlay[48];
    std::snprintf(overlay, sizeof overlay, "detecting %zu/%zu", job.done(), job.total());
    ImGui::ProgressBar(job.progress(), {200, 0}, overlay);
  } else if (const std::string detection = controller.detection_report().summary(); !detection.empty()) {
    ImGui::SameLine();
    const bool failed = !controller.detection_report().failed.empty();
    ImGui::TextColored(failed ? ImVec4{1, 0.5f, 0.3f, 1} : ImVec4{0.6f, 0.6f, 0.6f, 1}, "  %s", detection.c_str());
  }
  if (!controller.save_error().empty()) {
    ImGui::SameLine();
    ImGui::TextColored({1, 0.4f, 0.4f, 1}, "  autosave failed: %s", controller.save_error().c_str());
  } else if (controller.save_count() > 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("  saved");
  }
}

}  // namespace

void draw_studio(studio::StudioController& controller, UiState& ui, const CanvasTexture& texture) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->WorkPos);
  ImGui::SetNextWindowSize(viewport->WorkSize);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {6, 6});
  ImGui::Begin("fieldlines studio", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoSavedSettings);
  ImGui::PopStyleVar(2);

  const float side_width = 400;
  const float status_height = ImGui::GetFrameHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  draw_image_view(controller, ui.image_view, texture, {avail.x - side_width - 6, avail.y - status_height});
  ImGui::SameLine();
  ImGui::BeginChild("side", {side_width, avail.y - status_height});
  if (ImGui::BeginTabBar("panels")) {
    for (int p = 0; p < static_cast<int>(Panel::Count); ++p) {
      const Panel panel = static_cast<Panel>(p);
      const ImGuiTabItemFlags flags =
          ui.panel_request_pending && ui.requested_panel == panel ? ImGuiTabItemFlags_SetSelected : 0;
      if (ImGui::BeginTabItem(studio::panel_name(panel), nullptr, flags)) {
        ui.shown_panel = panel;
        switch (panel) {
          case Panel::Images: draw_images_panel(controller, ui); break;
          case Panel::Label: draw_label_panel(controller, ui); break;
          case Panel::Thresholds: draw_thresholds_panel(controller, ui); break;
          case Panel::Train: draw_train_panel(controller, ui); break;
          case Panel::Metrics: draw_metrics_panel(controller, ui); break;
          case Panel::Export: draw_export_panel(controller, ui); break;
          case Panel::Count: break;
        }
        ImGui::EndTabItem();
      }
    }
    ui.panel_request_pending = false;
    ImGui::EndTabBar();
  }
  ImGui::EndChild();
  draw_status_bar(controller, ui);
  ImGui::End();
}

void draw_video_import(const studio::VideoImport& import, UiState& ui) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->WorkPos.x + vp->WorkSize.x / 2, vp->WorkPos.y + vp->WorkSize.y / 2}, 0, {0.5f, 0.5f});
  ImGui::SetNextWindowSize({480, 0});
  ImGui::Begin("Reading video", nullptr, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings);
  ImGui::TextWrapped("%s: keeping every %d-th frame", import.video().string().c_str(), import.every());
  ImGui::ProgressBar(import.progress(), {-1, 0});
  ImGui::Text("%d frames written", import.written());
  if (ImGui::Button("Cancel")) ui.quit_requested = true;
  ImGui::End();
}

}  // namespace fieldlines::gui
