// Metrics tab: live precision/recall/F1 per class on both splits, detection and frame times.
#include <imgui.h>

#include "gui/model/figures.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
void counts_table(const char* id, const Counts& train, const Counts& test) {
  if (!ImGui::BeginTable(id, 5, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) return;
  // The first column fits its longest name; the figures share what is left.
  ImGui::TableSetupColumn("class / split", ImGuiTableColumnFlags_WidthFixed,
                          ImGui::CalcTextSize("boundary train").x + ImGui::GetStyle().CellPadding.x * 2);
  for (const char* h : {"precision", "recall", "F1", "TP/FP/FN"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  const auto row = [](const char* name, const ClassCounts& c) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    for (const double figure : {c.precision(), c.recall(), c.f1()}) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(studio::format_figure(c, figure).c_str());
    }
    ImGui::TableNextColumn();
    if (!c.empty()) ImGui::Text("%ld/%ld/%ld", c.tp, c.fp, c.fn);
    else ImGui::TextUnformatted("n/a");
  };
  row("marking train", train.marking);
  row("marking test", test.marking);
  row("boundary train", train.boundary);
  row("boundary test", test.boundary);
  ImGui::EndTable();
}
}  // namespace

void draw_metrics_panel(studio::StudioController& controller, UiState& ui) {
  ImGui::TextUnformatted("Current thresholds vs labels");
  ImGui::TextWrapped("%s", controller.split_summary().c_str());
  counts_table("counts", controller.train_counts(), controller.test_counts());
  ImGui::Separator();
  ImGui::Text("detection: this image %.2f ms, project mean %.2f ms", controller.current_detect_ms(),
              controller.mean_detect_ms());
  if (ui.frame_stats) {
    const auto history = ui.frame_stats->history_ms();
    ImGui::Text("UI frame: median %.2f ms, last %.2f ms", ui.frame_stats->median_ms(), ui.frame_stats->last_ms());
    if (!history.empty()) {
      ImGui::PlotLines("##frames", history.data(), static_cast<int>(history.size()), 0, "frame ms", 0, 33,
                       {ImGui::GetContentRegionAvail().x, 80});
    }
  }
}

}  // namespace fieldlines::gui
