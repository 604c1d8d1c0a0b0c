#pragma once
// The central canvas: the current image (a texture the window uploads), the segments drawn over
// it, and the mouse gestures that become controller commands (hover, click to label, drag a
// rectangle, pan, zoom). Its state is gui/model/canvas_state.hpp.
#include <imgui.h>

#include "gui/model/canvas_state.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/studio_controller.hpp"

namespace fieldlines::gui {

// The canvas's picture as the window uploaded it (app/studio/gl_texture.hpp); no id: none.
struct CanvasTexture {
  ImTextureID id = nullptr;
  int width = 0, height = 0;
};

// Gesture map: left click = label hovered with the brush; right click = label hovered "none";
// left drag = label everything the rectangle touches with the brush; right/middle drag = pan;
// wheel = zoom at the cursor.
void draw_image_view(studio::StudioController& controller, studio::CanvasState& state, const CanvasTexture& texture,
                     ImVec2 size);

// One segment with a stroke style (solid, dashed, dotted) in screen coordinates.
void draw_styled_line(ImDrawList* draw, ImVec2 a, ImVec2 b, const studio::SegmentStyle& style);

// Tooltip body for a segment: label, prediction and the per-class features.
void segment_tooltip(const Segment& segment, Label predicted, const SegmentFeatures& features);

}  // namespace fieldlines::gui
