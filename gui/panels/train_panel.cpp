// Train tab: PSO settings, Start/Stop, live best-score plot and particle scatter, results, Apply.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <imgui.h>

#include "gui/model/figures.hpp"
#include "gui/model/leave_one_out.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
constexpr const char* kDims[] = {"marking projection", "marking angle", "marking length",
                                 "boundary projection", "boundary angle", "boundary length"};

float dim_value(const Thresholds& t, int dim) {
  const ClassThresholds& c = dim < 3 ? t.marking.thresholds : t.boundary.thresholds;
  switch (dim % 3) {
    case 0: return c.min_projection;
    case 1: return c.max_angle_deg;
    default: return c.min_length;
  }
}

// The particles in two threshold dimensions, with each axis's name and value range: the swarm
// during PSO, where each polish start ended after it; the best is circled.
void draw_scatter(const studio::TrainingSnapshot& snap, int dx, int dy) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 180};
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  float lo_x = dim_value(snap.best, dx), hi_x = lo_x, lo_y = dim_value(snap.best, dy), hi_y = lo_y;
  for (const Thresholds& t : snap.particles) {
    lo_x = std::min(lo_x, dim_value(t, dx)), hi_x = std::max(hi_x, dim_value(t, dx));
    lo_y = std::min(lo_y, dim_value(t, dy)), hi_y = std::max(hi_y, dim_value(t, dy));
  }
  char lo_x_text[16], hi_x_text[16], lo_y_text[16], hi_y_text[16];
  std::snprintf(lo_x_text, sizeof lo_x_text, "%.4g", lo_x);
  std::snprintf(hi_x_text, sizeof hi_x_text, "%.4g", hi_x);
  std::snprintf(lo_y_text, sizeof lo_y_text, "%.4g", lo_y);
  std::snprintf(hi_y_text, sizeof hi_y_text, "%.4g", hi_y);
  // y values left of the plot, x values and the x name under it.
  const float line = ImGui::GetTextLineHeight();
  const float left = std::max(ImGui::CalcTextSize(lo_y_text).x, ImGui::CalcTextSize(hi_y_text).x) + 6;
  const ImVec2 a{p0.x + left, p0.y}, b{p0.x + size.x, p0.y + size.y - line - 2};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(a, b, IM_COL32(30, 30, 35, 255));
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text), dim = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  draw->AddText({a.x - ImGui::CalcTextSize(hi_y_text).x - 4, a.y}, text, hi_y_text);
  draw->AddText({a.x - ImGui::CalcTextSize(lo_y_text).x - 4, b.y - line}, text, lo_y_text);
  draw->AddText({a.x, b.y + 2}, text, lo_x_text);
  draw->AddText({b.x - ImGui::CalcTextSize(hi_x_text).x, b.y + 2}, text, hi_x_text);
  const float name_x = ImGui::CalcTextSize(kDims[dx]).x;
  draw->AddText({(a.x + b.x - name_x) / 2, b.y + 2}, dim, kDims[dx]);
  draw->AddText({a.x + 4, a.y + 2}, dim, kDims[dy]);
  const char* what = snap.phase == TrainingPhase::Polish ? "polished starts" : "swarm";
  draw->AddText({b.x - ImGui::CalcTextSize(what).x - 4, a.y + 2}, dim, what);

  const float span_x = std::max(hi_x - lo_x, 1e-3f), span_y = std::max(hi_y - lo_y, 1e-3f);
  const auto at = [&](const Thresholds& t) {
    return ImVec2{a.x + 6 + (dim_value(t, dx) - lo_x) / span_x * (b.x - a.x - 12),
                  b.y - 6 - (dim_value(t, dy) - lo_y) / span_y * (b.y - a.y - 12 - line)};
  };
  for (const Thresholds& t : snap.particles) draw->AddCircleFilled(at(t), 2.5f, IM_COL32(120, 200, 255, 200));
  draw->AddCircle(at(snap.best), 6, IM_COL32(255, 80, 80, 255), 0, 2);
}
}  // namespace

void draw_train_panel(studio::StudioController& controller, UiState& ui) {
  TrainParams& p = ui.training.params;
  draw_auto_train(controller);
  ImGui::Separator();
  ImGui::TextUnformatted("PSO training");
  studio::TrainingJob& job = controller.training();
  ImGui::BeginDisabled(job.running());
  int target = static_cast<int>(p.target);
  ImGui::Combo("class", &target, "marking\0boundary\0both\0");
  p.target = static_cast<TrainClass>(target);
  int objective = static_cast<int>(p.objective.kind);
  ImGui::Combo("objective", &objective, "TP - cost x FP\0F1\0F-beta\0");
  p.objective.kind = static_cast<Objective::Kind>(objective);
  if (p.objective.kind == Objective::Kind::TpMinusFp) {
    // 1 is the paper's; the default protocol's 1.5 admits a group of segments only above 60 % precision.
    float cost = static_cast<float>(p.objective.fp_cost);
    if (ImGui::SliderFloat("FP cost", &cost, 0.5f, 4, "%.2f")) p.objective.fp_cost = cost;
  }
  if (p.objective.kind == Objective::Kind::FBeta) {
    float beta = static_cast<float>(p.objective.beta);
    if (ImGui::SliderFloat("beta", &beta, 0.1f, 4)) p.objective.beta = beta;
  }
  ImGui::SliderInt("particles", &p.pso.particles, 5, 300);
  ImGui::SliderInt("iterations", &p.pso.iterations, 5, 500);
  ImGui::Checkbox("polish after PSO", &p.polish);
  ImGui::EndDisabled();

  if (!job.running()) {
    if (ImGui::Button("Start training")) ui.training.toggle(controller);
    // A marker, not the button's tooltip: that one covered the progress line under the button.
    ImGui::SameLine();
    help_marker(("trains on the train split, reports both splits\n" + controller.split_summary()).c_str());
    if (controller.test_segment_count() == 0) wrapped_text({1, 0.7f, 0.3f, 1}, controller.split_summary());
  } else if (ImGui::Button("Stop")) {
    ui.training.toggle(controller);
  }

  if (const auto& snap = job.latest()) {
    // Ends on the polish, so it agrees with the result's score below.
    if (job.running()) {
      ImGui::Text("%s  %.1f s  ETA %.1f s", studio::progress_line(*snap).c_str(), snap->elapsed_s, snap->eta_s);
    } else {
      ImGui::Text("%s  %.1f s", studio::progress_line(*snap).c_str(), snap->elapsed_s);
    }
    ImGui::ProgressBar(snap->iterations ? static_cast<float>(snap->iteration) / static_cast<float>(snap->iterations) : 0,
                       {-1, 0});
    const std::vector<float> scores(job.best_scores().begin(), job.best_scores().end());
    if (!scores.empty()) {
      // Explicit, padded range: a flat curve (converged at once) would otherwise not be drawn.
      const auto [lo, hi] = std::minmax_element(scores.begin(), scores.end());
      const float pad = std::max(1e-3f, (*hi - *lo) * 0.1f);
      char overlay[96];
      std::snprintf(overlay, sizeof overlay, "best score per iteration: %.4g -> %.4g", scores.front(), scores.back());
      // Explicit width: this ImGui's PlotLines takes no negative ("fill") size and draws nothing.
      ImGui::PlotLines("##best", scores.data(), static_cast<int>(scores.size()), 0, overlay, *lo - pad, *hi + pad,
                       {ImGui::GetContentRegionAvail().x, 90});
    }
    ImGui::Combo("x", &ui.training.scatter_x, kDims, IM_ARRAYSIZE(kDims));
    ImGui::Combo("y", &ui.training.scatter_y, kDims, IM_ARRAYSIZE(kDims));
    draw_scatter(*snap, ui.training.scatter_x, ui.training.scatter_y);
  }
  if (const auto& outcome = job.outcome()) {
    ImGui::Separator();
    if (!outcome->ok()) {
      ImGui::TextColored({1, 0.4f, 0.4f, 1}, "training failed: %s", outcome->error().c_str());
    } else {
      const studio::TrainingResult& r = outcome->value();
      ImGui::Text("%s after %d iterations, score %.3f", r.run.cancelled ? "stopped" : "finished", r.run.iterations_run,
                  r.run.score);
      const std::string few =
          controller.test_segment_count() ? studio::not_enough_to_judge(controller.test_image_count()) : "";
      for (const auto& [name, c] : {std::pair{"train", r.train_counts}, std::pair{"test", r.test_counts}}) {
        if (std::string_view(name) == "test" && !few.empty()) {  // one image's figures would mislead
          ImGui::Text("%-5s %s", name, few.c_str());
          continue;
        }
        ImGui::Text("%-5s marking P %s R %s | boundary P %s R %s", name,
                    studio::format_figure(c.marking, c.marking.precision()).c_str(),
                    studio::format_figure(c.marking, c.marking.recall()).c_str(),
                    studio::format_figure(c.boundary, c.boundary.precision()).c_str(),
                    studio::format_figure(c.boundary, c.boundary.recall()).c_str());
      }
      if (ImGui::Button("Apply these thresholds")) ui.training.apply(controller);
      if (const std::string& applied = ui.training.applied_message(controller); !applied.empty()) {
        wrapped_text({0.5f, 0.9f, 0.5f, 1}, applied);
      }
    }
  }
  // Below the plots, so they keep their place. The parameters live in the project (as
  // `fieldlines train --split --train-fraction --seed`); a change re-draws the split at once.
  ImGui::Separator();
  if (ImGui::CollapsingHeader("Test split")) {
    ImGui::BeginDisabled(job.running());
    SplitSpec split = controller.split_spec();
    int by_row = split.mode == SplitMode::ByRow;
    ImGui::Combo("split by", &by_row, "image\0row\0");
    split.mode = by_row ? SplitMode::ByRow : SplitMode::ByImage;
    float fraction = static_cast<float>(split.train_fraction);
    if (ImGui::SliderFloat("train fraction", &fraction, 0.05f, 1, "%.2f")) split.train_fraction = fraction;
    int seed = static_cast<int>(split.seed);
    if (ImGui::InputInt("split seed", &seed) && seed >= 0) split.seed = static_cast<std::uint64_t>(seed);
    controller.set_split_spec(split);
    ImGui::EndDisabled();
    ImGui::TextWrapped("%s", controller.split_summary().c_str());
  }
}

}  // namespace fieldlines::gui
