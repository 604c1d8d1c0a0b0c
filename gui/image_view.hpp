#pragma once
// The central canvas: the current image as a texture, the segments drawn over it, and the mouse
// gestures that become controller commands (hover, click to label, drag a rectangle, pan, zoom).
#include <cstddef>
#include <optional>
#include <vector>

#include "gui/gl_texture.hpp"
#include "gui/model/hover_cycle.hpp"
#include "gui/model/hover_focus.hpp"
#include "gui/model/missed_paint_view.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/studio_controller.hpp"
#include "gui/model/view_settings.hpp"
#include "gui/model/view_transform.hpp"

namespace fieldlines::gui {

struct ImageViewState {
  studio::ViewTransform view;
  studio::OverlayMode mode = studio::OverlayMode::Labels;
  Label brush = Label::Marking;  // what a left click or rectangle assigns
  float pick_radius_px = 8;      // hover reach, in screen pixels at every zoom
  bool fit_requested = true;
  bool show_segments = true;
  bool show_missed = false;         // tint paint that has no segment (Label tab)
  studio::MissedPaintView missed;   // its cached computation
  studio::ViewSettings settings;  // line width (Label tab)
  studio::HoverCycle cycle;       // which of the segments under the cursor is hovered (Space: next)
  std::vector<std::size_t> under;  // the segments under the cursor this frame (a reused buffer)
  GlTexture texture;
  std::size_t texture_generation = static_cast<std::size_t>(-1);
  bool texture_tinted = false;  // the texture holds missed.tinted(), not the plain image
  bool rect_active = false;
  studio::Vec2 rect_start{};
  // The segment Tab brought into view (StudioController::focus_most_uncertain), hovered until
  // the pointer moves onto another segment.
  studio::HoverFocus focus;
};

// Gesture map: left click = label hovered with the brush; right click = label hovered "none";
// left drag = label everything the rectangle touches with the brush; right/middle drag = pan;
// wheel = zoom at the cursor.
void draw_image_view(studio::StudioController& controller, ImageViewState& state, ImVec2 size);

// One segment with a stroke style (solid, dashed, dotted) in screen coordinates.
void draw_styled_line(ImDrawList* draw, ImVec2 a, ImVec2 b, const studio::SegmentStyle& style);

// Tooltip body for a segment: label, prediction and the per-class features.
void segment_tooltip(const Segment& segment, Label predicted, const SegmentFeatures& features);

}  // namespace fieldlines::gui
