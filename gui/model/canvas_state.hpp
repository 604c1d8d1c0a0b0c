#pragma once
// The image canvas's state, window-free: the view transform, the overlay and brush, which segment
// is hovered (under the cursor, Space, Tab), the rectangle being dragged, and which picture the
// window's texture must hold. gui/panels/image_view.* draws it and turns gestures into commands.
#include <cstddef>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "fieldlines/detect/segment.hpp"
#include "gui/model/geometry.hpp"
#include "gui/model/hover_cycle.hpp"
#include "gui/model/hover_focus.hpp"
#include "gui/model/missed_paint_view.hpp"
#include "gui/model/overlay_style.hpp"
#include "gui/model/view_settings.hpp"
#include "gui/model/view_transform.hpp"

namespace fieldlines::studio {

class StudioController;

struct CanvasState {
  ViewTransform view;
  OverlayMode mode = OverlayMode::Labels;
  Label brush = Label::Marking;  // what a left click or rectangle assigns
  float pick_radius_px = 8;      // hover reach, in screen pixels at every zoom
  bool fit_requested = true;
  bool show_segments = true;
  bool faint_above_field = true;  // segments above the field boundary faint (overlay_style.hpp)
  bool show_missed = false;   // tint paint that has no segment (Label tab)
  MissedPaintView missed;     // its cached computation
  ViewSettings settings;      // line width (Label tab)
  HoverCycle cycle;           // which of the segments under the cursor is hovered (Space: next)
  // The segment Tab brought into view (StudioController::focus_most_uncertain), hovered until
  // the pointer moves onto another segment.
  HoverFocus focus;
  std::vector<std::size_t> under;  // the segments under the cursor this frame (a reused buffer)
  bool rect_active = false;
  Vec2 rect_start{};

  // The picture the window's texture must hold: the current image, or with "paint with no
  // segment" on its tinted copy. Returns it when it differs from what was last handed out (and
  // counts it as handed out), null when the texture is up to date. Once per frame, before drawing.
  const cv::Mat* picture_to_upload(const StudioController& controller);
  // A new session: the next picture_to_upload hands the picture out again.
  void reupload() { uploaded_generation_ = static_cast<std::size_t>(-1); }

 private:
  std::size_t uploaded_generation_ = static_cast<std::size_t>(-1);
  bool uploaded_tinted_ = false;
};

}  // namespace fieldlines::studio
