// Train tab: PSO settings, Start/Stop, live best-score plot and particle scatter, results, Apply.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include <imgui.h>

#include "gui/model/figures.hpp"
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

void draw_scatter(const studio::TrainingSnapshot& snap, int dx, int dy) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 160};
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(p0, {p0.x + size.x, p0.y + size.y}, IM_COL32(30, 30, 35, 255));
  float lo_x = 1e9f, hi_x = -1e9f, lo_y = 1e9f, hi_y = -1e9f;
  for (const Thresholds& t : snap.particles) {
    lo_x = std::min(lo_x, dim_value(t, dx)), hi_x = std::max(hi_x, dim_value(t, dx));
    lo_y = std::min(lo_y, dim_value(t, dy)), hi_y = std::max(hi_y, dim_value(t, dy));
  }
  const float span_x = std::max(hi_x - lo_x, 1e-3f), span_y = std::max(hi_y - lo_y, 1e-3f);
  const auto at = [&](const Thresholds& t) {
    return ImVec2{p0.x + 6 + (dim_value(t, dx) - lo_x) / span_x * (size.x - 12),
                  p0.y + size.y - 6 - (dim_value(t, dy) - lo_y) / span_y * (size.y - 12)};
  };
  for (const Thresholds& t : snap.particles) draw->AddCircleFilled(at(t), 2.5f, IM_COL32(120, 200, 255, 200));
  draw->AddCircle(at(snap.best), 6, IM_COL32(255, 80, 80, 255), 0, 2);
}
}  // namespace

void draw_train_panel(studio::StudioController& controller, UiState& ui) {
  TrainParams& p = ui.train_params;
  draw_auto_train(controller);
  ImGui::Separator();
  ImGui::TextUnformatted("PSO training");
  studio::TrainingJob& job = controller.training();
  ImGui::BeginDisabled(job.running());
  int target = static_cast<int>(p.target);
  ImGui::Combo("class", &target, "marking\0boundary\0both\0");
  p.target = static_cast<TrainClass>(target);
  int objective = static_cast<int>(p.objective.kind);
  ImGui::Combo("objective", &objective, "TP - FP (paper)\0F1\0F-beta\0");
  p.objective.kind = static_cast<Objective::Kind>(objective);
  if (p.objective.kind == Objective::Kind::FBeta) {
    float beta = static_cast<float>(p.objective.beta);
    if (ImGui::SliderFloat("beta", &beta, 0.1f, 4)) p.objective.beta = beta;
  }
  ImGui::SliderInt("particles", &p.pso.particles, 5, 300);
  ImGui::SliderInt("iterations", &p.pso.iterations, 5, 500);
  ImGui::Checkbox("polish after PSO", &p.polish);
  ImGui::EndDisabled();

  if (!job.running()) {
    if (ImGui::Button("Start training")) controller.start_training(p);
    if (ImGui::IsItemHovered()) {
      ImGui::SetTooltip("trains on the train split, reports both splits\n%s", controller.split_summary().c_str());
    }
    if (controller.test_segment_count() == 0) ImGui::TextColored({1, 0.7f, 0.3f, 1}, "%s", controller.split_summary().c_str());
  } else if (ImGui::Button("Stop")) {
    controller.cancel_training();
  }

  if (const auto& snap = job.latest()) {
    ImGui::Text("iteration %d/%d  best %.3f  %.1f s  ETA %.1f s", snap->iteration, snap->iterations,
                snap->best_score, snap->elapsed_s, job.running() ? snap->eta_s : 0.0);
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
    ImGui::Combo("x", &ui.scatter_x, kDims, IM_ARRAYSIZE(kDims));
    ImGui::Combo("y", &ui.scatter_y, kDims, IM_ARRAYSIZE(kDims));
    draw_scatter(*snap, ui.scatter_x, ui.scatter_y);
  }
  if (const auto& outcome = job.outcome()) {
    ImGui::Separator();
    if (!outcome->ok()) {
      ImGui::TextColored({1, 0.4f, 0.4f, 1}, "training failed: %s", outcome->error().c_str());
    } else {
      const studio::TrainingResult& r = outcome->value();
      ImGui::Text("%s after %d iterations, score %.3f", r.run.cancelled ? "stopped" : "finished", r.run.iterations_run,
                  r.run.score);
      for (const auto& [name, c] : {std::pair{"train", r.train_counts}, std::pair{"test", r.test_counts}}) {
        ImGui::Text("%-5s marking P %s R %s | boundary P %s R %s", name,
                    studio::format_figure(c.marking, c.marking.precision()).c_str(),
                    studio::format_figure(c.marking, c.marking.recall()).c_str(),
                    studio::format_figure(c.boundary, c.boundary.precision()).c_str(),
                    studio::format_figure(c.boundary, c.boundary.recall()).c_str());
      }
      if (ImGui::Button("Apply these thresholds")) controller.apply_training_result();
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
