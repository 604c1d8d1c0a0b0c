#pragma once
// How the image view draws, as the user set it on the Label tab or with its keys (session
// state, not saved).
#include <algorithm>
#include <cmath>

#include "gui/model/feature_layers.hpp"
#include "gui/model/overlay_style.hpp"

namespace fieldlines::studio {

struct ViewSettings {
  static constexpr float kMinLineWidth = 0.5f, kMaxLineWidth = 3.0f;
  float line_width = 1.0f;  // scales every segment's width (and so its dots, dashes and halo)
  FeatureLayers features;   // the detector's field features drawn over the segments (all off)

  void set_line_width(float w) { line_width = std::clamp(w, kMinLineWidth, kMaxLineWidth); }
  // A style's width on screen: grown with the zoom (zoomed_thickness), times the user's factor.
  float segment_width(float style_thickness, float view_scale) const {
    return zoomed_thickness(style_thickness, view_scale) * std::clamp(line_width, kMinLineWidth, kMaxLineWidth);
  }
  // The width a line is drawn at: segment_width rounded to whole pixels, at least 1. ImGui draws
  // a whole-width anti-aliased line as one textured quad instead of three strips of triangles,
  // which a software renderer sets up and fills at a fraction of the cost (docs/studio.md).
  float drawn_width(float style_thickness, float view_scale) const {
    return std::max(1.0f, std::round(segment_width(style_thickness, view_scale)));
  }
};

}  // namespace fieldlines::studio
