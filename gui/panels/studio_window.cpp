#include "gui/panels/studio_window.hpp"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "gui/model/ellipsize.hpp"
#include "gui/model/shortcuts.hpp"
#include "gui/model/status_line.hpp"
#include "gui/panels/image_view.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

void draw_shortcut_help() {
  // The keys fit their column; the descriptions take the rest of the panel's width and wrap.
  if (!ImGui::BeginTable("shortcuts", 2)) return;
  ImGui::TableSetupColumn("input", ImGuiTableColumnFlags_WidthFixed);
  ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
  for (const studio::Shortcut& s : studio::shortcuts()) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(studio::input_name(s).c_str());
    ImGui::TableNextColumn();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("%.*s", static_cast<int>(s.description.size()), s.description.data());
    ImGui::PopStyleColor();
  }
  ImGui::EndTable();
}

namespace {

ImVec4 severity_colour(studio::Severity s) {
  switch (s) {
    case studio::Severity::Error: return {1, 0.4f, 0.4f, 1};
    case studio::Severity::Warning: return {1, 0.7f, 0.3f, 1};
    default: return ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled);
  }
}

// `text` cut with "..." to `width`; the full text (wrapped, inside the window) on hover.
void fitted_text(const std::string& text, float width, const ImVec4& colour, const std::vector<studio::StatusNote>& all) {
  const std::string shown =
      studio::ellipsize(text, width, [](std::string_view t) { return ImGui::CalcTextSize(t.data(), t.data() + t.size()).x; });
  ImGui::TextColored(colour, "%s", shown.c_str());
  if (shown == text || !ImGui::IsItemHovered()) return;
  ImGui::SetNextWindowSizeConstraints({0, 0}, {ImGui::GetMainViewport()->WorkSize.x * 0.6f, FLT_MAX});
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetMainViewport()->WorkSize.x * 0.6f - ImGui::GetStyle().WindowPadding.x * 2);
  if (all.empty()) ImGui::TextUnformatted(text.c_str());
  for (const studio::StatusNote& n : all) {
    ImGui::PushStyleColor(ImGuiCol_Text, n.severity == studio::Severity::Info ? ImGui::GetStyleColorVec4(ImGuiCol_Text)
                                                                              : severity_colour(n.severity));
    ImGui::TextUnformatted(n.text.c_str());
    ImGui::PopStyleColor();
  }
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

// One line: the counters, the detection progress while it runs, then the notes, each cut to
// the room left so nothing runs past the window's right edge.
void draw_status_bar(const studio::StudioController& controller, const UiState& ui) {
  const float gap = ImGui::GetStyle().ItemSpacing.x;
  const auto room = [] { return ImGui::GetContentRegionAvail().x; };
  const std::string counters = studio::status_counters(controller, ui.image_view.view.scale(),
                                                       ui.frame_stats ? ui.frame_stats->median_ms() : 0.0);
  const std::vector<studio::StatusNote> notes = studio::status_notes(controller, ui.status_message);
  std::string joined;
  for (const studio::StatusNote& n : notes) joined += (joined.empty() ? "" : "  |  ") + n.text;
  // The counters keep at least half the line; the notes get the rest, the counters what they leave.
  const float notes_width = notes.empty() ? 0 : ImGui::CalcTextSize(joined.c_str()).x + gap * 3;
  const float counters_width =
      std::min(ImGui::CalcTextSize(counters.c_str()).x, std::max(room() * 0.5f, room() - notes_width));
  fitted_text(counters, counters_width, ImGui::GetStyleColorVec4(ImGuiCol_Text), {});
  if (const studio::DetectionJob& job = controller.detection(); job.running()) {
    // Visible from every tab: detection of a whole folder takes a while on a laptop.
    // A folder's first detection measures every frame first, to choose the detector.
    ImGui::SameLine();
    ImGui::ProgressBar(job.bar_progress(), {std::min(200.f, std::max(room(), 1.f)), 0}, job.bar_text().c_str());
  }
  if (notes.empty()) return;
  ImGui::SameLine(0, gap * 3);
  fitted_text(joined, room(), severity_colour(notes.front().severity), notes);
}

// Side panel tabs have 2 px of padding either side of their labels instead of the style's 4:
// seven tabs then fit the 400 px panel even beside its scroll bar (ImGui would squeeze them
// otherwise, cutting their names).
constexpr float kTabPadding = 2;
bool begin_tab(const char* label, ImGuiTabItemFlags flags = 0) {
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, {kTabPadding, ImGui::GetStyle().FramePadding.y});
  const bool open = ImGui::BeginTabItem(label, nullptr, flags);
  ImGui::PopStyleVar();
  return open;
}

}  // namespace

ImVec4 studio_backdrop(ImVec4 behind) {
  const ImVec4 bg = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
  const auto over = [&](float top, float under) { return top * bg.w + under * (1 - bg.w); };
  return {over(bg.x, behind.x), over(bg.y, behind.y), over(bg.z, behind.z), 1};
}

void draw_studio(studio::StudioController& controller, UiState& ui, const CanvasTexture& texture) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(viewport->WorkPos);
  ImGui::SetNextWindowSize(viewport->WorkSize);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {6, 6});
  ImGui::Begin("fieldlines studio", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoBringToFrontOnFocus |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBackground);  // studio_backdrop
  ImGui::PopStyleVar(2);

  const float side_width = 400;
  const float status_height = ImGui::GetFrameHeightWithSpacing();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  // The canvas leaves the side panel its width and the spacing SameLine puts between them.
  const ImVec2 canvas_min = ImGui::GetCursorScreenPos();
  const ImVec2 canvas_size{avail.x - side_width - ImGui::GetStyle().ItemSpacing.x, avail.y - status_height};
  draw_image_view(controller, ui.image_view, texture, canvas_size);
  ImGui::SameLine();
  ImGui::BeginChild("side", {side_width, avail.y - status_height});
  // The bar draws its labels with the padding it was begun with, its tabs take theirs at
  // begin_tab: both the narrow one.
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, {kTabPadding, ImGui::GetStyle().FramePadding.y});
  const bool tabs = ImGui::BeginTabBar("panels");
  ImGui::PopStyleVar();
  if (tabs) {
    for (int p = 0; p < static_cast<int>(Panel::Count); ++p) {
      const Panel panel = static_cast<Panel>(p);
      const ImGuiTabItemFlags flags =
          ui.panel_request_pending && ui.requested_panel == panel ? ImGuiTabItemFlags_SetSelected : 0;
      if (begin_tab(studio::panel_name(panel), flags)) {
        ui.shown_panel = panel;
        switch (panel) {
          case Panel::Images: draw_images_panel(controller, ui); break;
          case Panel::Label: draw_label_panel(controller, ui); break;
          case Panel::Thresholds: draw_thresholds_panel(controller, ui); break;
          case Panel::Train: draw_train_panel(controller, ui); break;
          case Panel::Metrics: draw_metrics_panel(controller, ui); break;
          case Panel::Export: draw_export_panel(controller, ui); break;
          case Panel::Camera: draw_camera_panel(controller, ui); break;
          case Panel::Count: break;
        }
        ImGui::EndTabItem();
      }
    }
    ui.panel_request_pending = false;
    ImGui::EndTabBar();
  }
  ImGui::EndChild();
  // Over the canvas, once the tab has said whether it is open this frame.
  draw_camera_overlay(controller, ui, canvas_min,
                      {canvas_min.x + canvas_size.x, canvas_min.y + canvas_size.y});
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
