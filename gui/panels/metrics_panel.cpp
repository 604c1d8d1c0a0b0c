// Metrics tab: live precision/recall/F1 per class on both splits, detection and frame times.
#include <imgui.h>

#include <string>

#include "gui/model/figures.hpp"
#include "gui/model/leave_one_out.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
// `test` empty: too few test images to judge, and no leave-one-out figures: the rows say so.
void counts_table(const char* id, const Counts& train, const Counts* test, const char* test_name) {
  if (!ImGui::BeginTable(id, 5, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) return;
  // The first column fits its longest name; the figures share what is left.
  ImGui::TableSetupColumn("class / split", ImGuiTableColumnFlags_WidthFixed,
                          ImGui::CalcTextSize("boundary train").x + ImGui::GetStyle().CellPadding.x * 2);
  for (const char* h : {"precision", "recall", "F1", "TP/FP/FN"}) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  const auto row = [](const std::string& name, const ClassCounts* c) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name.c_str());
    if (!c) {
      for (int col = 0; col < 4; ++col) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("-");
      }
      return;
    }
    for (const double figure : {c->precision(), c->recall(), c->f1()}) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(studio::format_figure(*c, figure).c_str());
    }
    ImGui::TableNextColumn();
    if (!c->empty()) ImGui::Text("%ld/%ld/%ld", c->tp, c->fp, c->fn);
    else ImGui::TextUnformatted("n/a");
  };
  row("marking train", &train.marking);
  row(std::string("marking ") + test_name, test ? &test->marking : nullptr);
  row("boundary train", &train.boundary);
  row(std::string("boundary ") + test_name, test ? &test->boundary : nullptr);
  ImGui::EndTable();
}
}  // namespace

void draw_metrics_panel(studio::StudioController& controller, UiState& ui) {
  ImGui::TextUnformatted("Current thresholds vs labels");
  ImGui::TextWrapped("%s", controller.split_summary().c_str());
  // One image's F1 says how that picture went, not how the next will (leave_one_out.hpp).
  const std::string few = controller.test_segment_count() ? studio::not_enough_to_judge(controller.test_image_count()) : "";
  const studio::LeaveOneOut& loo = controller.leave_one_out();
  if (few.empty()) {
    counts_table("counts", controller.train_counts(), &controller.test_counts(), "test");
  } else if (loo.images > 0) {
    counts_table("counts", controller.train_counts(), &loo.pooled, "LOO");
    wrapped_hint(few + "; LOO: leave-one-image-out over " + std::to_string(loo.images) +
                 " labelled images (each held out in turn, auto-train's rule trained on the others)");
  } else {
    counts_table("counts", controller.train_counts(), nullptr, "test");
    wrapped_hint(few + " (auto-train on gives leave-one-image-out figures)");
  }
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
