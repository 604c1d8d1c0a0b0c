#pragma once
// How a segment is drawn over the image in each colouring mode (a legend lists the same styles).
#include <cstdint>
#include <span>
#include <string_view>

#include "fieldlines/detect/segment.hpp"

namespace fieldlines::studio {

enum class OverlayMode {
  Labels,      // the human label
  Prediction,  // what the current thresholds predict
  Agreement,   // prediction vs label: true positive solid, false positive dashed, false negative dotted
};
std::string_view to_string(OverlayMode mode);

enum class Stroke { Solid, Dashed, Dotted };

struct Rgba {
  std::uint8_t r = 0, g = 0, b = 0, a = 255;
  bool operator==(const Rgba&) const = default;
};

struct SegmentStyle {
  Rgba colour;
  Stroke stroke = Stroke::Solid;
  float thickness = 2;  // screen pixels
};

// Saturated colours that are neither green nor white, so they stand out on a field picture.
Rgba label_colour(Label label);

// What a segment looks like given its human label and the thresholds' prediction.
SegmentStyle style_for(OverlayMode mode, Label truth, Label predicted);

struct LegendEntry {
  std::string_view text;
  SegmentStyle style;
};
// The legend rows for a mode, in display order.
std::span<const LegendEntry> legend(OverlayMode mode);

}  // namespace fieldlines::studio
