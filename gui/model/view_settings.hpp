#pragma once
// How the image view draws, as the user set it on the Label tab or with its keys (session
// state, not saved).
#include <algorithm>

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
};

}  // namespace fieldlines::studio
