#pragma once
// How a segment is drawn over the image in each colouring mode (a legend lists the same styles).
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "fieldlines/data/palette.hpp"
#include "fieldlines/detect/field_boundary.hpp"
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

// The class colours of fieldlines/data/palette.hpp (shared with the CLI's --draw; its header
// states the measured legibility on turf, white paint and dark walls), opaque.
Rgba label_colour(Label label);

// `style` as a segment above the field boundary is drawn (stands, walls, lights): its colour at
// palette::kAboveFieldOpacity; unchanged on the field, when `faint` is off or without a boundary.
SegmentStyle on_field_style(SegmentStyle style, const Segment& segment, const FieldBoundary& boundary, bool faint);

// Drawn under every segment, a little wider: the colour then reads against bright turf and
// white paint; on dark walls the colour itself carries it (palette.hpp).
inline constexpr Rgba kOutline{palette::kOutline.r, palette::kOutline.g, palette::kOutline.b, 255};
inline constexpr float kOutlineExtra = palette::kOutlineExtra;  // outline width = line width + this, screen px

// A style's width at a view scale (screen pixels per image pixel): grows with the zoom (as the
// square root, so a 16x zoom draws 4x wider), never thinner than at 1:1.
float zoomed_thickness(float thickness, float scale);

// What a segment looks like given its human label, the thresholds' prediction and the review
// loop's proposal: an unlabelled segment with a proposal is drawn dashed in the proposed class's
// colour in the label and agreement modes, so a proposal never looks like a label.
SegmentStyle style_for(OverlayMode mode, Label truth, Label predicted, Label proposal = Label::Unlabelled);

// How a stroke is broken up along a line `thickness` screen pixels wide: `on` pixels drawn every
// `period` (solid: on == period). Dotted strokes are round dots `on` across; dashes are 4x as
// long as a dot, and every gap is at least 1.5x the thickness, so a false positive (dashed)
// and a false negative (dotted) tell apart at fit zoom and a dot is never thinner than the line.
struct DashPattern {
  float on = 0, period = 0;
  bool round = false;  // draw each "on" piece as a filled circle of diameter `on`
};
DashPattern dash_pattern(Stroke stroke, float thickness);

// The pieces [from, to] (distances along the line, 0..length) a stroke draws on a line of that
// length, into `out` (cleared; its capacity is reused, as the view draws hundreds per frame).
// Dots are whole (never cut at the end); a line too short for one dot gets one centred.
struct DashPiece {
  float from = 0, to = 0;
};
void dash_pieces(Stroke stroke, float thickness, float length, std::vector<DashPiece>& out);
std::vector<DashPiece> dash_pieces(Stroke stroke, float thickness, float length);

struct LegendEntry {
  std::string_view text;
  SegmentStyle style;
  std::string_view detail = {};  // a class's colour transition (palette::label_transition)
};
// The legend rows for a mode, in display order. Every mode lists each class's colour with its
// transition ("marking: green <-> white paint"), so the classes are explained where you label.
std::span<const LegendEntry> legend(OverlayMode mode);

}  // namespace fieldlines::studio
