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

// Saturated colours that are neither green nor white, so they stand out on a field picture:
// each is at least 100 CIE76 Delta-E from every turf green of tests/studio/overlay_style_test
// and from white, except yellow ("none", >= 55: an agreed non-feature need not shout).
Rgba label_colour(Label label);

// Drawn under every segment, a little wider: the colour then reads against bright turf, white
// paint and dark walls alike.
inline constexpr Rgba kOutline{10, 10, 10, 255};
inline constexpr float kOutlineExtra = 3;  // outline width = line width + this, screen pixels

// A style's width at a view scale (screen pixels per image pixel): grows with the zoom (as the
// square root, so a 16x zoom draws 4x wider), never thinner than at 1:1.
float zoomed_thickness(float thickness, float scale);

// What a segment looks like given its human label, the thresholds' prediction and the review
// loop's proposal: an unlabelled segment with a proposal is drawn dashed in the proposed class's
// colour in the label and agreement modes, so a proposal never looks like a label.
SegmentStyle style_for(OverlayMode mode, Label truth, Label predicted, Label proposal = Label::Unlabelled);

struct LegendEntry {
  std::string_view text;
  SegmentStyle style;
};
// The legend rows for a mode, in display order.
std::span<const LegendEntry> legend(OverlayMode mode);

}  // namespace fieldlines::studio
