// Train tab, top: live retraining (auto-train) and its learning curve, test-split F1 of each
// class against the number of labels, so the user sees the classifier converge as they label.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "gui/model/leave_one_out.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/shortcuts.hpp"
#include "gui/panels/panels.hpp"

namespace fieldlines::gui {

namespace {
ImU32 colour(studio::Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }

// Points without figures (too few test images, no leave-one-out) break the line.
void draw_curve(const std::vector<studio::CurvePoint>& curve) {
  const ImVec2 size{ImGui::GetContentRegionAvail().x, 120};
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const float left = 34, bottom = 16;  // room for the axis values
  const ImVec2 a{p0.x + left, p0.y + 4}, b{p0.x + size.x - 6, p0.y + size.y - bottom};
  draw->AddRectFilled(a, b, IM_COL32(30, 30, 35, 255));
  const std::size_t max_labels = std::max<std::size_t>(curve.back().labelled, 1);
  const auto at = [&](std::size_t labelled, double f1) {
    return ImVec2{a.x + (b.x - a.x) * static_cast<float>(labelled) / static_cast<float>(max_labels),
                  b.y - (b.y - a.y) * static_cast<float>(f1)};
  };
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  draw->AddText({p0.x, a.y - 2}, text, "1.0");
  draw->AddText({p0.x, b.y - 12}, text, "0.0");
  draw->AddText({a.x, b.y + 1}, text, "0");
  char right[32];
  std::snprintf(right, sizeof right, "%zu labels", max_labels);
  draw->AddText({b.x - ImGui::CalcTextSize(right).x, b.y + 1}, text, right);
  // One polyline per class; a point where the class has no test data (n/a) breaks the line.
  // Boundary first and wider, marking on top and narrower: where both classes score alike (the
  // same pooled F1) both stay visible, blue around magenta.
  const auto series = [&](auto counts_of, Label label, float width) {
    const ImU32 col = colour(studio::label_colour(label));
    std::optional<ImVec2> prev;
    for (const studio::CurvePoint& p : curve) {
      const ClassCounts& c = counts_of(p);
      if (p.test_segments == 0 || !p.judged || c.empty()) {
        prev.reset();
        continue;
      }
      const ImVec2 q = at(p.labelled, c.f1());
      if (prev) draw->AddLine(*prev, q, col, width);
      draw->AddCircleFilled(q, width + 0.5f, col);
      prev = q;
    }
  };
  series([](const studio::CurvePoint& p) -> const ClassCounts& { return p.test.boundary; }, Label::Boundary, 4);
  series([](const studio::CurvePoint& p) -> const ClassCounts& { return p.test.marking; }, Label::Marking, 2);
}
}  // namespace

void draw_auto_train(studio::StudioController& controller) {
  bool on = controller.auto_train();
  if (ImGui::Checkbox("auto-train", &on)) controller.set_auto_train(on);
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("retrain both classes on the train split after every label change\n"
                      "(label-free until a class has 10 labels, or 3 where calibration refuses it);\n"
                      "the thresholds follow your labels");
  }
  ImGui::SameLine();
  if (ImGui::Button("Propose labels")) controller.propose();
  ImGui::SameLine();
  ImGui::TextDisabled("(%s)", studio::key_for(studio::Action::Propose).c_str());
  if (controller.auto_train() && controller.auto_train_busy()) {
    ImGui::TextUnformatted("retraining...");
  } else if (!controller.auto_train_summary().empty()) {
    ImGui::TextWrapped("%s", controller.auto_train_summary().c_str());
  }
  if (!controller.proposal_summary().empty()) ImGui::TextWrapped("%s", controller.proposal_summary().c_str());
  // Why proposals are few and what to do (also in the status bar), until the labels answer it.
  if (!controller.guidance().empty()) wrapped_text({1, 0.7f, 0.3f, 1}, controller.guidance());
  const auto& curve = controller.learning_curve();
  if (curve.empty()) {
    wrapped_hint("learning curve (test F1 over labels): appears once you label with auto-train on");
    return;
  }
  const studio::CurvePoint& last = curve.back();
  const auto f1 = [&](const ClassCounts& c) {
    char s[16] = "n/a";
    if (last.test_segments > 0 && !c.empty()) std::snprintf(s, sizeof s, "%.3f", c.f1());
    return std::string(s);
  };
  if (!last.judged) {
    wrapped_hint("test F1 after " + std::to_string(last.labelled) + " labels: " +
                 studio::not_enough_to_judge(controller.test_image_count()));
  } else {
    ImGui::TextWrapped("%s F1 after %zu labels: marking %s, boundary %s",
                       last.leave_one_out ? "leave-one-image-out" : "test", last.labelled, f1(last.test.marking).c_str(),
                       f1(last.test.boundary).c_str());
  }
  draw_curve(curve);
}

}  // namespace fieldlines::gui
