#include "gui/panels/image_view.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <imgui.h>

#include "gui/model/canvas_backdrop.hpp"
#include "gui/model/feature_overlay.hpp"
#include "gui/model/hit_test.hpp"
#include "gui/model/shortcuts.hpp"

namespace fieldlines::gui {

namespace {
using studio::Vec2;

ImVec2 im(Vec2 v) { return {v.x, v.y}; }
Vec2 vec(ImVec2 v) { return {v.x, v.y}; }
ImU32 colour(studio::Rgba c) { return IM_COL32(c.r, c.g, c.b, c.a); }
constexpr float kClickSlop = 4;  // pixels a press may move and still count as a click

// The field features over the segments (gui/model/feature_overlay.hpp has what and why).
void draw_features(ImDrawList* draw, const studio::FeatureDrawing& d) {
  for (const studio::FeatureLine& l : d.lines) draw_styled_line(draw, im(l.a), im(l.b), l.style);
  for (const studio::FeatureRing& r : d.rings) {
    draw->AddCircle(im(r.centre), r.radius, colour(studio::kOutline), 0, r.style.thickness + studio::kOutlineExtra);
    draw->AddCircle(im(r.centre), r.radius, colour(r.style.colour), 0, r.style.thickness);
  }
  // The type letter half as large again as the UI's text, so L, T and X tell apart at a glance.
  ImFont* font = ImGui::GetFont();
  const float height = 1.5f * ImGui::GetFontSize();
  for (const studio::FeatureLetter& t : d.letters) {
    const char text[2] = {t.letter, 0};
    const ImVec2 at{t.at.x, t.at.y - height};
    // The outline rule for text: the letter in the outline colour one pixel around, then on top.
    for (const ImVec2 o : {ImVec2{-1, -1}, ImVec2{1, -1}, ImVec2{-1, 1}, ImVec2{1, 1}}) {
      draw->AddText(font, height, {at.x + o.x, at.y + o.y}, colour(studio::kOutline), text);
    }
    draw->AddText(font, height, at, colour(t.colour), text);
  }
}
}  // namespace

void draw_styled_line(ImDrawList* draw, ImVec2 a, ImVec2 b, const studio::SegmentStyle& style) {
  const ImU32 col = colour(style.colour);
  // The dark outline first, solid even under a dashed line, so the segment's extent shows.
  studio::Rgba outline = studio::kOutline;
  outline.a = style.colour.a;  // a faint segment's outline is as faint
  draw->AddLine(a, b, colour(outline), style.thickness + studio::kOutlineExtra);
  if (style.stroke == studio::Stroke::Solid) {
    draw->AddLine(a, b, col, style.thickness);
    return;
  }
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float length = std::hypot(dx, dy);
  if (length < 1e-3f) return;
  const auto at = [&](float t) { return ImVec2{a.x + dx * t / length, a.y + dy * t / length}; };
  const bool round = studio::dash_pattern(style.stroke, style.thickness).round;
  static std::vector<studio::DashPiece> pieces;  // UI thread only; reused so a frame allocates nothing
  studio::dash_pieces(style.stroke, style.thickness, length, pieces);
  for (const studio::DashPiece& piece : pieces) {
    if (round) {
      draw->AddCircleFilled(at(0.5f * (piece.from + piece.to)), 0.5f * (piece.to - piece.from), col);
    } else {
      draw->AddLine(at(piece.from), at(piece.to), col, style.thickness);
    }
  }
}

void segment_tooltip(const Segment& s, Label predicted, const SegmentFeatures& f) {
  ImGui::Text("label: %s   predicted: %s", std::string(to_string(s.label)).c_str(),
              std::string(to_string(predicted)).c_str());
  ImGui::Text("(%.1f, %.1f) - (%.1f, %.1f)   saliency %.0f", s.x0, s.y0, s.x1, s.y1, s.saliency);
  ImGui::Text("boundary: projection %.1f  angle %.1f deg", f.boundary.projection, f.boundary.angle_deg);
  for (int k = 0; k < f.marking_count; ++k) {
    ImGui::Text("marking%s: projection %.1f  angle %.1f deg", f.marking_count > 1 ? (k == 0 ? " (y)" : " (x)") : "",
                f.marking[k].projection, f.marking[k].angle_deg);
  }
  ImGui::Text("grad y RGB (%.0f, %.0f, %.0f)  grad x RGB (%.0f, %.0f, %.0f)", s.grad_y[0], s.grad_y[1], s.grad_y[2],
              s.grad_x[0], s.grad_x[1], s.grad_x[2]);
}

void draw_image_view(studio::StudioController& controller, studio::CanvasState& state, const CanvasTexture& texture,
                     ImVec2 size) {
  const cv::Mat& image = controller.image();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  size.x = std::max(size.x, 50.0f);
  size.y = std::max(size.y, 50.0f);
  ImGui::InvisibleButton("##canvas", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  const bool hovered = ImGui::IsItemHovered();
  const studio::Rect viewport{vec(origin), {origin.x + size.x, origin.y + size.y}};
  const Vec2 image_size{static_cast<float>(image.cols), static_cast<float>(image.rows)};
  if (state.fit_requested && image.cols > 0) {
    state.view.fit(image_size, viewport);
    state.fit_requested = false;
  }
  if (const auto focus = controller.take_focus_request(); focus && *focus < controller.segments().size()) {
    // Centre the view on the segment's midpoint, keeping the zoom.
    const Segment& s = controller.segments()[*focus];
    const Vec2 mid{0.5f * (s.x0 + s.x1) + 0.5f, 0.5f * (s.y0 + s.y1) + 0.5f};
    const Vec2 centre{0.5f * (viewport.min.x + viewport.max.x), 0.5f * (viewport.min.y + viewport.max.y)};
    state.view.set(state.view.scale(), centre - mid * state.view.scale());
    state.focus.hold(controller.current(), *focus);
  }

  ImGuiIO& io = ImGui::GetIO();
  const Vec2 mouse = vec(io.MousePos);
  // Zoom at the cursor; pan with a right or middle drag.
  if (hovered && io.MouseWheel != 0) state.view.zoom_at(mouse, std::pow(1.2f, io.MouseWheel));
  if (ImGui::IsItemActive() && (ImGui::IsMouseDragging(ImGuiMouseButton_Right, kClickSlop) ||
                                ImGui::IsMouseDragging(ImGuiMouseButton_Middle, kClickSlop))) {
    state.view.pan(vec(io.MouseDelta));
  }

  const auto segments = controller.segments();
  const auto predictions = controller.predictions();
  // Hover: the segments under the cursor in screen pixels, nearest first; Space cycles through
  // them (none while dragging a rectangle or panning).
  state.under.clear();
  if (hovered && !state.rect_active) studio::segments_under(segments, state.view, mouse, state.pick_radius_px, state.under);
  const std::optional<std::size_t> under = state.cycle.update(controller.current(), state.under, segments);
  const bool pointer_acted = hovered && (io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || ImGui::IsAnyMouseDown());
  const std::optional<std::size_t> chosen = state.focus.update(controller.current(), segments.size(), under, pointer_acted);
  if (chosen || (hovered && !state.rect_active)) {
    controller.set_hovered(chosen);
  } else if (!ImGui::IsItemActive()) {
    controller.set_hovered(std::nullopt);  // a drag keeps its segment when the pointer slips off
  }

  // Left button: a click labels the hovered segment, a drag draws a selection rectangle.
  if (ImGui::IsItemActivated() && ImGui::IsMouseClicked(ImGuiMouseButton_Left)) {
    state.rect_start = mouse;
    state.rect_active = false;
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left, kClickSlop)) state.rect_active = true;
  if (ImGui::IsItemDeactivated() && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) {
    if (state.rect_active) {
      const auto hit = studio::segments_in_rect(segments, state.view, {state.rect_start, mouse});
      controller.label(hit, state.brush);
    } else {
      controller.label_hovered(state.brush);
    }
    state.rect_active = false;
  }
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Right) &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0).x == 0 &&
      ImGui::GetMouseDragDelta(ImGuiMouseButton_Right, 0).y == 0) {
    controller.label_hovered(Label::None);
  }

  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->PushClipRect(origin, {origin.x + size.x, origin.y + size.y}, true);
  const bool has_picture = texture.id && texture.width > 0;
  const studio::Rect picture{state.view.image_to_screen({0, 0}), state.view.image_to_screen(image_size)};
  // Named: bands() views the object's own array, which a temporary would take with it.
  const studio::Backdrop backdrop(viewport, has_picture ? picture : studio::Rect{});
  for (const studio::Rect& band : backdrop.bands()) draw->AddRectFilled(im(band.min), im(band.max), IM_COL32(25, 25, 28, 255));
  if (has_picture) {
    draw->AddImage(texture.id, im(picture.min), im(picture.max));
  } else {
    const std::string msg = controller.image_error().empty() ? "no image" : controller.image_error();
    draw->AddText({origin.x + 10, origin.y + 10}, IM_COL32(255, 120, 120, 255), msg.c_str());
  }
  if (state.show_segments) {
    for (std::size_t i = 0; i < segments.size(); ++i) {
      const auto s = studio::to_screen(segments[i], state.view);
      auto style = studio::on_field_style(studio::style_for(state.mode, segments[i].label, predictions[i], controller.proposal(i)),
                                          segments[i], controller.field_features().field_boundary, state.faint_above_field);
      style.thickness = state.settings.drawn_width(style.thickness, state.view.scale());
      draw_styled_line(draw, im(s.a), im(s.b), style);
    }
  }
  if (state.settings.features.any()) {
    static studio::FeatureDrawing features;  // UI thread only; reused so a frame allocates nothing
    studio::build_feature_drawing(controller.field_features(), state.settings.features, state.view, state.settings,
                                  features);
    draw_features(draw, features);
  }
  if (const auto h = controller.hovered()) {
    // Highlight, unmistakable over any background and among overlapping segments: a black then a
    // white halo under a wider solid redraw, and both endpoints ringed.
    const auto s = studio::to_screen(segments[*h], state.view);
    const auto style = studio::style_for(state.mode, segments[*h].label, predictions[*h], controller.proposal(*h));
    const float width = state.settings.drawn_width(style.thickness, state.view.scale()) + 2;
    draw->AddLine(im(s.a), im(s.b), colour(studio::kOutline), width + 8);
    draw->AddLine(im(s.a), im(s.b), IM_COL32(255, 255, 255, 255), width + 4);
    draw->AddLine(im(s.a), im(s.b), colour(style.colour), width);  // solid: the class colour shows whole
    const float ring = 0.5f * width + 4;
    for (const Vec2 end : {s.a, s.b}) {
      draw->AddCircle(im(end), ring, colour(studio::kOutline), 0, 4);
      draw->AddCircle(im(end), ring, IM_COL32(255, 255, 255, 255), 0, 2);
    }
  }
  if (state.rect_active) {
    draw->AddRectFilled(im(state.rect_start), im(mouse), IM_COL32(255, 255, 255, 40));
    draw->AddRect(im(state.rect_start), im(mouse), IM_COL32(255, 255, 255, 200));
  }
  draw->PopClipRect();

  if (const auto h = controller.hovered(); h && hovered && !state.rect_active) {
    ImGui::BeginTooltip();
    if (const auto n = state.cycle.candidates().size(); n > 1 && state.cycle.hovered() == h) {
      ImGui::TextColored({1, 0.85f, 0.3f, 1}, "%zu of %zu under cursor (%s: next)", state.cycle.position() + 1, n,
                         studio::key_for(studio::Action::NextUnderCursor).c_str());
    }
    segment_tooltip(segments[*h], predictions[*h], controller.features(*h));
    ImGui::EndTooltip();
  }
}

}  // namespace fieldlines::gui
